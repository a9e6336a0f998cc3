// affine: the textbook mapper, our baseline (docs/mappers.md).
#include "kernel/mappers/affine.h"

#include "kernel/core/bound.h"
#include "kernel/core/footprint.h"
#include "kernel/core/spanline.h"
#include "kernel/core/spread.h"

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
    double x = span_centre_x(setup, s.x), y = span_centre_y(setup, s.y);
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

// The bound (docs/bounds.md): on each span the mapper steps the affine planes
// from the first pixel centre, so its u and v follow the planes' lines to within 16.16 rounding
// (half a unit at the start and in the step: (1 + k) / 2^17 after k pixels); the lines' deviation
// from the exact mapping is measured piece by piece (BOUND_PIECE pixels, over each piece's own
// smallest footprint).
ErrorBound affine_bound(const BoundContext& c, const Vertex* vertices, int count) {
    const int32_t size[2] = {c.tex.width, c.tex.height};
    auto whole = [&](PolygonSpread& p, const PolygonSetup& s) {
        const double last = p.lines[c.axis == Axis::Rows ? 0 : 1] - 1;
        const Plane* plane[2] = {&s.u, &s.v};
        for (int t = 0; t < 2; ++t) {
            const double step = (c.axis == Axis::Rows ? plane[t]->gx : plane[t]->gy) * double(SUBPIXEL_ONE);
            if (!fits_16_16(p.affine_abs[t], step, last, size[t], c.tex.wrap)) return NO_BOUND;
        }
        return spread_planes_bound(p, s, (1 + last) * HALF_ULP_16_16, c.budget);
    };
    return bound_by_spans(c, vertices, count, PLANES_ALL, whole, [&](const Span& span, const PolygonSetup& s, bool* fits) {
        SpanLine l = span_line(s, c.axis, span);
        const double last = double(span.count - 1);
        double a[2], step[2];
        affine_lines(s, c.axis, span, a, step);
        for (int t = 0; t < 2; ++t) *fits = *fits && fits_16_16(a[t], step[t], last, size[t], c.tex.wrap);
        auto piece = [&](double k0, double k1) { return lines_bound(l, a, step, k0, k1, (1 + k1) * HALF_ULP_16_16); };
        return span_bound(c, 0, last, BOUND_PIECE, piece, piece);
    });
}

}  // namespace raster
