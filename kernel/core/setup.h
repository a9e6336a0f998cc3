// Polygon setup: snapped vertices, exact integer edge functions with the top-left rule, and the
// attribute planes (u/w, v/w, 1/w, u, v) over the polygon. docs/accuracy.md has the maths.
#pragma once

#include <stdint.h>

#include "kernel/core/fixed.h"

namespace raster {

// The subpixel grid: vertices snap to 1/256 pixel (Fixed24_8), as D3D's 8 fractional bits.
constexpr int SUBPIXEL_BITS = 8;
constexpr int64_t SUBPIXEL_ONE = 1 << SUBPIXEL_BITS;
constexpr int64_t SUBPIXEL_HALF = SUBPIXEL_ONE / 2;
// Vertex coordinates must lie within +-16384 pixels (a guard band far beyond the 320x240 screen):
// then every edge-function product fits comfortably in 64 bits (|E| < 2^47).
constexpr int32_t MAX_COORD_PIXELS = 16384;
// Attribute limits: 0 < w, 2^-16 <= w <= 2^24, |u|, |v| <= 2^24 texels.
constexpr double MIN_W = 1.0 / 65536.0;
constexpr double MAX_W = 16777216.0;
constexpr double MAX_UV = 16777216.0;
constexpr int MAX_POLYGON_VERTICES = 16;

// A vertex as the scene gives it, x and y already snapped to the subpixel grid.
struct Vertex {
    Fixed24_8 x, y;  // pixels, y down
    double w;        // clip-space w: 1/w is interpolated linearly in screen space
    double u, v;     // texels
};

// Half-open pixel rectangle [x0, x1) x [y0, y1).
struct ClipRect {
    int32_t x0, y0, x1, y1;
};

// Edge i runs from vertex i to vertex i+1 of the polygon in clockwise screen order (y down);
// E(P) = dx * (P.y - py) - dy * (P.x - px) is positive inside. A pixel centre P is inside
// when E(P) >= threshold for every edge: threshold 0 on top and left edges, 1 on the others.
// (32 bits hold them: coordinates within 2^22 subpixels, so differences within 2^23; products are
// taken in 64 bits.)
struct Edge {
    int32_t px, py;  // start vertex, subpixels
    int32_t dx, dy;  // direction, subpixels
    int32_t threshold;
};

// An affine texture coordinate in 16.16 per whole pixel: at pixel (x, y) it is
// at + (x - x0) * dx + (y - y0) * dy, in wrapping 32-bit arithmetic (exact modulo 65536 texels, so
// exact for any texture size dividing that). (x0, y0) is the pixel whose centre is nearest the
// reference vertex; `at` its value, rounded; the gradients rounded to nearest 2^-16 texel.
struct FixedPlane {
    int32_t x0, y0;
    int32_t at, dx, dy;
    int32_t value(int32_t x, int32_t y) const {
        return int32_t(uint32_t(at) + uint32_t(x - x0) * uint32_t(dx) + uint32_t(y - y0) * uint32_t(dy));
    }
};

// A linear function of the pixel centre: a(P) = (a0 + gy * Y) + gx * X, with X = P.x - ref_x and
// Y = P.y - ref_y in subpixels. This order of operations is part of the definition: the reference
// and the exact mapper evaluate exactly this, so they agree to the last bit.
struct Plane {
    double a0, gx, gy;
    double at(double x, double y) const { return (a0 + gy * y) + gx * x; }
};
// The plane through three (X, Y, value) points, X and Y relative to the first; d = Xb*Yc - Xc*Yb != 0.
Plane plane_through(double ra, double rb, double rc, double xb, double yb, double xc, double yc, double d);

enum class SetupStatus : uint8_t {
    Ok,
    Degenerate,       // zero area (collinear or repeated vertices): nothing to draw
    NotConvex,
    TooManyVertices,
    OutOfRange,       // a coordinate, w, u or v beyond the limits above, or not finite
    OutsideTexture,   // a mapper that cannot wrap got texture coordinates beyond the texture
    Unsupported,      // the mapper cannot take this texture, target or walker
    Unproven,         // auto's envelope (DrawContext::envelope): the triangle is not one it draws; nothing drawn
};

const char* setup_status_name(SetupStatus s);

// No default member initialisers: a setup is declared for every polygon drawn, and setup_polygon
// writes what it says it does (zeroing the rest first would cost every polygon).
struct PolygonSetup {
    int32_t edge_count;
    Edge edges[MAX_POLYGON_VERTICES];
    int64_t area2;                          // twice the area, subpixels squared (positive)
    int64_t ref_x, ref_y;                   // the plane's reference vertex, subpixels
    int64_t min_x, min_y, max_x, max_y;     // bounding box of the vertices, subpixels
    Plane q, pu, pv;                        // 1/w, u/w, v/w: perspective
    Plane u, v;                             // u and v themselves: affine
    FixedPlane u_fx, v_fx;                  // u and v in 16.16 per pixel (the fast affine mappers)
};
// Whether the polygon's box (its vertices' extremes) lies inside the clip: nothing of it is cut.
inline bool box_in_clip(const PolygonSetup& s, const ClipRect& clip) {
    return s.min_x >= int64_t(clip.x0) * SUBPIXEL_ONE && s.max_x <= int64_t(clip.x1) * SUBPIXEL_ONE && s.min_y >= int64_t(clip.y0) * SUBPIXEL_ONE &&
           s.max_y <= int64_t(clip.y1) * SUBPIXEL_ONE;
}

// Snaps a pixel coordinate to the subpixel grid: round to nearest, ties up.
inline Fixed24_8 snap(double pixels) { return Fixed24_8::from_double(pixels); }

// Which attribute planes setup_polygon computes; the others are left as they were (unspecified).
// Coverage (edges, bounding box, reference vertex) is always there.
enum SetupPlanes : uint8_t {
    PLANES_NONE = 0,         // coverage only: a classic's own driver checking its input
    PLANES_AFFINE = 1,       // u, v, u_fx, v_fx
    PLANES_PERSPECTIVE = 2,  // q, pu, pv
    PLANES_ALL = 3,
};

// Who answers for the vertices' range: Any, the setup checks each against the limits above;
// InRange, the caller made them within the limits (build_frame's uncut faces, Frame::polygon_whole).
enum class Input : uint8_t { Any, InRange };

// Whether every vertex is within the limits above (NaN and infinities are not).
bool vertices_in_range(const Vertex* vertices, int count);

// setup_polygon's work in C++ alone (what setup_polygon below does with every polygon the NASM
// routine does not take).
SetupStatus setup_polygon_cpp(const Vertex* vertices, int count, PolygonSetup* out, SetupPlanes planes = PLANES_ALL, Input input = Input::Any);
#if defined(MODEXLAB_ASM_LOOPS)
extern "C" int setup_triangle_affine_asm(const Vertex* in, PolygonSetup* out);
#endif

// Orients the polygon, drops repeated vertices, checks range (unless the input is InRange) and
// convexity, builds the edges and the planes. Any input is safe: on anything but Ok, `out` must
// not be drawn. Where the NASM loops are built in (the kernel, the 32-bit host programs), a
// triangle in range with affine planes only (the fast mappers' on a frame's uncut faces) goes
// through setup_triangle_affine_asm (asm/setup.asm), whose twin setup_polygon_cpp is: it writes the
// same fields with the same bits, or returns 0 and leaves the triangle to C++. (Inline: the fast
// drivers' calls, their planes and input known, go straight to the NASM.)
inline SetupStatus setup_polygon(const Vertex* vertices, int count, PolygonSetup* out, SetupPlanes planes = PLANES_ALL, Input input = Input::Any) {
#if defined(MODEXLAB_ASM_LOOPS)
    if (count == 3 && planes == PLANES_AFFINE && input == Input::InRange && setup_triangle_affine_asm(vertices, out)) return SetupStatus::Ok;
#endif
    return setup_polygon_cpp(vertices, count, out, planes, input);
}

// Whether the pixel centre (x + 0.5, y + 0.5) is inside: the definition the walkers implement.
bool covers(const PolygonSetup& s, int32_t x, int32_t y);

// The pixel centre relative to the reference vertex, subpixels (exact in a double).
inline double centre_x(const PolygonSetup& s, int32_t x) { return double(int64_t(x) * SUBPIXEL_ONE + SUBPIXEL_HALF - s.ref_x); }
inline double centre_y(const PolygonSetup& s, int32_t y) { return double(int64_t(y) * SUBPIXEL_ONE + SUBPIXEL_HALF - s.ref_y); }
// The same for a pixel of the polygon (a span's: inside its box, so within 16384 pixels of 0 by
// setup's range, as is the reference vertex) in 32 bits: each difference is within 2^23
// subpixels, so the value is the same, without i686's 64-bit product and difference a span.
inline double span_centre_x(const PolygonSetup& s, int32_t x) {
    return double(int32_t(uint32_t(x) * uint32_t(SUBPIXEL_ONE) + uint32_t(SUBPIXEL_HALF) - uint32_t(s.ref_x)));
}
inline double span_centre_y(const PolygonSetup& s, int32_t y) {
    return double(int32_t(uint32_t(y) * uint32_t(SUBPIXEL_ONE) + uint32_t(SUBPIXEL_HALF) - uint32_t(s.ref_y)));
}

// The exact texel at a pixel centre (X, Y relative to the reference vertex, subpixels): the
// perspective-correct u = (u/w)/(1/w) and v = (v/w)/(1/w), floored. This is the reference's
// definition; the `exact` mapper and its NASM twin compute exactly this. In the kernel the x87
// runs with 53-bit precision (boot/entry.asm), so these double operations give the same bits as
// the host's SSE2.
inline void perspective_texel(const Plane& q, const Plane& pu, const Plane& pv, double x, double y, int32_t* tu, int32_t* tv) {
    double qq = q.at(x, y);
    *tu = floor_i32(pu.at(x, y) / qq);
    *tv = floor_i32(pv.at(x, y) / qq);
}

inline void perspective_texel(const PolygonSetup& s, double x, double y, int32_t* tu, int32_t* tv) {
    perspective_texel(s.q, s.pu, s.pv, x, y, tu, tv);
}

// A pixel's footprint in texels (docs/accuracy.md, "Footprint error"): the larger of the exact
// mapping's texel steps per pixel across and down, each step measured as a texel error is (the
// larger of its u and v parts), at the pixel centre (X, Y as above). By the quotient rule,
// d(p/q)/dx = (p_x q - p q_x) / q^2 per subpixel, times 256 per pixel. Not clamped: the footprint
// error divides by max(1, footprint).
inline double texel_footprint(const Plane& pq, const Plane& pu, const Plane& pv, double x, double y) {
    double q = pq.at(x, y), u = pu.at(x, y), v = pv.at(x, y);
    double per_pixel = double(SUBPIXEL_ONE) / (q * q);
    double dudx = magnitude((pu.gx * q - u * pq.gx) * per_pixel), dvdx = magnitude((pv.gx * q - v * pq.gx) * per_pixel);
    double dudy = magnitude((pu.gy * q - u * pq.gy) * per_pixel), dvdy = magnitude((pv.gy * q - v * pq.gy) * per_pixel);
    double across = dudx > dvdx ? dudx : dvdx, down = dudy > dvdy ? dudy : dvdy;
    return across > down ? across : down;
}
inline double texel_footprint(const PolygonSetup& s, double x, double y) { return texel_footprint(s.q, s.pu, s.pv, x, y); }

}  // namespace raster
