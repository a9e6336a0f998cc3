// The mapper registry: one row per mapper, in the order the tables list them. Adding a mapper with
// a NASM loop: kernel/mappers/NAME.h and NAME.cpp (driver, argument block, twin, checks, offsets),
// asm/NAME.asm, and its row here (docs/architecture.md, "Where to add").
#include "kernel/core/mapper.h"
#include "kernel/mappers/affine.h"
#include "kernel/mappers/auto/choice.h"
#include "kernel/mappers/auto/draw.h"
#include "kernel/mappers/exact.h"
#include "kernel/mappers/fast.h"
#include "kernel/mappers/fastsubdiv.h"
#include "kernel/mappers/fatmap.h"
#include "kernel/mappers/hecker.h"
#include "kernel/mappers/quake.h"
#include "kernel/mappers/quake_draw16.h"
#include "kernel/mappers/subdiv.h"
#include "kernel/mappers/xsharp.h"

namespace raster {

// Each row names its fields (core/mapper.h says what each holds); a field left out takes its
// default: no span function, loop, driver, check or bound, not auto, spans not asked.
const Mapper MAPPERS[] = {
    {.name = "affine", .family = "ours", .origin = "textbook affine interpolation",
     .promise = "exact coverage; u, v affine in screen space (16.16 steps): error grows with depth variation",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_NOTHING, .axes = AXIS_BOTH, .span = affine_span, .bound = affine_bound,
     .span_planes = PLANES_AFFINE},
    {.name = "exact", .family = "ours", .origin = "the reference's definition, per pixel",
     .promise = "equal to the reference: per-pixel perspective divide in double precision",
     .guarantee = EQUALS_REFERENCE, .needs = NEED_NOTHING, .axes = AXIS_BOTH, .span = exact_span,
     TWIN_AND_ASM(exact_loop), .check = check_exact, .bound = exact_bound, .auto_role = AutoRole::Fallback},
    {.name = "persp-subdiv-4", .family = "ours", .origin = "exact every 4 pixels, affine between",
     .promise = "perspective-correct at every 4th pixel and the last; 16.16 steps rounded to nearest; exact coverage; any texture",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_NOTHING, .axes = AXIS_BOTH, .span = subdiv_span<4>,
     TWIN_AND_ASM(step_loop), .check = check_step, .bound = subdiv_bound<4>},
    {.name = "persp-subdiv-8", .family = "ours", .origin = "exact every 8 pixels, affine between",
     .promise = "as persp-subdiv-4, every 8th pixel",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_NOTHING, .axes = AXIS_BOTH, .span = subdiv_span<8>,
     TWIN_AND_ASM(step_loop), .check = check_step, .bound = subdiv_bound<8>},
    {.name = "persp-subdiv-16", .family = "ours", .origin = "exact every 16 pixels, affine between",
     .promise = "as persp-subdiv-4, every 16th pixel",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_NOTHING, .axes = AXIS_BOTH, .span = subdiv_span<16>,
     TWIN_AND_ASM(step_loop), .check = check_step, .bound = subdiv_bound<16>},
    {.name = "persp-subdiv-32", .family = "ours", .origin = "exact every 32 pixels, affine between",
     .promise = "as persp-subdiv-4, every 32nd pixel",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_NOTHING, .axes = AXIS_BOTH, .span = subdiv_span<32>,
     TWIN_AND_ASM(step_loop), .check = check_step, .bound = subdiv_bound<32>},
    {.name = "constant-depth", .family = "ours", .origin = "Doom's floors and walls: exact at both ends of each row or column, affine between",
     .promise = "exact u, v at each span's first and last pixel centre, 16.16 steps between: exact up to rounding along lines of constant "
         "depth (floors and ceilings by rows, upright walls by columns), its bound says how far off elsewhere; exact coverage; any texture",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_NOTHING, .axes = AXIS_BOTH, .span = subdiv_span<SPAN_LONG>,
     TWIN_AND_ASM(step_loop), .check = check_step, .bound = subdiv_bound<SPAN_LONG>,
     .span_proof = SPANS_ASKED},
    {.name = "persp-adaptive-0.5", .family = "ours", .origin = "runs as long as the bound keeps within half a footprint",
     .promise = "exact u, v at each run's ends, 16.16 steps between; each run the longest (to 256 pixels) whose chord bound is within "
         "0.5 footprints, from the curvature of 1/w there: long where depth barely changes; exact coverage; any texture",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_NOTHING, .axes = AXIS_BOTH, .span = adaptive_span<2>,
     TWIN_AND_ASM(step_loop), .check = check_step, .bound = adaptive_bound<2>},
    {.name = "persp-adaptive-1", .family = "ours", .origin = "runs as long as the bound keeps within one footprint",
     .promise = "as persp-adaptive-0.5, within 1 footprint",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_NOTHING, .axes = AXIS_BOTH, .span = adaptive_span<4>,
     TWIN_AND_ASM(step_loop), .check = check_step, .bound = adaptive_bound<4>},
    {.name = "persp-adaptive-2", .family = "ours", .origin = "runs as long as the bound keeps within two footprints",
     .promise = "as persp-adaptive-0.5, within 2 footprints",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_NOTHING, .axes = AXIS_BOTH, .span = adaptive_span<8>,
     TWIN_AND_ASM(step_loop), .check = check_step, .bound = adaptive_bound<8>},
    {.name = "persp-adaptive-4", .family = "ours", .origin = "runs as long as the bound keeps within four footprints",
     .promise = "as persp-adaptive-0.5, within 4 footprints",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_NOTHING, .axes = AXIS_BOTH, .span = adaptive_span<16>,
     TWIN_AND_ASM(step_loop), .check = check_step, .bound = adaptive_bound<16>},
    {.name = "fast-affine", .family = "ours", .origin = "fatmap2's 8:16 core, unrolled with a computed entry, walking runs of rows in NASM",
     .promise = "exact coverage; u, v affine from the polygon's 16.16 planes at each span's first pixel centre; textures with power-of-two "
         "sides up to 1024, repeating or with the polygon's coordinates inside (up to 256 tiled over 256 x 256; above, from the doubled "
         "copy where the polygon's coordinates span at most the sides and 15 texels more, else from the texture by masks)",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_POW2_OR_INSIDE, .axes = AXIS_ROWS,
     TWIN_AND_ASM(fast_run_loop), .draw = fast::draw_rows, .check = check_fast_run,
     .bound = fast::bound, .enveloped = fast::draw_rows_enveloped},
    {.name = "fast-table", .family = "ours", .origin = "fast-affine's runs of rows, each span's texels at offsets from its first precomputed once a polygon (fatmap's table idea)",
     .promise = "exact coverage; u, v affine from the polygon's 16.16 planes, each texel read at most half a texel on each axis from "
         "fast-affine's line (the table reads each span as if it started at its first texel's centre): within one texel without perspective; "
         "textures with power-of-two sides up to 1024, repeating or with the polygon's coordinates inside, from their doubled copy",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_POW2_OR_INSIDE | NEED_DOUBLED, .axes = AXIS_ROWS,
     TWIN_AND_ASM(fast_table_loop), .draw = fast::draw_table_rows, .check = check_fast_run,
     .bound = fast::table_bound},
    {.name = "fast-columns", .family = "ours", .origin = "the same core down Mode X columns, the map mask set once a column",
     .promise = "as fast-affine, by columns into Mode X planes",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_POW2_OR_INSIDE | NEED_PLANAR_TARGET, .axes = AXIS_COLUMNS,
     TWIN_AND_ASM(fast_column_run), .draw = fast::draw_columns, .check = check_fast_column_run,
     .bound = fast::bound, .enveloped = fast::draw_columns_enveloped},
    {.name = "fast-table-columns", .family = "ours", .origin = "fast-table's offsets down Mode X columns, the map mask set once a column",
     .promise = "as fast-table, by columns into Mode X planes: within one texel without perspective",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_POW2_OR_INSIDE | NEED_DOUBLED | NEED_PLANAR_TARGET, .axes = AXIS_COLUMNS,
     TWIN_AND_ASM(fast_table_column_loop), .draw = fast::draw_table_columns,
     .check = check_fast_table_column, .bound = fast::table_bound},
    {.name = "fast-subdiv-8", .family = "ours", .origin = "exact every 8 pixels in x87, the fast 8:16 core between, one NASM loop a span",
     .promise = "perspective-correct at every 8th pixel and the last; 16.16 steps from the ends' difference; exact coverage; repeating "
         "textures with power-of-two sides up to 1024 (tiled over 256 x 256, or a doubled copy above 256); rows in pairs, columns "
         "a pixel at a time",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_POW2_REPEAT, .axes = AXIS_BOTH, .span = fast_subdiv_span<8>,
     TWIN_AND_ASM(fast_subdiv_loop), .check = check_fast_subdiv, .bound = fast_subdiv_bound<8>},
    {.name = "fast-subdiv-16", .family = "ours", .origin = "exact every 16 pixels in x87, the fast 8:16 core between",
     .promise = "as fast-subdiv-8, every 16th pixel",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_POW2_REPEAT, .axes = AXIS_BOTH, .span = fast_subdiv_span<16>,
     TWIN_AND_ASM(fast_subdiv_loop), .check = check_fast_subdiv, .bound = fast_subdiv_bound<16>},
    {.name = "fast-subdiv-32", .family = "ours", .origin = "exact every 32 pixels in x87, the fast 8:16 core between",
     .promise = "as fast-subdiv-8, every 32nd pixel",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_POW2_REPEAT, .axes = AXIS_BOTH, .span = fast_subdiv_span<32>,
     TWIN_AND_ASM(fast_subdiv_loop), .check = check_fast_subdiv, .bound = fast_subdiv_bound<32>},
    {.name = "fast-constant-depth", .family = "ours", .origin = "Doom's floors and walls on the fast core: exact at both ends of each row or column in x87, the 8:16 core between",
     .promise = "exact u, v at each span's first and last pixel centre, 16.16 steps between: exact up to rounding along lines of constant "
         "depth (floors and ceilings by rows, upright walls by columns), its bound says how far off elsewhere; exact coverage; textures "
         "as fast-subdiv-8",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_POW2_REPEAT, .axes = AXIS_BOTH, .span = fast_subdiv_span<FAST_SPAN_LONG>,
     TWIN_AND_ASM(fast_subdiv_loop), .check = check_fast_subdiv,
     .bound = fast_subdiv_bound<FAST_SPAN_LONG>, .span_proof = SPANS_ASKED, .auto_role = AutoRole::ConstantDepth},
    {.name = "fast-adaptive-1", .family = "ours", .origin = "fast-subdiv's loop, its segments span by span as long as the bound keeps within one footprint",
     .promise = "exact u, v every 2^s pixels and at the last, the fast 8:16 core between, s for each span the largest (to 512 pixels) whose "
         "chords the relative chords bound keeps within 1 footprint (long where 1/w barely changes along the span); exact coverage; "
         "textures as fast-subdiv-8",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_POW2_REPEAT, .axes = AXIS_BOTH, .span = fast_adaptive_span<4>,
     TWIN_AND_ASM(fast_subdiv_loop), .check = check_fast_subdiv, .bound = fast_adaptive_bound<4>, .auto_role = AutoRole::Adaptive1},
    {.name = "fast-adaptive-2", .family = "ours", .origin = "fast-subdiv's loop, its segments span by span as long as the bound keeps within two footprints",
     .promise = "as fast-adaptive-1, within 2 footprints",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_POW2_REPEAT, .axes = AXIS_BOTH, .span = fast_adaptive_span<8>,
     TWIN_AND_ASM(fast_subdiv_loop), .check = check_fast_subdiv, .bound = fast_adaptive_bound<8>, .auto_role = AutoRole::Adaptive2},
    {.name = "fast-oriented-1", .family = "ours", .origin = "fast-adaptive-1 along the walker where 1/w changes least, polygon by polygon (walls by columns, floors by rows)",
     .promise = "as fast-adaptive-1 (within 1 footprint), each polygon by rows or by columns, whichever its 1/w gradient and its lines make "
         "cheaper (on a Mode X target: columns); exact coverage; textures as fast-subdiv-8",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_POW2_REPEAT, .axes = AXIS_BOTH,
     TWIN_AND_ASM(fast_subdiv_loop), .draw = fast_oriented_draw<4>, .check = check_fast_subdiv,
     .bound = fast_oriented_bound<4>, .own_walker = fast_oriented_walker<4>, .auto_role = AutoRole::Oriented},
    {.name = "xsharp-dda", .family = "classic", .origin = "Abrash, Black Book listing 57.1 (X-Sharp 21, C)",
     .promise = "affine; whole-pixel vertices, X-Sharp's fill convention; half-step prestep, rounds to the nearest texel; cannot wrap",
     .guarantee = NO_GUARANTEE, .needs = NEED_BORDERED | NEED_INSIDE, .axes = AXIS_ROWS, .draw = xsharp::draw_dda,
     .bound = xsharp::bound_rows},
    {.name = "xsharp-row-out", .family = "classic", .origin = "Abrash, Black Book listing 57.2, inner loop 58.1 (X-Sharp 21, asm)",
     .promise = "the same pixels as xsharp-dda, written to Mode X planes with an OUT to the Map Mask per pixel",
     .guarantee = NO_GUARANTEE, .needs = NEED_BORDERED | NEED_INSIDE | NEED_PLANAR_TARGET | NEED_VGA_FOR_ASM, .axes = AXIS_ROWS,
     TWIN_AND_ASM(xsharp_row_loop), .draw = xsharp::draw_row_out, .bound = xsharp::bound_rows},
    {.name = "xsharp-column", .family = "classic", .origin = "Abrash, Black Book listing 58.4, as X-Sharp 22 shipped it",
     .promise = "affine; columns with X-Sharp's fill convention; the Y fraction keeps 15 bits (a texel row off at about 2 pixels in 10000)",
     .guarantee = NO_GUARANTEE, .needs = NEED_BORDERED | NEED_INSIDE | NEED_PLANAR_TARGET, .axes = AXIS_COLUMNS,
     TWIN_AND_ASM(xsharp_column_loop), .draw = xsharp::draw_column,
     .check = check_xsharp_column, .bound = xsharp::bound_column},
    {.name = "hecker-steptable", .family = "classic", .origin = "Hecker, Game Developer 1995-96, parts III-V (SUBAFXFL setup, part V listing 2 loop)",
     .promise = "perspective-correct every 8 pixels, affine between; 28.4 vertices, top-left fill; rounding modifiers from du/dx; cannot wrap",
     .guarantee = NO_GUARANTEE, .needs = NEED_BORDERED | NEED_INSIDE, .axes = AXIS_ROWS,
     TWIN_AND_ASM(hecker_loop), .draw = hecker::draw, .check = check_hecker, .bound = hecker::bound},
    {.name = "fatmap-256", .family = "classic", .origin = "Byggmastar, fatmap.txt (1996): the constant-delta setup and the 5-tick loop",
     .promise = "affine; whole-pixel vertices, x truncated, no prestep; 8-bit fractions (\"shaky\"); 256 x 256 only, wraps",
     .guarantee = NO_GUARANTEE, .needs = NEED_ALIGNED256, .axes = AXIS_ROWS, TWIN_AND_ASM(fatmap_loop),
     .draw = fatmap::draw_256, .check = check_fatmap, .bound = fatmap::bound_256},
    {.name = "fatmap-256-16", .family = "classic", .origin = "Byggmastar, fatmap.txt setup with fatmap2.txt's 8:16 loop (Simmons)",
     .promise = "as fatmap-256 with 16-bit fractions in the loop",
     .guarantee = NO_GUARANTEE, .needs = NEED_ALIGNED256, .axes = AXIS_ROWS,
     TWIN_AND_ASM(fatmap16_loop), .draw = fatmap::draw_256, .check = check_fatmap,
     .bound = fatmap::bound_256_16},
    {.name = "fatmap-lut", .family = "classic", .origin = "Byggmastar, fatmap.txt section 13: the table-lookup loop",
     .promise = "affine; every scanline starts at the table's first entry: its start fractions dropped, up to a texel off on each axis and drifting; 256 x 256 only, cannot wrap",
     .guarantee = NO_GUARANTEE, .needs = NEED_ALIGNED256 | NEED_INSIDE, .axes = AXIS_ROWS,
     TWIN_AND_ASM(fatmap_lut_loop), .draw = fatmap::draw_lut, .check = check_fatmap_lut,
     .bound = fatmap::bound_lut},
    {.name = "quake-subdiv16", .family = "classic", .origin = "id Software, WinQuake d_scan.c / d_draw16.s (1996-99)",
     .promise = "perspective-correct every 16 pixels and at each span's last pixel, affine between (steps floored); s, t clamped into the texture; exact coverage (our walker)",
     .guarantee = EXACT_COVERAGE, .needs = NEED_INSIDE, .axes = AXIS_ROWS,
     TWIN_AND_ASM(quake_span_loop), .draw = quake::draw16, .check = check_quake,
     .bound = quake::bound16, .span_proof = SPANS_ASKED},
    {.name = "quake-subdiv8", .family = "classic", .origin = "id Software, WinQuake d_scan.c D_DrawSpans8 / d_draw.s",
     .promise = "as quake-subdiv16 with 8-pixel segments",
     .guarantee = EXACT_COVERAGE, .needs = NEED_INSIDE, .axes = AXIS_ROWS,
     TWIN_AND_ASM(quake_span_loop), .draw = quake::draw8, .check = check_quake,
     .bound = quake::bound8, .span_proof = SPANS_ASKED},
    {.name = "quake-d_draw16", .family = "classic", .origin = "id Software, WinQuake d_draw16.s D_DrawSpans16, as shipped (Abrash, Black Book ch. 68 and 70)",
     .promise = "as quake-subdiv16, with d_draw16.s's own arithmetic: s/z, t/z, 1/z as floats and the x87 at 24-bit precision with chop (Quake's single_cw), "
         "full segments stepped exactly (delta / 16), the last by a reciprocal table, segment ends clamped to [1/16 texel, size)",
     .guarantee = EXACT_COVERAGE, .needs = NEED_INSIDE, .axes = AXIS_ROWS,
     TWIN_AND_ASM(quake_draw16_loop), .draw = quake::draw_d_draw16, .check = check_quake_draw16,
     .bound = quake::bound_d_draw16, .span_proof = SPANS_ASKED},
    {.name = "auto", .family = "ours", .origin = "the scene's budget: the cheapest mapper proven to meet it, polygon by polygon",
     .promise = "each polygon by the cheapest of the bounded mappers (the cost model: make bench) whose error bound meets the scene's budget "
         "(without a budget line: footprint error 1, exact coverage); exact coverage unless the budget allows any",
     .guarantee = EXACT_COVERAGE_FLAT_ONE, .needs = NEED_NOTHING, .axes = AXIS_BOTH, .bound = auto_bound, .is_auto = true,
     .chooses = auto_draw, .draw_frame = auto_draw_frame},
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
