// Our fastest affine mappers, for 256 x 256 repeating textures (docs/mappers.md):
//   fast-affine:  rows into a linear surface;
//   fast-columns: columns into Mode X planes (the map mask set once per column).
// Both take our walker's exact coverage and start each span from the polygon's 16.16 planes at the
// span's first pixel centre (subpixel-correct, no per-span floating point); the loop is fatmap2's
// 8:16 core (16-bit fractions, the wholes in bl and bh of a pointer to the 64 KiB-aligned texture)
// unrolled eight times, entered part-way for the remainder, with no per-pixel loop counter.
#include "kernel/raster/fast.h"

namespace raster::fast {

void row_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t) {
    FatmapArgs a;
    a.dst = dst;
    a.count = s.count;
    a.texture = c.tex.aligned256;
    a.u = c.setup.u_fx.value(s.x, s.y);
    a.v = c.setup.v_fx.value(s.x, s.y);
    a.du = c.setup.u_fx.dx;
    a.dv = c.setup.v_fx.dx;
    c.loop(&a);
}

void column_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t) {
    FastColumnArgs a;
    a.dst = dst;  // the target is planar: pixels MODEX_ROW_BYTES apart
    a.count = s.count;
    a.texture = c.tex.aligned256;
    a.u = c.setup.u_fx.value(s.x, s.y);
    a.v = c.setup.v_fx.value(s.x, s.y);
    a.du = c.setup.u_fx.dy;
    a.dv = c.setup.v_fx.dy;
    c.loop(&a);
}

}  // namespace raster::fast

namespace raster {

void fast_column_loop(const void* raw) {
    const auto& a = *static_cast<const FastColumnArgs*>(raw);
    uint32_t u = uint32_t(a.u), v = uint32_t(a.v);
    uint8_t* dst = a.dst;
    for (int32_t n = 0; n < a.count; ++n) {
        *dst = a.texture[((v >> 8) & 0xFF00) | ((u >> 16) & 0xFF)];
        dst += MODEX_ROW_BYTES;
        u += uint32_t(a.du);
        v += uint32_t(a.dv);
    }
}

}  // namespace raster
