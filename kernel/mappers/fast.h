// Our fastest affine mappers (repeating textures tiled over 256 x 256): the polygon drivers, the loops'
// argument blocks, the twins and the NASM loops (asm/fast.asm).
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"
#include "kernel/mappers/fatmap.h"

namespace raster {

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
    const uint8_t* texture;  // tiled over 256 x 256, aligned to 64 KiB
    uint32_t u_16_16, v_16_16;        // at pixel 0 of the first row
    uint32_t u_row_16_16, v_row_16_16;  // their change from row to row
    int32_t du_16_16, dv_16_16;       // per pixel
    uint32_t* tally;         // tally[0] += the spans drawn, tally[1] += their pixels
};
void fast_run_loop(const void* args);

// fast-columns: the same arithmetic down a Mode X column, 80 bytes between pixels; it takes
// fatmap's block (the 8:16 loops' inputs, a 64 KiB-aligned texture).
constexpr int32_t MODEX_ROW_BYTES = 80;
using FastColumnArgs = FatmapArgs;
void fast_column_loop(const void* args);

LoopCheck check_fast_run(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buffers);
LoopCheck check_fast_column(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buffers);

}  // namespace raster

extern "C" {
void fast_run_loop_asm(const void* args);
void fast_column_loop_asm(const void* args);
}

namespace raster::fast {

SetupStatus draw_rows(const DrawContext& c, const Vertex* vertices, int count);     // fast-affine
SetupStatus draw_columns(const DrawContext& c, const Vertex* vertices, int count);  // fast-columns
ErrorBound bound(const BoundContext& c, const Vertex* vertices, int count);         // both

}  // namespace raster::fast
