// Our fastest affine mappers (repeating textures tiled over 256 x 256): the loops' argument blocks,
// their twins and NASM loops (fast.cpp, asm/fast.asm), a frame's triangle in one call
// (fast_triangle.cpp, asm/fast_triangle.asm) and the polygon drivers (fast_draw.cpp); fast-table,
// the same runs of rows with the texel offsets along a span precomputed once a polygon.
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"
#include "kernel/mappers/fatmap.h"

namespace raster {

// Where fast-affine's run loop reads its texels. TILED_BLOCK: the tiled block's (v whole & 255) *
// 256 + (u whole & 255), which the NASM loops take by bl and bh. DOUBLED_COPY (textures above 256 a
// side): block_pitch bytes a row, u and v the polygon's less its window's corner
// (fast::doubled_window), so their wholes are the texel's column and row in the copy, and the loop
// steps a texel pointer from there without wrapping. BY_MASKS: the driver runs
// fast_run_loop_wrapping instead (the polygon spans more of the texture than a window).
enum RunSource : int32_t { TILED_BLOCK, DOUBLED_COPY, BY_MASKS };

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
    // Then next_lines rows more (0 or less: none) right after them, between next_lower and
    // next_upper: a polygon's next run in the same call, row, u and v stepping on (drawn only where
    // `lines` is at least 1)
    int32_t next_lines;
    EdgeBound* next_lower;
    EdgeBound* next_upper;
    const uint8_t* texture;  // tiled over 256 x 256, aligned to 64 KiB (fast-table: its table block's)
    uint32_t u_16_16, v_16_16;        // at pixel 0 of the first row (fast-table: at the table's first pixel)
    uint32_t u_row_16_16, v_row_16_16;  // their change from row to row
    int32_t du_16_16, dv_16_16;       // per pixel
    uint32_t* tally;         // tally[0] += the spans drawn, tally[1] += their pixels
    const int32_t* table;    // fast-table: table[x] the offset of pixel x (fast-affine: unread)
    // Nonzero: every row whose bounds are in order lies within clip_lo..clip_hi (the polygon's box
    // lies inside the clip), so the NASM loops need not clip (the twins clip all the same)
    int32_t inside;
    // fast-table: the doubled copy (Texture::doubled), a row's first texel at texture + (v whole &
    // v_mask) * block_pitch + (u whole & u_mask); `source` unread. fast-affine: see RunSource.
    RunSource source;
    uint32_t u_mask, v_mask;
    int32_t block_pitch;
};
Loop fast_run_loop;
// fast-affine's and fast-columns' pixels on a polygon that spans more of a texture above 256 a side
// than a window of its doubled copy: the texels the 8:16 core would read, (u whole mod width, v
// whole mod height), from the texture itself by masks, count pixels `stride` bytes apart (C++ only:
// rare polygons); fast_run_loop_wrapping: fast_run_loop's rows so (its texture fields unread).
void wrapping_pixels(const Texture& tex, int32_t du, int32_t dv, uint32_t u, uint32_t v, uint8_t* dst, int32_t count, int32_t stride);
void fast_run_loop_wrapping(const FastRunArgs& a, const Texture& tex);

// A frame's uncut triangle set up for a run loop in one call: setup_polygon's work (PLANES_AFFINE,
// Input::InRange) into `setup`, triangle_runs on it (the target's clip), and the run loop's block
// from them (lines; where there is a row to walk, all but texture, tally and table: the caller's).
// Returns 1; 2 where only the setup is written (the walker walks it); 0 (the NASM routine only)
// where setup_polygon must set it up. fast_triangle_runs: the same from the rows on, for a triangle
// set up already with its 16.16 planes (auto's, or setup_polygon's): 1 or 2. fast_triangle_enveloped:
// fast_triangle, then within_envelope with `envelope`'s limits: 3 where it fails (the setup written).
// Each the C++ twin of its _asm routine (asm/fast.asm; docs/mappers.md, "fast-affine, fast-columns").
struct FastTriangleArgs {
    const Vertex* in;
    PolygonSetup* setup;  // (fast_triangle_runs: read, never written)
    FastRunArgs* run;
    const Target* target;  // linear
    const EnvelopeLimits* envelope;  // (fast_triangle_enveloped's only)
    EdgeBound lower[3], upper[3];  // the chains
};
// What fast_triangle and its kin did (the NASM routines return the same numbers in eax).
enum TriangleTaken : int32_t {
    TRIANGLE_TO_SETUP = 0,         // nothing: setup_polygon must set it up
    TRIANGLE_RUNS = 1,             // set up, its runs and the run loop's block written
    TRIANGLE_TO_WALKER = 2,        // only the setup written: the walker walks it
    TRIANGLE_OUTSIDE_ENVELOPE = 3  // (fast_triangle_enveloped) the setup written, the envelope refuses it
};
TriangleTaken fast_triangle(FastTriangleArgs* a);
TriangleTaken fast_triangle_runs(FastTriangleArgs* a);
TriangleTaken fast_triangle_enveloped(FastTriangleArgs* a);
#if defined(MODEXLAB_ASM_LOOPS)
extern "C" TriangleTaken fast_triangle_asm(FastTriangleArgs* a);
extern "C" TriangleTaken fast_triangle_runs_asm(FastTriangleArgs* a);
extern "C" TriangleTaken fast_triangle_enveloped_asm(FastTriangleArgs* a);
#endif

// fast-table: the offsets of pixel k of any span from its first pixel's texel in the texture's
// doubled copy (TableBlock: W x H its sides, P its pitch), for a polygon whose u and v step by du
// and dv (16.16) a pixel: table[k] = (floor(½ + k dv) & (H - 1)) * P + (floor(½ + k du) & (W - 1)),
// k = 0 .. length - 1, exact in integers (TABLE_START). fast_table_loop walks fast_run_loop's rows
// and reads pixel x0 + k of a row (u0, v0 at x0, where the table starts: at or left of every span's
// first pixel, written from table + x0) at block + (v0 whole & (H - 1)) * P + (u0 whole & (W - 1))
// + table[x0 + k]: the floor of fast-affine's line moved by at most half a texel on each axis
// (docs/bounds.md, "The offset table"; why not the tiled block: docs/mappers.md, "fast-table").
constexpr uint32_t TABLE_START = 0x8000;  // half a texel
constexpr int32_t TABLE_LIMIT = 512;        // room for the longest span (a row: 320 pixels)
// (u and v are 16.16 values modulo 2^32, whose wholes modulo a power of two up to 65536 are the
// floors': 2^32 is a multiple of 2^32 / 65536.)
inline void build_offset_table(int32_t du_16_16, int32_t dv_16_16, int32_t length, int32_t* table, const TableBlock& block) {
    uint32_t u = TABLE_START, v = TABLE_START;
    for (int32_t k = 0; k < length; ++k) {
        table[k] = int32_t(((v >> 16) & block.v_mask) * uint32_t(block.pitch) + ((u >> 16) & block.u_mask));
        u += uint32_t(du_16_16);
        v += uint32_t(dv_16_16);
    }
}
Loop fast_table_loop;

// fast-columns: the same arithmetic down Mode X columns, 80 bytes between pixels.
constexpr int32_t MODEX_ROW_BYTES = 80;
// fast-columns' run of columns (fast_column_run_asm, twin fast_column_run): the columns between two
// vertices of a polygon, x, x + 1, ..., each with its two edge bounds stepped in place and its span
// clipped, as fast_run_loop walks rows, then next_lines columns more between the next bounds; each
// column's pixels through the 8:16 column core (the tiled block) or the doubled copy's texel pointer
// (block_pitch not 0: u and v from the polygon's window's corner, fast::doubled_window, read by a
// texel pointer as fast_run_loop reads them)
// into the Mode X planar target, pixel (x, y) at base + (x & 3) * plane_bytes + y * 80 + x / 4, its
// plane selected first where the target selects planes (the VGA's map mask: select_plane).
struct FastColumnRunArgs {
    const Target* target;             // planar: base, plane_bytes, select_plane and ctx
    int32_t x;                        // the first column
    int32_t lines;                    // its columns, >= 1
    int32_t clip_lo, clip_hi;         // the clip's rows, inclusive
    EdgeBound* lower;                 // stepped in place, once a column
    EdgeBound* upper;
    int32_t next_lines;               // then as many columns more (0 or less: none) between these
    EdgeBound* next_lower;
    EdgeBound* next_upper;
    const uint8_t* texture;           // tiled over 256 x 256, aligned to 64 KiB; or a doubled copy
    int32_t block_pitch;              // 0: the tiled block; else the doubled copy's bytes a row
    uint32_t u_16_16, v_16_16;        // at the first column's pixel 0 (row 0)
    uint32_t u_column_16_16, v_column_16_16;  // their change from column to column
    int32_t du_16_16, dv_16_16;       // per pixel down a column
    uint32_t* tally;                  // tally[0] += the columns drawn, tally[1] += their pixels
};
Loop fast_column_run;
// fast-table-columns: a Mode X column through the polygon's offset table along y (as fast-table's
// rows along x): pixel n, 80 bytes after pixel n - 1, is source[table[n]], source the column's first
// texel in the table block; fatmap-lut's block (the same reading, its stride a row of a plane).
using FastTableColumnArgs = FatmapLutArgs;
Loop fast_table_column_loop;

// fast_run_loop's and fast_table_loop's random cases (a run and the offset table of its steps)
Check check_fast_run;
// fast_column_run's random cases (runs of columns into a planar target, the tiled block or a doubled copy)
Check check_fast_column_run;
Check check_fast_table_column;

}  // namespace raster

extern "C" {
raster::Loop fast_run_loop_asm;
raster::Loop fast_table_loop_asm;
raster::Loop fast_column_run_asm;
raster::Loop fast_table_column_loop_asm;
}

namespace raster::fast {

SetupStatus draw_rows(const DrawContext& c, const Vertex* vertices, int count);        // fast-affine
SetupStatus draw_table_rows(const DrawContext& c, const Vertex* vertices, int count);  // fast-table
SetupStatus draw_columns(const DrawContext& c, const Vertex* vertices, int count);     // fast-columns
// fast-affine's and fast-columns' drivers for auto's envelope (Mapper::enveloped: DrawContext::envelope)
SetupStatus draw_rows_enveloped(const DrawContext& c, const Vertex* vertices, int count);
SetupStatus draw_columns_enveloped(const DrawContext& c, const Vertex* vertices, int count);
SetupStatus draw_table_columns(const DrawContext& c, const Vertex* vertices, int count);  // fast-table-columns
ErrorBound bound(const BoundContext& c, const Vertex* vertices, int count);            // fast-affine, fast-columns
ErrorBound table_bound(const BoundContext& c, const Vertex* vertices, int count);      // fast-table: half a texel more
// fast-affine on a texture's doubled copy: whether the polygon's u and v over the pixels of the clip
// it covers fit a window of the copy, and that window's corner (16.16, to take from u and v)
bool doubled_window(const PolygonSetup& s, const Texture& tex, const ClipRect& clip, uint32_t* u_base, uint32_t* v_base);

// The run loop's `inside`: whether the box lies within the clip's columns (a pixel whose centre lies
// in the box [min_x, max_x] lies in [x0, x1) where the box does; the box, within setup's range, and
// the clip's sides in subpixels within 32 bits).
inline int32_t inside_columns(const PolygonSetup& s, const ClipRect& clip) {
    constexpr int32_t ONE = int32_t(SUBPIXEL_ONE);
    return int32_t(s.min_x) >= clip.x0 * ONE && int32_t(s.max_x) <= clip.x1 * ONE;
}

}  // namespace raster::fast
