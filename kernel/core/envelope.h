// The object's envelope: what holds for every uncut triangle of an object in a frame, the guards
// and limits a triangle must pass to be drawn under it, and the bound it proves.
#pragma once

#include <stdint.h>

#include "kernel/core/footprint.h"
#include "kernel/core/setup.h"

namespace raster {

// The object's envelope (docs/auto.md, "The object's envelope"): what holds for every uncut
// triangle of an object in a frame, from the object (its mesh measured once, its nearest depth in
// the frame), so that the planes' bound (spread_planes_bound, spread.h) needs no spread per
// triangle. With the guards below, checked on the triangle's setup, every field of its spread is
// bounded a priori.
struct TriangleEnvelope {
    double texel_abs[2];    // A_t: the largest |u|, |v| (texels) at a corner, from above
    double texel_range[2];  // T_t: the largest range of u, v over a triangle's corners, from above
    double depth_ratio;     // rho: the largest w_max / w_min - 1 over a triangle's corners, from above
};
// The guards, on a triangle's setup (affine planes): its box of W x H subpixels and doubled area D
// (subpixels squared) have W + H <= ENVELOPE_REACH pixels (how far its 16.16 planes step from
// their anchor) and 4 W H <= ENVELOPE_CONDITION D (how badly its planes can be conditioned), and
// its 16.16 steps are within 32766 texels a pixel (so that planes_fit_16_16 holds).
constexpr double ENVELOPE_CONDITION = 65536;
constexpr int32_t ENVELOPE_REACH = 1024;
// (Inline, in integers, once a triangle of the mesh: the sides' sum within the reach first, so
// that each side is below 2^18 subpixels and W H, one 32-bit multiply, below 2^36; a D of 2^22 or
// more passes the second at once, and a smaller one times 16384 cannot overflow.)
inline bool envelope_guards(const PolygonSetup& s) {
    if (s.edge_count != 3) return false;
    // (the box within setup's range: its sides in 32 bits, from the low halves)
    const uint32_t w = uint32_t(s.max_x) - uint32_t(s.min_x), h = uint32_t(s.max_y) - uint32_t(s.min_y);
    if (w + h > uint32_t(ENVELOPE_REACH * SUBPIXEL_ONE) || w + h < w) return false;
    static_assert(ENVELOPE_CONDITION == 65536, "4 W H <= 65536 D is W H <= 16384 D");
    if ((s.area2 >> 22) == 0 && uint64_t(w) * h > uint64_t(uint32_t(s.area2)) << 14) return false;
    // the 16.16 steps within +-32766 texels (they saturate at +-2^31): the steps within 32767
    constexpr uint32_t STEP = 32766u << 16;
    auto fits = [](int32_t raw) { return uint32_t(raw) + STEP <= 2 * STEP; };
    return fits(s.u_fx.dx) && fits(s.u_fx.dy) && fits(s.v_fx.dx) && fits(s.v_fx.dy);
}
// What auto's envelope takes besides the guards (AutoPlan::enveloped_area2, enveloped_extent): the
// largest doubled area (subpixels squared) and the largest extents of the box (subpixels; INT32_MAX:
// unlimited) of a triangle it draws.
struct EnvelopeLimits {
    int64_t area2;
    int32_t extent_x, extent_y;
};
// The guards and the limits: the triangles auto's envelope draws (draw_enveloped; the drivers
// given DrawContext::envelope check it, fast_triangle_enveloped_asm in NASM).
inline bool within_envelope(const PolygonSetup& s, const EnvelopeLimits& e) {
    return envelope_guards(s) && s.area2 <= e.area2 && int32_t(s.max_y - s.min_y) <= e.extent_y && int32_t(s.max_x - s.min_x) <= e.extent_x;
}
// Upper bounds on spread_planes_deviation's d[t] for a triangle within the envelope that passes
// the guards, the planes' 16.16 rounding at the largest reach the guards allow included: the
// deviations of fast-affine's and fast-columns' coordinates from the reference's (NO_BOUND where
// rho is not finite and positive or at least 1).
void envelope_deviation(const TriangleEnvelope& e, double d[2]);
// What the envelope proves for an object in a frame: its deviations (envelope_deviation) and the
// bound auto takes, in footprints at a footprint of 1 (NO_BOUND: none).
struct EnvelopeBound {
    TriangleEnvelope envelope;
    double deviation[2];
    double footprint = NO_BOUND;
};
EnvelopeBound envelope_bound(const TriangleEnvelope& e);

}  // namespace raster
