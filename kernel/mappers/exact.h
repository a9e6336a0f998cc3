// exact: the reference's definition at every pixel (an x87 divide per pixel in NASM): the span
// function, its loop's argument block, the twin and the NASM loop (asm/exact.asm).
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"

namespace raster {

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

Loop exact_loop;

void exact_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);
ErrorBound exact_bound(const BoundContext& c, const Vertex* vertices, int count);
Check check_exact;

}  // namespace raster

extern "C" {
raster::Loop exact_loop_asm;
}

