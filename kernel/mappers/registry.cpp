// The mapper registry: one row per mapper, in the order the tables list them. Adding a mapper with
// a NASM loop: kernel/mappers/NAME.h and NAME.cpp (driver, argument block, twin, checks, offsets),
// asm/NAME.asm, and its row here (docs/architecture.md, "Where to add").
#include "kernel/core/bound.h"
#include "kernel/core/choice.h"
#include "kernel/core/mapper.h"
#include "kernel/mappers/affine.h"
#include "kernel/mappers/exact.h"
#include "kernel/mappers/fast.h"
#include "kernel/mappers/fastsubdiv.h"
#include "kernel/mappers/fatmap.h"
#include "kernel/mappers/hecker.h"
#include "kernel/mappers/quake.h"
#include "kernel/mappers/subdiv.h"
#include "kernel/mappers/xsharp.h"

namespace raster {

// Each row: name, family, origin; the promise in words; the promise checkable, what it needs, the
// walkers it takes; its span function (generic walker) or nullptr; its twin loop and NASM loop
// (TWIN_AND_ASM); its own polygon driver; the random cases that check its NASM loop; its error
// bound on a polygon (core/bound.h; unbounded where none is derived yet); whether it is auto; and
// whether auto asks its bound span by span (SpanProof).
const Mapper MAPPERS[] = {
    {"affine", "ours", "textbook affine interpolation",
     "exact coverage; u, v affine in screen space (16.16 steps): error grows with depth variation",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, affine_span, nullptr, nullptr, nullptr, nullptr, affine_bound, false, SPANS_NOT_ASKED,
     nullptr, PLANES_AFFINE},
    {"exact", "ours", "the reference's definition, per pixel",
     "equal to the reference: per-pixel perspective divide in double precision",
     EQUALS_REFERENCE, NEED_NOTHING, AXIS_BOTH, exact_span, TWIN_AND_ASM(exact_loop), nullptr, check_exact, exact_bound},
    {"persp-subdiv-4", "ours", "exact every 4 pixels, affine between",
     "perspective-correct at every 4th pixel and the last; 16.16 steps rounded to nearest; exact coverage; any texture",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, subdiv_span<4>, TWIN_AND_ASM(step_loop), nullptr, check_step, subdiv_bound<4>},
    {"persp-subdiv-8", "ours", "exact every 8 pixels, affine between", "as persp-subdiv-4, every 8th pixel",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, subdiv_span<8>, TWIN_AND_ASM(step_loop), nullptr, check_step, subdiv_bound<8>},
    {"persp-subdiv-16", "ours", "exact every 16 pixels, affine between", "as persp-subdiv-4, every 16th pixel",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, subdiv_span<16>, TWIN_AND_ASM(step_loop), nullptr, check_step, subdiv_bound<16>},
    {"persp-subdiv-32", "ours", "exact every 32 pixels, affine between", "as persp-subdiv-4, every 32nd pixel",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, subdiv_span<32>, TWIN_AND_ASM(step_loop), nullptr, check_step, subdiv_bound<32>},
    {"constant-depth", "ours", "Doom's floors and walls: exact at both ends of each row or column, affine between",
     "exact u, v at each span's first and last pixel centre, 16.16 steps between: exact up to rounding along lines of constant "
     "depth (floors and ceilings by rows, upright walls by columns), its bound says how far off elsewhere; exact coverage; any texture",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, subdiv_span<SPAN_LONG>, TWIN_AND_ASM(step_loop), nullptr, check_step, subdiv_bound<SPAN_LONG>, false, SPANS_ASKED},
    {"persp-adaptive-0.5", "ours", "runs as long as the bound keeps within half a footprint",
     "exact u, v at each run's ends, 16.16 steps between; each run the longest (to 256 pixels) whose chord bound is within "
     "0.5 footprints, from the curvature of 1/w there: long where depth barely changes; exact coverage; any texture",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, adaptive_span<2>, TWIN_AND_ASM(step_loop), nullptr, check_step, adaptive_bound<2>},
    {"persp-adaptive-1", "ours", "runs as long as the bound keeps within one footprint", "as persp-adaptive-0.5, within 1 footprint",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, adaptive_span<4>, TWIN_AND_ASM(step_loop), nullptr, check_step, adaptive_bound<4>},
    {"persp-adaptive-2", "ours", "runs as long as the bound keeps within two footprints", "as persp-adaptive-0.5, within 2 footprints",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, adaptive_span<8>, TWIN_AND_ASM(step_loop), nullptr, check_step, adaptive_bound<8>},
    {"persp-adaptive-4", "ours", "runs as long as the bound keeps within four footprints", "as persp-adaptive-0.5, within 4 footprints",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, adaptive_span<16>, TWIN_AND_ASM(step_loop), nullptr, check_step, adaptive_bound<16>},
    {"fast-affine", "ours", "fatmap2's 8:16 core, unrolled with a computed entry, walking runs of rows in NASM",
     "exact coverage; u, v affine from the polygon's 16.16 planes at each span's first pixel centre; textures with power-of-two "
     "sides up to 1024, repeating or with the polygon's coordinates inside (up to 256 tiled over 256 x 256; above, from the doubled "
     "copy where the polygon's coordinates span at most the sides and 15 texels more, else from the texture by masks)",
     EXACT_COVERAGE_FLAT_ONE, NEED_POW2_OR_INSIDE, AXIS_ROWS, nullptr, TWIN_AND_ASM(fast_run_loop), fast::draw_rows, check_fast_run, fast::bound, false, SPANS_NOT_ASKED,
     fast::draw_rows_enveloped},
    {"fast-table", "ours", "fast-affine's runs of rows, each span's texels at offsets from its first precomputed once a polygon (fatmap's table idea)",
     "exact coverage; u, v affine from the polygon's 16.16 planes, each texel read at most half a texel on each axis from "
     "fast-affine's line (the table reads each span as if it started at its first texel's centre): within one texel without perspective; "
     "textures with power-of-two sides up to 1024, repeating or with the polygon's coordinates inside, from their doubled copy",
     EXACT_COVERAGE_FLAT_ONE, NEED_POW2_OR_INSIDE | NEED_DOUBLED, AXIS_ROWS, nullptr, TWIN_AND_ASM(fast_table_loop), fast::draw_table_rows,
     check_fast_run, fast::table_bound},
    {"fast-columns", "ours", "the same core down Mode X columns, the map mask set once a column",
     "as fast-affine, by columns into Mode X planes",
     EXACT_COVERAGE_FLAT_ONE, NEED_POW2_OR_INSIDE | NEED_PLANAR_TARGET, AXIS_COLUMNS, nullptr, TWIN_AND_ASM(fast_column_run),
     fast::draw_columns, check_fast_column_run, fast::bound, false, SPANS_NOT_ASKED, fast::draw_columns_enveloped},
    {"fast-table-columns", "ours", "fast-table's offsets down Mode X columns, the map mask set once a column",
     "as fast-table, by columns into Mode X planes: within one texel without perspective",
     EXACT_COVERAGE_FLAT_ONE, NEED_POW2_OR_INSIDE | NEED_DOUBLED | NEED_PLANAR_TARGET, AXIS_COLUMNS, nullptr,
     TWIN_AND_ASM(fast_table_column_loop), fast::draw_table_columns, check_fast_table_column, fast::table_bound},
    {"fast-subdiv-8", "ours", "exact every 8 pixels in x87, the fast 8:16 core between, one NASM loop a span",
     "perspective-correct at every 8th pixel and the last; 16.16 steps from the ends' difference; exact coverage; repeating "
     "textures with power-of-two sides up to 1024 (tiled over 256 x 256, or a doubled copy above 256); rows in pairs, columns "
     "a pixel at a time",
     EXACT_COVERAGE_FLAT_ONE, NEED_POW2_REPEAT, AXIS_BOTH, fast_subdiv_span<8>, TWIN_AND_ASM(fast_subdiv_loop), nullptr, check_fast_subdiv,
     fast_subdiv_bound<8>},
    {"fast-subdiv-16", "ours", "exact every 16 pixels in x87, the fast 8:16 core between", "as fast-subdiv-8, every 16th pixel",
     EXACT_COVERAGE_FLAT_ONE, NEED_POW2_REPEAT, AXIS_BOTH, fast_subdiv_span<16>, TWIN_AND_ASM(fast_subdiv_loop), nullptr, check_fast_subdiv,
     fast_subdiv_bound<16>},
    {"fast-subdiv-32", "ours", "exact every 32 pixels in x87, the fast 8:16 core between", "as fast-subdiv-8, every 32nd pixel",
     EXACT_COVERAGE_FLAT_ONE, NEED_POW2_REPEAT, AXIS_BOTH, fast_subdiv_span<32>, TWIN_AND_ASM(fast_subdiv_loop), nullptr, check_fast_subdiv,
     fast_subdiv_bound<32>},
    {"fast-constant-depth", "ours", "Doom's floors and walls on the fast core: exact at both ends of each row or column in x87, the 8:16 core between",
     "exact u, v at each span's first and last pixel centre, 16.16 steps between: exact up to rounding along lines of constant "
     "depth (floors and ceilings by rows, upright walls by columns), its bound says how far off elsewhere; exact coverage; textures "
     "as fast-subdiv-8",
     EXACT_COVERAGE_FLAT_ONE, NEED_POW2_REPEAT, AXIS_BOTH, fast_subdiv_span<FAST_SPAN_LONG>, TWIN_AND_ASM(fast_subdiv_loop), nullptr,
     check_fast_subdiv, fast_subdiv_bound<FAST_SPAN_LONG>, false, SPANS_ASKED},
    {"fast-adaptive-1", "ours", "fast-subdiv's loop, its segments span by span as long as the bound keeps within one footprint",
     "exact u, v every 2^s pixels and at the last, the fast 8:16 core between, s for each span the largest (to 512 pixels) whose "
     "chords the relative chords bound keeps within 1 footprint (long where 1/w barely changes along the span); exact coverage; "
     "textures as fast-subdiv-8",
     EXACT_COVERAGE_FLAT_ONE, NEED_POW2_REPEAT, AXIS_BOTH, fast_adaptive_span<4>, TWIN_AND_ASM(fast_subdiv_loop), nullptr, check_fast_subdiv,
     fast_adaptive_bound<4>},
    {"fast-adaptive-2", "ours", "fast-subdiv's loop, its segments span by span as long as the bound keeps within two footprints",
     "as fast-adaptive-1, within 2 footprints",
     EXACT_COVERAGE_FLAT_ONE, NEED_POW2_REPEAT, AXIS_BOTH, fast_adaptive_span<8>, TWIN_AND_ASM(fast_subdiv_loop), nullptr, check_fast_subdiv,
     fast_adaptive_bound<8>},
    {"fast-oriented-1", "ours", "fast-adaptive-1 along the walker where 1/w changes least, polygon by polygon (walls by columns, floors by rows)",
     "as fast-adaptive-1 (within 1 footprint), each polygon by rows or by columns, whichever its 1/w gradient and its lines make "
     "cheaper (on a Mode X target: columns); exact coverage; textures as fast-subdiv-8",
     EXACT_COVERAGE_FLAT_ONE, NEED_POW2_REPEAT, AXIS_BOTH, nullptr, TWIN_AND_ASM(fast_subdiv_loop), fast_oriented_draw<4>, check_fast_subdiv,
     fast_oriented_bound<4>, false, SPANS_NOT_ASKED, nullptr, PLANES_PERSPECTIVE, fast_oriented_walker<4>},
    {"xsharp-dda", "classic", "Abrash, Black Book listing 57.1 (X-Sharp 21, C)",
     "affine; whole-pixel vertices, X-Sharp's fill convention; half-step prestep, rounds to the nearest texel; cannot wrap",
     NO_GUARANTEE, NEED_BORDERED | NEED_INSIDE, AXIS_ROWS, nullptr, nullptr, nullptr, xsharp::draw_dda, nullptr, xsharp::bound_rows},
    {"xsharp-row-out", "classic", "Abrash, Black Book listing 57.2, inner loop 58.1 (X-Sharp 21, asm)",
     "the same pixels as xsharp-dda, written to Mode X planes with an OUT to the Map Mask per pixel",
     NO_GUARANTEE, NEED_BORDERED | NEED_INSIDE | NEED_PLANAR_TARGET | NEED_VGA_FOR_ASM, AXIS_ROWS, nullptr, TWIN_AND_ASM(xsharp_row_loop),
     xsharp::draw_row_out, nullptr, xsharp::bound_rows},
    {"xsharp-column", "classic", "Abrash, Black Book listing 58.4, as X-Sharp 22 shipped it",
     "affine; columns with X-Sharp's fill convention; the Y fraction keeps 15 bits (a texel row off at about 2 pixels in 10000)",
     NO_GUARANTEE, NEED_BORDERED | NEED_INSIDE | NEED_PLANAR_TARGET, AXIS_COLUMNS, nullptr, TWIN_AND_ASM(xsharp_column_loop),
     xsharp::draw_column, check_xsharp_column, xsharp::bound_column},
    {"hecker-steptable", "classic", "Hecker, Game Developer 1995-96, parts III-V (SUBAFXFL setup, part V listing 2 loop)",
     "perspective-correct every 8 pixels, affine between; 28.4 vertices, top-left fill; rounding modifiers from du/dx; cannot wrap",
     NO_GUARANTEE, NEED_BORDERED | NEED_INSIDE, AXIS_ROWS, nullptr, TWIN_AND_ASM(hecker_loop), hecker::draw, check_hecker, hecker::bound},
    {"fatmap-256", "classic", "Byggmastar, fatmap.txt (1996): the constant-delta setup and the 5-tick loop",
     "affine; whole-pixel vertices, x truncated, no prestep; 8-bit fractions (\"shaky\"); 256 x 256 only, wraps",
     NO_GUARANTEE, NEED_ALIGNED256, AXIS_ROWS, nullptr, TWIN_AND_ASM(fatmap_loop), fatmap::draw_256, check_fatmap, fatmap::bound_256},
    {"fatmap-256-16", "classic", "Byggmastar, fatmap.txt setup with fatmap2.txt's 8:16 loop (Simmons)",
     "as fatmap-256 with 16-bit fractions in the loop",
     NO_GUARANTEE, NEED_ALIGNED256, AXIS_ROWS, nullptr, TWIN_AND_ASM(fatmap16_loop), fatmap::draw_256, check_fatmap, fatmap::bound_256_16},
    {"fatmap-lut", "classic", "Byggmastar, fatmap.txt section 13: the table-lookup loop",
     "affine; every scanline starts at the table's first entry: its start fractions dropped, up to a texel off on each axis and drifting; 256 x 256 only, cannot wrap",
     NO_GUARANTEE, NEED_ALIGNED256 | NEED_INSIDE, AXIS_ROWS, nullptr, TWIN_AND_ASM(fatmap_lut_loop),
     fatmap::draw_lut, check_fatmap_lut, fatmap::bound_lut},
    {"quake-subdiv16", "classic", "id Software, WinQuake d_scan.c / d_draw16.s (1996-99)",
     "perspective-correct every 16 pixels and at each span's last pixel, affine between (steps floored); s, t clamped into the texture; exact coverage (our walker)",
     EXACT_COVERAGE, NEED_INSIDE, AXIS_ROWS, nullptr, TWIN_AND_ASM(quake_span_loop), quake::draw16, check_quake, quake::bound16, false, SPANS_ASKED},
    {"quake-subdiv8", "classic", "id Software, WinQuake d_scan.c D_DrawSpans8 / d_draw.s",
     "as quake-subdiv16 with 8-pixel segments",
     EXACT_COVERAGE, NEED_INSIDE, AXIS_ROWS, nullptr, TWIN_AND_ASM(quake_span_loop), quake::draw8, check_quake, quake::bound8, false, SPANS_ASKED},
    {"auto", "ours", "the scene's budget: the cheapest mapper proven to meet it, polygon by polygon",
     "each polygon by the cheapest of the bounded mappers (the cost model: make bench) whose error bound meets the scene's budget "
     "(without a budget line: footprint error 1, exact coverage); exact coverage unless the budget allows any",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, nullptr, nullptr, nullptr, nullptr, nullptr, auto_bound, true},
};
const int MAPPER_COUNT = sizeof(MAPPERS) / sizeof(MAPPERS[0]);
static_assert(sizeof(MAPPERS) / sizeof(MAPPERS[0]) <= MAPPER_LIMIT, "more registry rows than MAPPER_LIMIT");

const Mapper* find_mapper(lib::StrView name) {
    for (int i = 0; i < MAPPER_COUNT; ++i)
        if (name.equals(MAPPERS[i].name)) return &MAPPERS[i];
    return nullptr;
}

const NeedName NEED_NAMES[] = {
    {NEED_BORDERED, "bordered", "the texture's bordered copy"},
    {NEED_DOUBLED, "doubled", "the texture's doubled copy"},
    {NEED_INSIDE, "inside-texture", "texture coordinates inside the texture"},
    {NEED_PLANAR_TARGET, "planar-target", "a Mode X target (surface planar or vga)"},
    {NEED_VGA_FOR_ASM, "vga-for-asm", "a VGA page for its NASM loop"},
    {NEED_ALIGNED256, "256x256-repeat", "a 256x256 repeating texture"},
    {NEED_POW2_REPEAT, "pow2-repeat", "a repeating texture with power-of-two sides up to 1024"},
    {NEED_TILED256_OR_INSIDE, "pow2-repeat-or-inside",
     "a texture with power-of-two sides up to 256, repeating or with the polygon's coordinates inside it"},
    {NEED_POW2_OR_INSIDE, "pow2-1024-repeat-or-inside",
     "a texture with power-of-two sides up to 1024, repeating or with the polygon's coordinates inside it"},
};
const int NEED_NAME_COUNT = sizeof(NEED_NAMES) / sizeof(NEED_NAMES[0]);

void describe_needs(lib::Fmt& m, uint32_t needs) {
    const char* sep = "";
    for (int i = 0; i < NEED_NAME_COUNT; ++i)
        if (needs & NEED_NAMES[i].need) m.s(sep).s(NEED_NAMES[i].words), sep = ", ";
}

}  // namespace raster
