// What a scene requires of the mapper that draws it (docs/auto.md): the largest footprint error,
// whether the pixels drawn must be exactly the reference's, and the machine the mapper that meets
// it is to be cheapest on. auto (kernel/mappers/auto/) draws to it; the other mappers ignore it.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/core/bound.h"

namespace raster {

// The unit auto prices its candidates in (docs/auto.md, "Per target"): instructions under QEMU's
// icount, or the timing model's cycles on a 486 or a Pentium (docs/cycles.md).
enum class CostTarget : uint8_t { Icount, I486, Pentium, Count };
// Its word in scene files, commands and replies ("icount", "486", "pentium"), and back (false: none).
const char* cost_target_name(CostTarget t);
bool cost_target_named(const char* word, size_t length, CostTarget* t);

constexpr double ANY_ERROR = -1;
struct ChoiceLists;  // (mappers/auto/choice.h)
struct Budget {
    bool given = false;          // from the scene's budget line (else the default)
    double max_error = 1;        // footprints (docs/accuracy.md); ANY_ERROR: any
    bool exact_coverage = true;  // no gaps, no overdraw
    CostTarget target = CostTarget::Icount;
    // auto's candidate lists for it, built as needed (the caller's memory, as a frame's scratch);
    // nullptr: auto builds the one it needs a polygon
    ChoiceLists* lists = nullptr;
};
// Scenes without a budget line: within one footprint, exact coverage.
constexpr Budget DEFAULT_BUDGET{};

inline bool budget_allows(const Budget& b, const ErrorBound& e) {
    return e.draws && (e.exact_coverage || !b.exact_coverage) && (b.max_error < 0 || e.footprint <= b.max_error);
}

}  // namespace raster
