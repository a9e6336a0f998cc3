// X-Sharp's texture mappers (Black Book ch. 56-58): the polygon drivers, the argument blocks of
// their loops, the twins and the NASM loops (asm/xsharp.asm).
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"

namespace raster {

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
Loop xsharp_row_loop;

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
Loop xsharp_column_loop;

Check check_xsharp_column;
struct Random;
// Random XSharpRowArgs for a row of up to 320 pixels starting at plane offset `offset` of a page
// whose rows are 80 bytes (the kernel's VGA check), texel reads inside `texels` (CHECK_TEXEL_BYTES).
void random_xsharp_row(Random& r, const uint8_t* texels, XSharpRowArgs* a, int32_t* x, int32_t* y);

}  // namespace raster

extern "C" {
raster::Loop xsharp_row_loop_asm;  // VGA only: writes the Map Mask through port 0x3C5
raster::Loop xsharp_column_loop_asm;
}

namespace raster::xsharp {

SetupStatus draw_dda(const DrawContext& c, const Vertex* vertices, int count);      // listing 57.1
SetupStatus draw_row_out(const DrawContext& c, const Vertex* vertices, int count);  // listing 57.2 / 58.1
SetupStatus draw_column(const DrawContext& c, const Vertex* vertices, int count);   // listing 58.4, X-Sharp 22
// Their error bounds: the walk run again and each line's texel indices against the exact mapping.
ErrorBound bound_rows(const BoundContext& c, const Vertex* vertices, int count);    // xsharp-dda, xsharp-row-out
ErrorBound bound_column(const BoundContext& c, const Vertex* vertices, int count);  // xsharp-column

}  // namespace raster::xsharp
