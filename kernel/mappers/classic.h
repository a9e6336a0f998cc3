// What the classic mappers share: the fixed-point arithmetic of their time, and the conversion of a
// scene polygon to their inputs (whole-pixel vertices, clockwise on screen, texture coordinates
// placed inside the texture, since their loops cannot wrap).
#pragma once

#include <stdint.h>

#include "kernel/core/setup.h"
#include "kernel/core/texture.h"

namespace raster::classic {

// X-Sharp's FIXED.ASM: FixedDiv truncates toward zero ((a << 16) / b in 64 bits), FixedMul rounds
// (adds 0x8000 before taking the middle 32 bits). FixedDiv saturates where the original would have
// raised a divide error (a quotient beyond 16.16); b must not be 0.
int32_t fixed_div(int32_t a, int32_t b);
int32_t fixed_mul(int32_t a, int32_t b);
// 16.16 to the nearest integer (ties up), as X-Sharp's C rounded texel coordinates.
inline int32_t round_fixed(int32_t v) { return int32_t(uint32_t(v) + 0x8000) >> 16; }

// X-Sharp's asm loops (57.2, 58.4) step 16-bit fractions that count up: a 16.16 step split into
// its whole part toward zero, the fraction (negated for negative steps), and the extra advance a
// fraction carry adds (+1 or -1).
struct SplitStep {
    int32_t whole;
    uint32_t fraction;
    int32_t carry_advance;
};
inline SplitStep split(int32_t step) {
    SplitStep s;
    s.whole = step >> 16;
    uint32_t frac = uint32_t(step) & 0xFFFF;
    if (step < 0) {
        s.carry_advance = -1;
        if (frac != 0) s.whole += 1;  // toward zero
        s.fraction = (0x10000 - frac) & 0xFFFF;
    } else {
        s.carry_advance = 1;
        s.fraction = frac;
    }
    return s;
}
// A coordinate's fraction in the counting-up form: NOTed when its step is negative.
inline uint32_t counting_fraction(int32_t coordinate, int32_t step) {
    uint32_t f = uint32_t(coordinate) & 0xFFFF;
    return step < 0 ? (~f & 0xFFFF) : f;
}

// A vertex as the classics take it: screen coordinates in whole pixels (their vertices had no
// fractional bits), texture coordinates in 16.16.
struct Vertex16 {
    int32_t x, y;
    int32_t u_16_16, v_16_16;  // in the mapper's texel space (see texel_offset below)
    double w;
};

constexpr int MAX_VERTICES = MAX_POLYGON_VERTICES;
// Their 16.16 arithmetic holds line lengths below 32768 pixels: vertices must lie within +-8192.
constexpr int32_t MAX_COORD = 8192;

// The whole-period shifts (repeat) that bring a polygon's smallest texture coordinates into
// [0, size); TooManyVertices beyond MAX_VERTICES, Degenerate below 3, OutsideTexture when the
// shifted coordinates still leave [0, width] x [0, height], OutOfRange for coordinates beyond
// MAX_COORD or non-finite texture coordinates. Every classic's driver starts with it.
SetupStatus texture_shift(const Vertex* in, int n, const Texture& tex, double* shift_u, double* shift_v);
// The same with the shifted coordinates required to lie in [0, limit_u] x [0, limit_v] instead
// (loops that wrap at the texture's size and hold more in their registers).
SetupStatus texture_shift(const Vertex* in, int n, const Texture& tex, double limit_u, double limit_v, double* shift_u, double* shift_v);

// Converts a polygon: x and y rounded to the nearest pixel corner (ties up); clockwise screen order
// (the classics relied on back-face culling for it; here the winding is fixed up instead); texture
// coordinates shifted by whole periods so the smallest lies in [0, size) (repeat) and then required
// to lie within [0, width] x [0, height] at every vertex, with texel_offset added (X-Sharp and
// Hecker put texel centres at integers: -0.5; Quake and fatmap at half-integers: 0).
// Returns Ok, Degenerate (zero area after rounding: nothing to draw), TooManyVertices, OutOfRange
// (beyond MAX_COORD, or u, v not finite) or OutsideTexture; `count` receives the vertex count.
// shift, where given, receives the whole periods added to u and v.
SetupStatus convert(const Vertex* in, int n, const Texture& tex, double texel_offset, Vertex16* out, int* count, double* shift = nullptr);

// Whether both vertex chains from the first vertex of least y (x for columns) to the first of
// greatest y (x) run monotonically: the classics' "every horizontal (vertical) line crosses exactly
// two active edges". A polygon that fails would send their edge walkers past its ends, reading
// far outside the texture; the drivers refuse it (NotConvex). Convex polygons pass, also after
// their vertices are rounded to whole pixels.
bool monotone(const Vertex16* v, int n, bool columns);

}  // namespace raster::classic
