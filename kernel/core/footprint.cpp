// The 16.16 range (footprint.h).
#include "kernel/core/footprint.h"

namespace raster {

bool fits_16_16(double start, double step, double steps, int32_t size, Wrap wrap) {
    constexpr double LIMIT = 32767;
    double travel = magnitude(step) * steps;
    if (!(magnitude(step) < LIMIT) || !(travel < 1e9)) return false;
    if (wrap == Wrap::Repeat) return (65536 % size == 0) || double(size) + travel < LIMIT;
    return magnitude(start) + travel < LIMIT;
}

}  // namespace raster
