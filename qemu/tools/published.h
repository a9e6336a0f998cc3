// The classics' published figures beside ours in the report (trade.md): each published loop, the
// machine its figure is for, the timing model's cycles for its listing and for our loop, and the
// instructions counted and measured.
#pragma once

#include <ostream>
#include <vector>

#include "qemu/tools/trade.h"

namespace harness {

// The section of trade.md, from the rows (our loops' measured instructions on the scene each drew
// most of) and the listings and the kernel's objects (the model's figures; "-" where absent).
void write_published(std::ostream& out, const std::vector<TradeRow>& rows);

// The section after it (write_published writes both): our loops' figures under the timing model
// against the goals the lab set them (docs/cycles.md, "Our loops against the goals").
void write_goals(std::ostream& out, const std::vector<TradeRow>& rows);

}  // namespace harness
