// The timing model's figures in the report (trade.md): cycles a pixel a mapper on each target and
// bus, and straight into Mode X against RAM and a blit.
#pragma once

#include <string>
#include <vector>

#include "qemu/tools/trade.h"

namespace harness {

// The timing model's rows (cycles_486, cycles_pentium), a line a mapper: cycles a pixel over all
// the scenes it drew, of its inner loops, its drawing and its frames on each bus, for each target.
std::string cycles_table(const std::vector<TradeRow>& rows);

// A line a scene, target and bus: the fastest frame (cycles a pixel) of the mappers that draw
// straight into the VGA's page, against the fastest that draw into RAM and blit; "" unmeasured.
std::string modex_table(const std::vector<TradeRow>& rows);

// A line a scene and target: its Pareto front under the timing model, drawing cycles a pixel
// against mean footprint error (the rows that draw everything and were run on the target), fastest
// first; "" unmeasured.
std::string pareto_by_target(const std::vector<TradeRow>& rows);

}  // namespace harness

namespace harness {

// A line a scene's auto row (at its budget) run on a target: its drawing cycles a pixel there,
// priced by icount's cost model and by the target's (Cycles::priced_draw), and what it drew with
// for each target, by share of pixels; "" where no row was priced.
std::string auto_by_target(const std::vector<TradeRow>& rows);
// A line a scene's auto row (at its budget) and target it ran on: its drawing cycles a pixel there,
// priced for the target and by icount, against the fastest single mapper run there whose measured
// error meets the budget (the speed-ups: its cycles over auto's), and choosing's share of auto's
// drawing cycles priced by icount; "" where no auto row ran on a target.
std::string auto_against_singles_by_target(const std::vector<TradeRow>& rows);

}  // namespace harness
