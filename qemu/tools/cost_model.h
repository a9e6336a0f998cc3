// The cost model auto chooses by (kernel/mappers/auto/choice.h): per target (icount, and the timing
// model's 486 and Pentium) and mapper, the cost to set up a polygon, per span and per pixel,
// fitted to the bench's own figures (docs/bench.md, "The cost model") and written as
// kernel/mappers/auto/costs.cpp.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "kernel/mappers/auto/choice.h"

namespace harness {

struct FittedCost {
    double polygon = 0, span = 0, pixel = 0;
    int scenes = 0;  // the bench rows it was fitted to
};

// A target's fit: its rows by mapper, and the cycles an instruction of auto's choosing (1 for
// icount). No rows: the run did not measure the target.
struct FittedModel {
    std::map<std::string, FittedCost> rows;
    double proof_scale = 1;
};

// Fits every mapper of a trade.csv (read_csv's lines, header first) on `target` (raster's
// cost_target_name: icount's ticks_* columns, or cycles_TARGET_*; rows not measured there are
// left out): setup over polygons; the walking and inner loop per pixel as a line in spans per
// pixel (slope: per span, intercept: per pixel), least squares over the scenes, neither below
// zero; proof_scale: auto's choosing, its cycles over its instructions, over the rows with both.
FittedModel fit_costs(const std::vector<std::vector<std::string>>& csv, raster::CostTarget target);

// The C++ source of kernel/mappers/auto/costs.cpp: a table a target, one row per registry row, in its
// order (-1: not measured; auto chooses such a mapper last). A target the run did not measure
// keeps the model the tools were built with (raster::COST_MODELS), and says so. `source` names
// where the figures came from.
std::string cost_model_source(const FittedModel (&models)[int(raster::CostTarget::Count)], const std::string& source);

// The C++ source of kernel/mappers/errors.cpp: per scene and mapper of a trade.csv (auto at the
// scene's own budget, not the auto@B rows), the largest footprint error the bench measured, which
// the kernel's on-screen bench shows beside its own timings (the kernel's pictures are the host's).
std::string measured_errors_source(const std::vector<std::vector<std::string>>& csv, const std::string& source);

}  // namespace harness
