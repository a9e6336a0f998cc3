// affine: the textbook mapper, our baseline (docs/mappers.md).
#include "kernel/mappers/affine.h"

namespace raster {

namespace {

// A texture coordinate in 16.16 at a span's start. With repeat, it is first reduced modulo the
// texture size (same texels, and far from the 16.16 limit of +-32768 texels); with clamp it
// saturates, which clamps to the same edge texel.
Fixed16_16 start_coordinate(double t, int32_t size, Wrap wrap) {
    if (wrap == Wrap::Repeat) {
        double period = double(size);
        t -= period * double(floor_i64(t / period));  // exact: the result is a multiple of t's ulp below 2*size
    }
    return Fixed16_16::from_double(t);
}

}  // namespace

// affine: u and v linear in screen space, stepped in 16.16 from their value at the span's first
// pixel centre; texel = floor.
void affine_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride) {
    const PolygonSetup& setup = c.setup;
    double x = centre_x(setup, s.x), y = centre_y(setup, s.y);
    Fixed16_16 u = start_coordinate(setup.u.at(x, y), c.tex.width, c.tex.wrap);
    Fixed16_16 v = start_coordinate(setup.v.at(x, y), c.tex.height, c.tex.wrap);
    double per_pixel = double(SUBPIXEL_ONE);
    Fixed16_16 du = Fixed16_16::from_double((c.axis == Axis::Rows ? setup.u.gx : setup.u.gy) * per_pixel);
    Fixed16_16 dv = Fixed16_16::from_double((c.axis == Axis::Rows ? setup.v.gx : setup.v.gy) * per_pixel);
    for (int32_t n = 0; n < s.count; ++n) {
        *dst = texel(c.tex, u.floor_int(), v.floor_int());
        dst += stride;
        u = u + du;
        v = v + dv;
    }
}

}  // namespace raster
