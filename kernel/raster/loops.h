// Inner loops with NASM twins. Each loop takes one pointer to its argument block (cdecl); the C++
// function is the specification, the NASM one (asm/, i386 builds) must match it bit for bit.
// Argument layouts reach NASM through a generated offsets.inc (asm/offsets.cpp).
#pragma once

#include <stdint.h>

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

}  // namespace raster

// The NASM twins (asm/*.asm), in builds that assemble them.
extern "C" {
void exact_loop_asm(const void* args);
}

#if defined(MODEXLAB_ASM_LOOPS)
#define MODEXLAB_ASM(symbol) (&symbol)
#else
#define MODEXLAB_ASM(symbol) nullptr
#endif
