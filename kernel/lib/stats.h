// Summaries of per-frame figures (the play and bench replies): sum, minimum, maximum and median,
// the median by selection in expected linear time. Portable (kernel and host).
#pragma once

#include <stdint.h>

namespace lib {

// Puts the median of v[0..n) (n >= 1) at v[n / 2], the upper one of an even count, with nothing
// greater before it and nothing smaller after it (as std::nth_element), and returns it. The
// order of the rest changes. Quickselect with a median-of-three pivot: no room needed, and the
// sorted and reversed runs a frame series tends to be cost linear time, not quadratic.
uint32_t median_in_place(uint32_t* v, uint32_t n);

struct Summary {
    uint64_t sum = 0;
    uint32_t min = 0, max = 0, median = 0;
};

// The summary of v[0..n) (n >= 1); reorders v, as median_in_place.
Summary summarise_in_place(uint32_t* v, uint32_t n);

}  // namespace lib
