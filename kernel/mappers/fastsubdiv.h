// fast-subdiv-N: our subdividing perspective mapper on the fast 8:16 core (docs/mappers.md): the
// span function, its loop's argument block, the twin and the NASM loop (asm/fastsubdiv.asm).
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"

namespace raster {

// One span, segment by segment: the exact point (u, v) = (pu/q, pv/q) at pixel 0, at every
// N = 2^shift pixels after it and at the last pixel, each plane evaluated along the span (a row:
// (a0 + gy y) + gx x, as the reference does, c below being a0 + gy y; a column: (a0 + gx x) + gy y),
// each coordinate scaled to 16.16 and rounded to
// nearest in 64 bits, of which the low 32 are kept (a whole number of 65536-texel periods off: the
// tiled block repeats every 256). Between two points the 8:16 core steps by their 32-bit difference
// over the pixels between them: by a shift over N, by a division over fewer (the last segment).
// Each pixel reads the tiled block at (v whole & 255, u whole & 255).
struct FastSubdivArgs {
    uint8_t* dst;            // pixel 0
    int32_t stride;          // bytes from a pixel to the next: 1 (a row, drawn in pairs), or a column's
    int32_t count;           // pixels, 0 or more
    const uint8_t* texture;  // tiled over 256 x 256, aligned to 64 KiB (Texture::aligned256)
    int32_t shift;           // segments of 1 << shift pixels, shift 1 to 9
    double x;                // pixel 0's centre along the span (x, or y: a column), from the reference vertex, subpixels
    double c[3], g[3];       // q, pu, pv on the span's line: a0 + gy y and gx (a row), a0 + gx x and gy (a column)
};

void fast_subdiv_loop(const void* args);

// Segments longer than any row or column (320 pixels at most): one a span, exact at its first and
// last pixels (fast-constant-depth: constant-depth on the fast core).
constexpr int FAST_SPAN_LONG = 512;

template <int N>
void fast_subdiv_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);
template <int N>
ErrorBound fast_subdiv_bound(const BoundContext& c, const Vertex* vertices, int count);
LoopCheck check_fast_subdiv(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buffers);

}  // namespace raster

extern "C" {
void fast_subdiv_loop_asm(const void* args);
}
