// Our generic-walker mappers' span functions, and the registry.
#include "kernel/core/mapper.h"

#include "kernel/mappers/fast.h"
#include "kernel/mappers/fatmap.h"
#include "kernel/mappers/hecker.h"
#include "kernel/mappers/quake.h"
#include "kernel/mappers/xsharp.h"

namespace raster {

namespace {

// A texture coordinate in 16.16 at a span's start. With repeat, it is first reduced modulo the
// texture size (same texels, and far from the 16.16 limit of +-32768 texels); with clamp it
// saturates, which clamps to the same edge texel.
Fixed16_16 start_coordinate(double t, int32_t size, Wrap wrap) {
    if (wrap == Wrap::Repeat) {
        double period = double(size);
        t -= period * double(floor_i64(t / period));  // exact: the result is a multiple of t's ulp below 2*size
    }
    return Fixed16_16::from_double(t);
}

// affine: u and v linear in screen space, stepped in 16.16 from their value at the span's first
// pixel centre; texel = floor.
void affine_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride) {
    const PolygonSetup& setup = c.setup;
    double x = centre_x(setup, s.x), y = centre_y(setup, s.y);
    Fixed16_16 u = start_coordinate(setup.u.at(x, y), c.tex.width, c.tex.wrap);
    Fixed16_16 v = start_coordinate(setup.v.at(x, y), c.tex.height, c.tex.wrap);
    double per_pixel = double(SUBPIXEL_ONE);
    Fixed16_16 du = Fixed16_16::from_double((c.axis == Axis::Rows ? setup.u.gx : setup.u.gy) * per_pixel);
    Fixed16_16 dv = Fixed16_16::from_double((c.axis == Axis::Rows ? setup.v.gx : setup.v.gy) * per_pixel);
    for (int32_t n = 0; n < s.count; ++n) {
        *dst = texel(c.tex, u.floor_int(), v.floor_int());
        dst += stride;
        u = u + du;
        v = v + dv;
    }
}

// exact: the argument block for exact_loop / exact_loop_asm.
void exact_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride) {
    const PolygonSetup& setup = c.setup;
    ExactArgs a;
    a.dst = dst;
    a.stride = stride;
    a.count = s.count;
    a.texels = c.tex.texels;
    a.width = c.tex.width;
    a.height = c.tex.height;
    a.clamp = c.tex.wrap == Wrap::Clamp;
    a.reserved = 0;
    a.x = centre_x(setup, s.x);
    a.y = centre_y(setup, s.y);
    a.step_x = c.axis == Axis::Rows ? double(SUBPIXEL_ONE) : 0.0;
    a.step_y = c.axis == Axis::Rows ? 0.0 : double(SUBPIXEL_ONE);
    const Plane* planes[3] = {&setup.q, &setup.pu, &setup.pv};
    double* out[3] = {a.q, a.pu, a.pv};
    for (int k = 0; k < 3; ++k) {
        out[k][0] = planes[k]->a0;
        out[k][1] = planes[k]->gx;
        out[k][2] = planes[k]->gy;
    }
    c.loop(&a);
}

// persp-subdiv-N: exact u, v (the reference's perspective divide, unfloored) at the span's first
// pixel centre, every N pixels after it and at its last pixel; 16.16 steps between them, rounded
// to nearest (the divisor is the pixel count between the exact points, so the last pixel of each
// piece lands on the exact value). Repeat: both ends of a piece reduced by the same whole number of
// periods, so the piece never straddles a wrap. Every texel read goes through texel().
template <int N>
void subdiv_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride) {
    const PolygonSetup& setup = c.setup;
    const bool rows = c.axis == Axis::Rows;
    double x = centre_x(setup, s.x), y = centre_y(setup, s.y);
    auto exact_at = [&](int32_t k, double* u, double* v) {
        double px = rows ? x + double(k) * SUBPIXEL_ONE : x, py = rows ? y : y + double(k) * SUBPIXEL_ONE;
        double q = setup.q.at(px, py);
        *u = setup.pu.at(px, py) / q;
        *v = setup.pv.at(px, py) / q;
    };
    auto period = [&](double t, int32_t size) {  // whole periods below t (repeat), else none
        return c.tex.wrap == Wrap::Repeat ? double(size) * double(floor_i64(t / double(size))) : 0.0;
    };
    double u0, v0;
    exact_at(0, &u0, &v0);
    for (int32_t k = 0; k < s.count;) {
        int32_t len = s.count - k > N ? N : s.count - k;  // pixels in this piece
        int32_t end = k + len < s.count ? k + len : s.count - 1;  // the next exact point
        double u1, v1;
        if (end != k) exact_at(end, &u1, &v1);
        else u1 = u0, v1 = v0;
        double pu = period(u0, c.tex.width), pv = period(v0, c.tex.height);
        Fixed16_16 u = Fixed16_16::from_double(u0 - pu), v = Fixed16_16::from_double(v0 - pv);
        int32_t divisor = end - k;
        Fixed16_16 du{}, dv{};
        if (divisor > 0) {
            du = Fixed16_16::from_double(((u1 - pu) - (u0 - pu)) / divisor);
            dv = Fixed16_16::from_double(((v1 - pv) - (v0 - pv)) / divisor);
        }
        for (int32_t n = 0; n < len; ++n) {
            *dst = texel(c.tex, u.floor_int(), v.floor_int());
            dst += stride;
            u = u + du;
            v = v + dv;
        }
        k += len;
        u0 = u1, v0 = v1;
    }
}

}  // namespace

// Each entry: name, family, origin; the promise in words; the promise checkable, what it needs,
// the walkers it takes, its span function or twin loop, its NASM loop, its own polygon driver.
const Mapper MAPPERS[] = {
    {"affine", "ours", "textbook affine interpolation",
     "exact coverage; u, v affine in screen space (16.16 steps): error grows with depth variation",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, affine_span, nullptr, nullptr},
    {"exact", "ours", "the reference's definition, per pixel",
     "equal to the reference: per-pixel perspective divide in double precision",
     EQUALS_REFERENCE, NEED_NOTHING, AXIS_BOTH, exact_span, exact_loop, MODEXLAB_ASM(exact_loop_asm)},
    {"persp-subdiv-4", "ours", "exact every 4 pixels, affine between",
     "perspective-correct at every 4th pixel and the last; 16.16 steps rounded to nearest; exact coverage; any texture",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, subdiv_span<4>, nullptr, nullptr},
    {"persp-subdiv-8", "ours", "exact every 8 pixels, affine between", "as persp-subdiv-4, every 8th pixel",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, subdiv_span<8>, nullptr, nullptr},
    {"persp-subdiv-16", "ours", "exact every 16 pixels, affine between", "as persp-subdiv-4, every 16th pixel",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, subdiv_span<16>, nullptr, nullptr},
    {"persp-subdiv-32", "ours", "exact every 32 pixels, affine between", "as persp-subdiv-4, every 32nd pixel",
     EXACT_COVERAGE_FLAT_ONE, NEED_NOTHING, AXIS_BOTH, subdiv_span<32>, nullptr, nullptr},
    {"fast-affine", "ours", "fatmap2's 8:16 core, unrolled with a computed entry, walking runs of rows in NASM",
     "exact coverage; u, v affine from the polygon's 16.16 planes at each span's first pixel centre; 256 x 256 repeating textures",
     EXACT_COVERAGE_FLAT_ONE, NEED_ALIGNED256, AXIS_ROWS, nullptr, fast_run_loop, MODEXLAB_ASM(fast_run_asm), fast::draw_rows},
    {"fast-columns", "ours", "the same core down Mode X columns, the map mask set once a column",
     "as fast-affine, by columns into Mode X planes",
     EXACT_COVERAGE_FLAT_ONE, NEED_ALIGNED256 | NEED_PLANAR_TARGET, AXIS_COLUMNS, nullptr, fast_column_loop,
     MODEXLAB_ASM(fast_column_asm), fast::draw_columns},
    {"xsharp-dda", "classic", "Abrash, Black Book listing 57.1 (X-Sharp 21, C)",
     "affine; whole-pixel vertices, X-Sharp's fill convention; half-step prestep, rounds to the nearest texel; cannot wrap",
     NO_GUARANTEE, NEED_BORDERED | NEED_INSIDE, AXIS_ROWS, nullptr, nullptr, nullptr, xsharp::draw_dda},
    {"xsharp-row-out", "classic", "Abrash, Black Book listing 57.2, inner loop 58.1 (X-Sharp 21, asm)",
     "the same pixels as xsharp-dda, written to Mode X planes with an OUT to the Map Mask per pixel",
     NO_GUARANTEE, NEED_BORDERED | NEED_INSIDE | NEED_PLANAR_TARGET | NEED_VGA_FOR_ASM, AXIS_ROWS, nullptr, xsharp_row_loop,
     MODEXLAB_ASM(xsharp_row_asm), xsharp::draw_row_out},
    {"xsharp-column", "classic", "Abrash, Black Book listing 58.4, as X-Sharp 22 shipped it",
     "affine; columns with X-Sharp's fill convention; the Y fraction keeps 15 bits (a texel row off at about 2 pixels in 10000)",
     NO_GUARANTEE, NEED_BORDERED | NEED_INSIDE | NEED_PLANAR_TARGET, AXIS_COLUMNS, nullptr, xsharp_column_loop,
     MODEXLAB_ASM(xsharp_column_asm), xsharp::draw_column},
    {"hecker-steptable", "classic", "Hecker, Game Developer 1995-96, parts III-V (SUBAFXFL setup, part V listing 2 loop)",
     "perspective-correct every 8 pixels, affine between; 28.4 vertices, top-left fill; rounding modifiers from du/dx; cannot wrap",
     NO_GUARANTEE, NEED_BORDERED | NEED_INSIDE, AXIS_ROWS, nullptr, hecker_loop, MODEXLAB_ASM(hecker_loop_asm), hecker::draw},
    {"fatmap-256", "classic", "Byggmastar, fatmap.txt (1996): the constant-delta setup and the 5-tick loop",
     "affine; whole-pixel vertices, x truncated, no prestep; 8-bit fractions (\"shaky\"); 256 x 256 only, wraps",
     NO_GUARANTEE, NEED_ALIGNED256, AXIS_ROWS, nullptr, fatmap_loop, MODEXLAB_ASM(fatmap_loop_asm), fatmap::draw_256},
    {"fatmap-256-16", "classic", "Byggmastar, fatmap.txt setup with fatmap2.txt's 8:16 loop (Simmons)",
     "as fatmap-256 with 16-bit fractions in the loop",
     NO_GUARANTEE, NEED_ALIGNED256, AXIS_ROWS, nullptr, fatmap16_loop, MODEXLAB_ASM(fatmap16_loop_asm), fatmap::draw_256},
    {"fatmap-lut", "classic", "Byggmastar, fatmap.txt section 13: the table-lookup loop",
     "affine; every scanline starts at the table's first entry: its start fractions dropped, up to a texel off on each axis and drifting; 256 x 256 only, cannot wrap",
     NO_GUARANTEE, NEED_ALIGNED256 | NEED_INSIDE, AXIS_ROWS, nullptr, fatmap_lut_loop, MODEXLAB_ASM(fatmap_lut_loop_asm),
     fatmap::draw_lut},
    {"quake-subdiv16", "classic", "id Software, WinQuake d_scan.c / d_draw16.s (1996-99)",
     "perspective-correct every 16 pixels and at each span's last pixel, affine between (steps floored); s, t clamped into the texture; exact coverage (our walker)",
     EXACT_COVERAGE, NEED_INSIDE, AXIS_ROWS, nullptr, quake_span_loop, MODEXLAB_ASM(quake_span_asm), quake::draw16},
    {"quake-subdiv8", "classic", "id Software, WinQuake d_scan.c D_DrawSpans8 / d_draw.s",
     "as quake-subdiv16 with 8-pixel segments",
     EXACT_COVERAGE, NEED_INSIDE, AXIS_ROWS, nullptr, quake_span_loop, MODEXLAB_ASM(quake_span_asm), quake::draw8},
};
const int MAPPER_COUNT = sizeof(MAPPERS) / sizeof(MAPPERS[0]);

const Mapper* find_mapper(lib::StrView name) {
    for (int i = 0; i < MAPPER_COUNT; ++i)
        if (name.equals(MAPPERS[i].name)) return &MAPPERS[i];
    return nullptr;
}

}  // namespace raster
