// Footprint errors, the unit every error bound is given in (docs/bounds.md; NO_BOUND where none
// can be given), and what a 16.16 coordinate holds: what the span lines (spanline.h), the spread
// (spread.h), the envelope (envelope.h) and the mappers' bounds (bound.h) are all built on.
#pragma once

#include <stdint.h>

#include "kernel/core/setup.h"
#include "kernel/core/texture.h"

namespace raster {

// No bound can be given (a classic's arithmetic, an overflow): larger than any budget.
constexpr double NO_BOUND = 1e30;

// A coordinate off by at most `du` and `dv` texels reads a texel at most ceil(du), ceil(dv) away;
// over max(1, footprint) that is the footprint error.
inline double footprint_error(double du, double dv, double footprint) {
    auto texels = [](double d) {  // ceil(d) for d >= 0, without libm
        if (d <= 0) return 0.0;
        if (d >= 1e15) return d;  // beyond any budget; and int64_t would not hold it
        double whole = double(int64_t(d));
        return whole < d ? whole + 1 : whole;
    };
    double e = larger(texels(du), texels(dv));
    return e / larger(1.0, footprint);
}

// 16.16 rounding to nearest: half a unit in the last place.
constexpr double HALF_ULP_16_16 = 1.0 / 131072.0;
// Whether a 16.16 coordinate that starts at `start` (with repeat: reduced into [0, size) first, as
// our mappers do) and moves by `step` a pixel for `steps` pixels stays what it means: the step in
// range, and the values in range or wrapping harmlessly (a repeating size that divides 65536).
bool fits_16_16(double start, double step, double steps, int32_t size, Wrap wrap);

// Whether the polygon's affine planes' gradients hold in 16.16 (a step of 32768 texels a pixel or
// more saturates), for a repeating texture tiled over 256 x 256: the fast mappers' planes mean what they say.
// (fits_16_16 with no travel, 256 dividing 65536: the step's magnitude alone.)
inline bool planes_fit_16_16(const PolygonSetup& s) {
    constexpr double LIMIT = 32767.0 / double(SUBPIXEL_ONE);
    return magnitude(s.u.gx) < LIMIT && magnitude(s.u.gy) < LIMIT && magnitude(s.v.gx) < LIMIT && magnitude(s.v.gy) < LIMIT;
}

}  // namespace raster
