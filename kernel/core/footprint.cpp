// Footprint errors and the 16.16 range (footprint.h).
#include "kernel/core/footprint.h"

namespace raster {

double footprint_error(double du, double dv, double footprint) {
    auto texels = [](double d) {  // ceil(d) for d >= 0, without libm
        if (d <= 0) return 0.0;
        if (d >= 1e15) return d;  // beyond any budget; and int64_t would not hold it
        double whole = double(int64_t(d));
        return whole < d ? whole + 1 : whole;
    };
    double e = larger(texels(du), texels(dv));
    return e / larger(1.0, footprint);
}

bool fits_16_16(double start, double step, double steps, int32_t size, Wrap wrap) {
    constexpr double LIMIT = 32767;
    double travel = magnitude(step) * steps;
    if (!(magnitude(step) < LIMIT) || !(travel < 1e9)) return false;
    if (wrap == Wrap::Repeat) return (65536 % size == 0) || double(size) + travel < LIMIT;
    return magnitude(start) + travel < LIMIT;
}

}  // namespace raster
