// Inner loops with NASM twins. Each loop takes one pointer to its argument block (cdecl); the C++
// function is the specification, the NASM one (asm/, i386 builds) must match it bit for bit.
// Argument layouts reach NASM through a generated offsets.inc (asm/offsets.cpp).
#pragma once

#include <stdint.h>

#include "kernel/core/walk.h"

namespace raster {

using LoopFn = void (*)(const void* args);

// exact: per pixel, u = pu/q and v = pv/q from the three planes at (x, y), floored (saturating,
// NaN -> 0), wrapped or clamped, the texel stored; then x += step_x, y += step_y.
struct ExactArgs {
    uint8_t* dst;
    int32_t stride;
    int32_t count;
    const uint8_t* texels;
    int32_t width, height;
    int32_t clamp;          // 0: repeat, 1: clamp
    int32_t reserved;
    double x, y;            // pixel centre minus the reference vertex, subpixels
    double step_x, step_y;  // per pixel: 256 and 0 (rows) or 0 and 256 (columns)
    double q[3], pu[3], pv[3];  // each plane: a0, gx, gy (Plane's layout)
};

void exact_loop(const void* args);

// xsharp-row-out (Black Book listing 57.2, inner loop = listing 58.1): a row of Mode X pixels,
// OUT to the Map Mask before every pixel. The texel pointer carries the integer parts of both
// coordinates; the fractions count up in 16 bits (negative steps: negated fraction, NOTed
// coordinate fraction, a -1 / -pitch extra advance on the carry).
struct XSharpRowArgs {
    uint8_t* dst;            // the first pixel's byte within its plane
    int32_t plane_bytes;     // the twin's RAM planes lie this far apart (the NASM loop OUTs instead)
    int32_t count;           // pixels, >= 1
    uint32_t mask;           // 0x11 << (x & 3): the plane bit in both nibbles, rotated per pixel
    const uint8_t* texel;    // the first pixel's texel (rounding already folded in)
    uint32_t x_frac, y_frac; // 16-bit fractions
    uint32_t x_step, y_step; // 16-bit fraction steps
    int32_t x_base, x_carry; // whole X step (toward zero), and +-1 more on a fraction carry
    int32_t y_base, y_carry; // whole Y step times the pitch, and +-pitch more on a carry
    // the twin's OUT: called with the plane before each pixel when set (a VGA target)
    void (*select_plane)(void* ctx, int plane);
    void* ctx;
};
void xsharp_row_loop(const void* args);

// xsharp-column (listing 58.4, as X-Sharp 22 shipped it: unrolled twice, with a second loop for
// X running backwards): a column of Mode X pixels 80 bytes apart, the map mask set by the caller.
// fractions: X fraction in bits 31..16, Y fraction >> 1 in bits 14..0, bit 15 the Y carry.
constexpr int32_t XSHARP_SCANWIDTH = 80;
struct XSharpColumnArgs {
    uint8_t* dst;            // the first pixel; the next is 80 bytes on
    int32_t count;           // pixels, >= 1
    const uint8_t* texel;
    uint32_t fractions;      // packed as above
    uint32_t steps;          // the steps, packed the same way (bit 15 clear)
    int32_t base;            // whole X step + whole Y step times the pitch (both toward zero)
    int32_t row;             // +-pitch, added on a Y carry
    int32_t backwards;       // X runs backwards: an X carry moves one texel left (X-Sharp 22's SBB loop)
};
void xsharp_column_loop(const void* args);

// hecker-steptable (Hecker, Game Developer part V, listing 2): one pointer carries both texel
// coordinates; per pixel the v fraction's carry (sbb: 0 or -1) picks one of two table entries and
// the u fraction's carry goes in through adc. Any texture width; nothing wraps.
struct HeckerArgs {
    uint8_t* dst;            // count pixels left to right
    int32_t count;
    const uint8_t* texel;    // the first pixel's texel
    uint32_t u_frac, v_frac; // fractions in bits 31..16
    uint32_t du_frac, dv_frac;
    int32_t step_carry;      // whole du + whole dv times the pitch, plus the pitch: v carried
    int32_t step_no_carry;   // whole du + whole dv times the pitch
};
void hecker_loop(const void* args);

// fatmap-256 and fatmap-256-16 (fatmap.txt's 5-tick loop; fatmap2's 8:16 loop): a 256 x 256
// texture at a 64 KiB boundary, the texel pointer's low 16 bits v:u, wrapping in both directions.
// Both take u, v and the deltas in 16:16 and keep what their registers hold of them.
struct FatmapArgs {
    uint8_t* dst;            // count pixels left to right
    int32_t count;
    const uint8_t* texture;  // aligned to 64 KiB
    int32_t u, v;            // 16:16
    int32_t du, dv;          // 16:16 per pixel
};
void fatmap_loop(const void* args);    // 8-bit fractions
void fatmap16_loop(const void* args);  // 16-bit fractions

// fatmap-lut: texel n is source[table[n]]: the triangle's table of offsets from its first pixel.
struct FatmapLutArgs {
    uint8_t* dst;
    int32_t count;
    const uint8_t* source;   // the scanline's first texel
    const int32_t* table;    // the offsets, one per pixel
};
void fatmap_lut_loop(const void* args);

// fast-affine: a run of rows of a polygon (EdgeWalker::run), the edge walking and the spans in one
// loop. On each row: first pixel max(lower.q, clip_lo), last pixel min(upper.q, clip_hi), both
// bounds stepped; a non-empty span drawn with fatmap2's 8:16 arithmetic (16.16 u and v, wrapping
// at 256 texels) from u + x * du, v + x * dv at its first pixel x; then u, v and row advance.
struct FastRunArgs {
    uint8_t* row;            // the first row's pixel 0 (only pixels clip_lo..clip_hi are written)
    int32_t pitch;           // bytes from row to row
    int32_t lines;           // >= 1
    int32_t clip_lo, clip_hi;
    EdgeBound* lower;        // stepped in place, once a row
    EdgeBound* upper;
    const uint8_t* texture;  // 256 x 256, aligned to 64 KiB
    uint32_t u, v;           // 16.16 at pixel 0 of the first row
    uint32_t u_row, v_row;   // their change from row to row
    int32_t du, dv;          // 16.16 per pixel
    uint32_t* tally;         // tally[0] += the spans drawn, tally[1] += their pixels
};
void fast_run_loop(const void* args);

// fast-columns: the same arithmetic down a Mode X column, 80 bytes between pixels.
constexpr int32_t MODEX_ROW_BYTES = 80;
struct FastColumnArgs {
    uint8_t* dst;
    int32_t count;
    const uint8_t* texture;  // aligned to 64 KiB
    int32_t u, v;            // 16.16
    int32_t du, dv;          // 16.16 per pixel down the column
};
void fast_column_loop(const void* args);

// quake-subdiv16 / quake-subdiv8: one span, all its segments (d_scan.c's algorithm; the NASM loop
// starts the x87 divide for the next segment's end before drawing the current segment).
struct QuakeArgs {
    uint8_t* dst;             // the span's first pixel; count pixels to the right
    int32_t count;            // >= 1
    int32_t x, y;             // the span's first pixel on screen (Quake's du, dv)
    const uint8_t* texels;    // the texture (Quake's surface cache), pitch bytes a row
    int32_t pitch;
    int32_t sadjust, tadjust;     // 16.16, added after s/z * z
    int32_t bbextents, bbextentt; // size * 65536 - 1
    int32_t shift;            // log2 of the segment length: 4 or 3
    int32_t reserved;
    double s_origin, s_stepu, s_stepv;  // s/z at pixel (0, 0) and per pixel across and down
    double t_origin, t_stepu, t_stepv;
    double z_origin, z_stepu, z_stepv;  // 1/z
    double s_stepu_n, t_stepu_n, z_stepu_n;  // the steps times the segment length
};
void quake_span_loop(const void* args);

}  // namespace raster

// The NASM twins (asm/*.asm), in builds that assemble them.
extern "C" {
void exact_loop_asm(const void* args);
void xsharp_row_asm(const void* args);     // VGA only: writes the Map Mask through port 0x3C5
void xsharp_column_asm(const void* args);
void hecker_loop_asm(const void* args);
void fatmap_loop_asm(const void* args);
void fatmap16_loop_asm(const void* args);
void fatmap_lut_loop_asm(const void* args);
void quake_span_asm(const void* args);
void fast_run_asm(const void* args);
void fast_column_asm(const void* args);
}

#if defined(MODEXLAB_ASM_LOOPS)
#define MODEXLAB_ASM(symbol) (&symbol)
#else
#define MODEXLAB_ASM(symbol) nullptr
#endif
