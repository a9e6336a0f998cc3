// fast-affine and fast-columns: our fastest affine mappers for repeating textures with power-of-two
// sides up to 256 (read through the tiled 64 KiB block), each its own polygon driver
// (docs/mappers.md); the twins and the loops' checks.
#include "kernel/mappers/fast.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/bound.h"
#include "kernel/core/envelope.h"
#include "kernel/core/footprint.h"
#include "kernel/core/selftest.h"
#include "kernel/core/spanline.h"
#include "kernel/core/spread.h"

namespace raster::fast {

namespace {

// A polygon's u and v in 16.16 at pixel (x, y): origin + x * dx + y * dy, wrapping.
struct Planes {
    uint32_t u0, v0, udx, udy, vdx, vdy;
    explicit Planes(const PolygonSetup& s)
        : u0(uint32_t(s.u_fx.value(0, 0))), v0(uint32_t(s.v_fx.value(0, 0))), udx(uint32_t(s.u_fx.dx)),
          udy(uint32_t(s.u_fx.dy)), vdx(uint32_t(s.v_fx.dx)), vdy(uint32_t(s.v_fx.dy)) {}
    uint32_t u(int32_t x, int32_t y) const { return u0 + uint32_t(x) * udx + uint32_t(y) * udy; }
    uint32_t v(int32_t x, int32_t y) const { return v0 + uint32_t(x) * vdx + uint32_t(y) * vdy; }
};

// The range of the polygon's 16.16 u and v (t = 0, 1) over the pixels of the clip it covers, each
// widened by `extra` texels: at the polygon's corners, where the planes take their extremes over it,
// each evaluated within 4 eps of its terms, the 16.16 value at a pixel of the clip within
// (1 + |x - x0| + |y - y0|) 2^-17 of the plane (largest at a corner of the clip). NaN where a corner's
// value is (lo and hi then fail every compare).
void plane_ranges(const PolygonSetup& s, const ClipRect& clip, double extra, double lo[2], double hi[2]) {
    constexpr double EPS = 2.220446049250313e-16;
    const double x0 = double(s.u_fx.x0), y0 = double(s.u_fx.y0);
    const double reach = larger(magnitude(double(clip.x0) - x0), magnitude(double(clip.x1 - 1) - x0)) +
                         larger(magnitude(double(clip.y0) - y0), magnitude(double(clip.y1 - 1) - y0));
    const double rounding = (1 + reach) * HALF_ULP_16_16 * (1 + 1e-9) + extra;
    const Plane* planes[2] = {&s.u, &s.v};
    for (int t = 0; t < 2; ++t) {
        const Plane& p = *planes[t];
        for (int i = 0; i < s.edge_count; ++i) {
            const double x = double(s.edges[i].px - s.ref_x), y = double(s.edges[i].py - s.ref_y);
            const double at = p.at(x, y), off = rounding + 4 * EPS * (magnitude(p.a0) + magnitude(p.gx * x) + magnitude(p.gy * y));
            const double l = at - off, h = at + off;
            if (!(l == l && h == h)) {  // (NaN from then on)
                lo[t] = hi[t] = l + h;
                break;
            }
            if (i == 0 || l < lo[t]) lo[t] = l;
            if (i == 0 || h > hi[t]) hi[t] = h;
        }
    }
}

// Whether the texture reads on the polygon as the tiled block does (NEED_TILED256_OR_INSIDE): a
// repeating texture always; a clamped one where the polygon's affine u and v lie inside it at every
// pixel it covers, a coordinate `extra` texels further included (fast-table's offsets), with their
// 16.16 rounding (plane_ranges). There the block's texel (u mod 256, v mod 256) is the texture's (u,
// v), clamped or not; so is the doubled copy's.
// (Out of line: the drivers ask it only of a clamped texture, one compare a polygon otherwise.)
[[gnu::noinline]] bool reads_inside(const PolygonSetup& s, const Texture& tex, const ClipRect& clip, double extra) {
    if (tex.wrap == Wrap::Repeat) return true;
    double lo[2], hi[2];
    plane_ranges(s, clip, extra, lo, hi);
    return lo[0] >= 0 && hi[0] < double(tex.width) && lo[1] >= 0 && hi[1] < double(tex.height);
}

}  // namespace

// fast-affine on a doubled copy: the corner of the window of the copy that its texel pointer walks
// on the polygon without wrapping, as 16.16 values to take from u and v (their wholes then the
// texel's column and row in the copy). With [f, g] the floors of u over the pixels (plane_ranges)
// and a the largest multiple of the width with a - DOUBLED_LEAD <= f, the window fits where
// g < a + 2 width + DOUBLED_LEAD: always where g - f <= width + 2 DOUBLED_LEAD, and on a face that
// maps the texture once even where its affine planes overshoot at a corner (docs/bounds.md,
// "fast-affine and fast-columns on the doubled copy"). The same for v. False where the polygon spans
// more (fast-affine then reads the texture by masks), or its range is not finite within int32.
bool doubled_window(const PolygonSetup& s, const Texture& tex, const ClipRect& clip, uint32_t* u_base, uint32_t* v_base) {
    double lo[2], hi[2];
    plane_ranges(s, clip, 0, lo, hi);
    const int32_t sides[2] = {tex.width, tex.height};
    uint32_t bases[2];
    for (int t = 0; t < 2; ++t) {
        if (!(lo[t] > -SMALL_FLOOR && hi[t] < SMALL_FLOOR)) return false;
        const int32_t f = floor_small(lo[t]), g = floor_small(hi[t]);
        const int32_t a = (f + DOUBLED_LEAD) & -sides[t];  // (a power of two: the multiple at or below)
        if (int64_t(g) - a >= 2 * sides[t] + DOUBLED_LEAD) return false;
        bases[t] = uint32_t(a - DOUBLED_LEAD) << 16;
    }
    *u_base = bases[0], *v_base = bases[1];  // (only where it fits: the caller's 0 otherwise)
    return true;
}

namespace {

// The run loop's `inside`: whether the box lies within the clip's columns (a pixel whose centre lies
// in the box [min_x, max_x] lies in [x0, x1) where the box does; the box, within setup's range, and
// the clip's sides in subpixels within 32 bits).
inline int32_t inside_columns(const PolygonSetup& s, const ClipRect& clip) {
    constexpr int32_t ONE = int32_t(SUBPIXEL_ONE);
    return int32_t(s.min_x) >= clip.x0 * ONE && int32_t(s.max_x) <= clip.x1 * ONE;
}

// The polygon's setup (affine planes): the one auto made already, else set up here into `own`.
const PolygonSetup* set_up(const DrawContext& c, const Vertex* vertices, int count, PolygonSetup* own, SetupStatus* status) {
    *status = SetupStatus::Ok;
    if (c.setup) return c.setup;
    *status = setup_polygon(vertices, count, own, PLANES_AFFINE, c.input);
    return own;
}

}  // namespace

namespace {

// The triangle's set-up in one call (fast_triangle's, or its NASM routine's where built in), and
// the same from the rows on (fast_triangle_runs').
inline TriangleTaken set_up_triangle(FastTriangleArgs* t) {
#if defined(MODEXLAB_ASM_LOOPS)
    return fast_triangle_asm(t);
#else
    return fast_triangle(t);
#endif
}
inline TriangleTaken walk_triangle(FastTriangleArgs* t) {
#if defined(MODEXLAB_ASM_LOOPS)
    return fast_triangle_runs_asm(t);
#else
    return fast_triangle_runs(t);
#endif
}
inline TriangleTaken set_up_enveloped(FastTriangleArgs* t) {
#if defined(MODEXLAB_ASM_LOOPS)
    return fast_triangle_enveloped_asm(t);
#else
    return fast_triangle_enveloped(t);
#endif
}

// A run's block drawn (the run loop counts what it draws): by the context's loop, or where
// fast-affine's polygon spans more of a doubled copy than its window (FastRunArgs::doubled 2) by
// fast_run_loop_wrapping (DOUBLED: only fast-affine's driver on a doubled copy asks; that call out
// of line, as cold).
[[gnu::noinline, gnu::cold]] void run_wrapping(const DrawContext& c, const FastRunArgs& a) {
    emit(c.stats->probe, c.stats, 0, 0, [&] { fast_run_loop_wrapping(a, c.tex); });
}
// The next call's lines for a run loop (FastRunArgs' rows, FastColumnRunArgs' columns): the walker's
// next run and the one right after it where one follows at once (a triangle's two), or a line with
// a vertex on its centre (two live bounds on a side) as a run of one between the constant bounds
// lone[0] and lone[1]; its first line into *line; false when the walk is done.
template <Axis AXIS, typename Args>
[[gnu::always_inline]] inline bool next_runs(EdgeWalker& walker, Args& a, int32_t* line, EdgeBound lone[2]) {
    a.lines = walker.run(line, &a.lower, &a.upper);
    a.next_lines = 0;
    if (a.lines > 0) {
        walker.skip(a.lines);
        int32_t next_line;  // (line + a.lines: runs are contiguous)
        a.next_lines = walker.run(&next_line, &a.next_lower, &a.next_upper);
        walker.skip(a.next_lines);
        return true;
    }
    Span span;
    if (!walker.next(&span)) return false;
    const int32_t across = AXIS == Axis::Rows ? span.x : span.y;
    lone[0] = EdgeBound::constant(across);
    lone[1] = EdgeBound::constant(across + span.count - 1);
    a.lower = &lone[0], a.upper = &lone[1];
    a.lines = 1;
    *line = AXIS == Axis::Rows ? span.y : span.x;
    return true;
}

template <bool DOUBLED>
[[gnu::always_inline]] inline void run(const DrawContext& c, const FastRunArgs& a) {
    if (DOUBLED && a.source == BY_MASKS) run_wrapping(c, a);
    else emit(c, &a, 0, 0);
}

// Rows go by runs (docs/mappers.md, "fast-affine, fast-columns"): a run's rows have one live bound a
// side, so the run loop walks them itself, two runs a call where the second follows at once. A
// frame's uncut triangle is set up with its runs and the loop's block in one call (set_up_triangle,
// or with auto's envelope set_up_enveloped, which checks it), any other triangle's after its setup
// (walk_triangle; the envelope checked here); any other polygon, and a triangle those leave, by
// setup_polygon and the walker. With an offset table (fast-table), the table for the polygon's
// longest span is built once, after the walk's set-up (what the setup phase counts).
// DOUBLED: fast-affine on a texture's doubled copy; ENVELOPED: its driver for auto's envelope
template <bool TABLE, bool DOUBLED = false, bool ENVELOPED = false>
[[gnu::always_inline]] inline SetupStatus draw_runs(const DrawContext& c, const Vertex* vertices, int count) {
    FastRunArgs a;
    PolygonSetup own;
    FastTriangleArgs t;  // (the chains' room, and its outputs written by the call)
    t.in = vertices, t.setup = &own, t.run = &a, t.target = &c.target;
    TriangleTaken taken = TRIANGLE_TO_SETUP;  // set_up_triangle's or walk_triangle's answer
    if constexpr (ENVELOPED) {
        t.envelope = c.envelope;
        if (count == 3 && !c.setup && c.input == Input::InRange && (taken = set_up_enveloped(&t)) == TRIANGLE_OUTSIDE_ENVELOPE)
            return SetupStatus::Unproven;
    } else if (count == 3 && !c.setup && c.input == Input::InRange) {
        taken = set_up_triangle(&t);
    }
    SetupStatus status = SetupStatus::Ok;
    const PolygonSetup& s = taken != TRIANGLE_TO_SETUP ? own : *set_up(c, vertices, count, &own, &status);
    if (status != SetupStatus::Ok) return status;
    if (ENVELOPED && taken == TRIANGLE_TO_SETUP && !within_envelope(s, *c.envelope)) return SetupStatus::Unproven;
    if (taken == TRIANGLE_TO_SETUP && s.edge_count == 3) {  // a triangle set up already (auto's), or by setup_polygon
        t.setup = const_cast<PolygonSetup*>(&s);  // (read only)
        taken = walk_triangle(&t);
    }
    if (c.tex.wrap == Wrap::Clamp && !reads_inside(s, c.tex, c.target.clip, TABLE ? 1 : 0)) return SetupStatus::Unsupported;
    uint32_t u_base = 0, v_base = 0;  // fast-affine on a doubled copy: its window's corner, from u and v
    int32_t table[TABLE ? TABLE_LIMIT : 1];
    int32_t table_x = 0;  // fast-table: the pixel its offsets start at, at or left of every span's first
    if constexpr (TABLE) {
        // from the box's first pixel (a pixel whose centre lies at or right of min_x is at or right
        // of floor(min_x)) inside the clip to its last (at most floor(max_x)) inside it
        const int32_t box_lo = int32_t(s.min_x >> SUBPIXEL_BITS), box_hi = int32_t(s.max_x >> SUBPIXEL_BITS);  // (setup's range: 32 bits)
        table_x = box_lo > c.target.clip.x0 ? box_lo : c.target.clip.x0;
        const int32_t last = box_hi < c.target.clip.x1 - 1 ? box_hi : c.target.clip.x1 - 1;
        if (last >= TABLE_LIMIT) return SetupStatus::Unsupported;  // (a target wider than any screen: never here)
        const TableBlock block = table_block(c.tex);
        if (last >= table_x) build_offset_table(s.u_fx.dx, s.v_fx.dx, last - table_x + 1, table + table_x, block);
        a.table = table;
        a.texture = block.block, a.u_mask = block.u_mask, a.v_mask = block.v_mask, a.block_pitch = block.pitch;
    } else {
        a.texture = c.tex.aligned256;
        a.source = TILED_BLOCK;
        if constexpr (DOUBLED) {
            if (doubled_window(s, c.tex, c.target.clip, &u_base, &v_base)) {
                a.texture = c.tex.doubled, a.block_pitch = doubled_pitch(c.tex.width), a.source = DOUBLED_COPY;
            } else {
                a.source = BY_MASKS;
            }
        }
    }
    uint32_t drawn[2] = {0, 0};  // spans, pixels
    a.tally = drawn;
    if (taken == TRIANGLE_RUNS) {
        setup_done(c);
        if (a.lines > 0) {
            if constexpr (TABLE) {  // u and v at the table's first pixel, not at pixel 0
                a.u_16_16 += uint32_t(table_x) * uint32_t(a.du_16_16);
                a.v_16_16 += uint32_t(table_x) * uint32_t(a.dv_16_16);
            } else if constexpr (DOUBLED) {
                a.u_16_16 -= u_base;
                a.v_16_16 -= v_base;
            }
            run<DOUBLED>(c, a);
        }
    } else {
        EdgeWalker walker(s, EdgeWalker::Along<Axis::Rows>{}, c.target.clip);
        const Planes p(s);
        setup_done(c);
        a.pitch = c.target.pitch;
        a.clip_lo = walker.minor_lo();
        a.clip_hi = walker.minor_hi();
        a.u_row_16_16 = p.udy;
        a.v_row_16_16 = p.vdy;
        a.du_16_16 = int32_t(p.udx);
        a.dv_16_16 = int32_t(p.vdx);
        a.inside = inside_columns(s, c.target.clip);
        int32_t line;
        EdgeBound lone[2];
        while (next_runs<Axis::Rows>(walker, a, &line, lone)) {
            a.row = c.target.base + line * c.target.pitch;
            a.u_16_16 = p.u(table_x, line) - u_base;  // (fast-affine: at pixel 0)
            a.v_16_16 = p.v(table_x, line) - v_base;
            run<DOUBLED>(c, a);
        }
    }
    tally(c.stats, drawn[0], drawn[1]);
    return SetupStatus::Ok;
}

}  // namespace

namespace {

// fast-affine on a texture's doubled copy, its own instantiation (out of line: the tiled block's
// triangles pay one compare for it)
template <bool ENVELOPED>
[[gnu::noinline]] SetupStatus draw_rows_doubled(const DrawContext& c, const Vertex* vertices, int count) {
    return draw_runs<false, true, ENVELOPED>(c, vertices, count);
}

}  // namespace

SetupStatus draw_rows(const DrawContext& c, const Vertex* vertices, int count) {
    if (!c.tex.aligned256) [[unlikely]] return draw_rows_doubled<false>(c, vertices, count);  // (a side above 256: the doubled copy)
    return draw_runs<false>(c, vertices, count);
}
SetupStatus draw_rows_enveloped(const DrawContext& c, const Vertex* vertices, int count) {
    if (!c.tex.aligned256) [[unlikely]] return draw_rows_doubled<true>(c, vertices, count);
    return draw_runs<false, false, true>(c, vertices, count);
}
SetupStatus draw_table_rows(const DrawContext& c, const Vertex* vertices, int count) { return draw_runs<true>(c, vertices, count); }

namespace {

// Columns: fast-columns by runs of columns (fast_column_run: on a doubled copy from its window's
// corner; where the polygon spans more than a window, a column at a time by wrapping_pixels), or
// fast-table-columns a column a call (the map mask set once a column), fast_table_column_loop
// from its first texel in the doubled copy through the polygon's offset table along y, built once
// for its tallest column.
// DOUBLED: fast-columns on a doubled copy (fast-table-columns: always); ENVELOPED: its driver for auto's envelope
template <bool TABLE, bool DOUBLED = false, bool ENVELOPED = false>
[[gnu::always_inline]] inline SetupStatus draw_column_spans(const DrawContext& c, const Vertex* vertices, int count) {
    PolygonSetup own;
    SetupStatus status;
    const PolygonSetup& s = *set_up(c, vertices, count, &own, &status);
    if (status != SetupStatus::Ok) return status;
    if (ENVELOPED && !within_envelope(s, *c.envelope)) return SetupStatus::Unproven;
    if (c.tex.wrap == Wrap::Clamp && !reads_inside(s, c.tex, c.target.clip, TABLE ? 1 : 0)) return SetupStatus::Unsupported;
    uint32_t u_base = 0, v_base = 0;  // fast-columns on a doubled copy: its window's corner
    const bool wrapping = !TABLE && DOUBLED && !doubled_window(s, c.tex, c.target.clip, &u_base, &v_base);
    EdgeWalker walker(s, EdgeWalker::Along<Axis::Columns>{}, c.target.clip);
    const Planes p(s);
    int32_t table[TABLE ? TABLE_LIMIT : 1];
    const TableBlock block = TABLE ? table_block(c.tex) : TableBlock{};  // (fast-table-columns')
    if constexpr (TABLE) {
        const int32_t height = c.target.clip.y1 - c.target.clip.y0;
        const int32_t box = int32_t((s.max_y - s.min_y) >> SUBPIXEL_BITS) + 2;
        build_offset_table(int32_t(p.udy), int32_t(p.vdy), box < height ? box : height, table, block);
    }
    setup_done(c);
    if constexpr (!TABLE) {
        if (!wrapping) {
            // fast-columns: by runs of columns, each run walked and drawn by one call of the loop
            // (fast_column_run), two runs a call where the second follows at once; a column with a
            // vertex on its centre (two live bounds on a side) as a run of one between constant
            // bounds
            FastColumnRunArgs r;
            uint32_t drawn[2] = {0, 0};  // columns, pixels
            r.target = &c.target;
            r.clip_lo = walker.minor_lo(), r.clip_hi = walker.minor_hi();
            r.texture = DOUBLED ? c.tex.doubled : c.tex.aligned256;
            r.block_pitch = DOUBLED ? doubled_pitch(c.tex.width) : 0;
            r.u_column_16_16 = p.udx, r.v_column_16_16 = p.vdx;
            r.du_16_16 = int32_t(p.udy), r.dv_16_16 = int32_t(p.vdy);
            r.tally = drawn;
            EdgeBound lone[2];
            while (next_runs<Axis::Columns>(walker, r, &r.x, lone)) {
                r.u_16_16 = p.u(r.x, 0) - u_base, r.v_16_16 = p.v(r.x, 0) - v_base;
                emit(c, &r, 0, 0);
            }
            tally(c.stats, drawn[0], drawn[1]);
            return SetupStatus::Ok;
        }
    }
    // fast-table-columns, and fast-columns' polygons that span more of a doubled copy than its
    // window: a column a call
    FastTableColumnArgs a;
    a.table = table;
    uint32_t spans = 0, pixels = 0;
    Span span;
    while (walker.next(&span)) {
        int32_t stride;
        uint8_t* dst = span_start(c.target, Axis::Columns, span, &stride);
        const uint32_t u = p.u(span.x, span.y), v = p.v(span.x, span.y);
        // (counted once for the polygon)
        if constexpr (TABLE) {
            a.dst = dst;
            a.count = span.count;
            a.source = block.at(u, v);
            emit(c, &a, 0, 0);
        } else {
            emit(c.stats->probe, c.stats, 0, 0,
                 [&] { wrapping_pixels(c.tex, int32_t(p.udy), int32_t(p.vdy), u, v, dst, span.count, MODEX_ROW_BYTES); });
        }
        ++spans;
        pixels += uint32_t(span.count);
    }
    tally(c.stats, spans, pixels);
    return SetupStatus::Ok;
}

}  // namespace

SetupStatus draw_columns(const DrawContext& c, const Vertex* vertices, int count) {
    return !c.tex.aligned256 ? draw_column_spans<false, true>(c, vertices, count) : draw_column_spans<false>(c, vertices, count);
}
SetupStatus draw_columns_enveloped(const DrawContext& c, const Vertex* vertices, int count) {
    return !c.tex.aligned256 ? draw_column_spans<false, true, true>(c, vertices, count) : draw_column_spans<false, false, true>(c, vertices, count);
}
SetupStatus draw_table_columns(const DrawContext& c, const Vertex* vertices, int count) { return draw_column_spans<true>(c, vertices, count); }

namespace {

// The bound (docs/bounds.md): the three mappers read the polygon's 16.16 planes,
// the affine planes rounded at the anchor pixel and in each gradient (half a unit each), so at pixel
// (x, y) they are within (1 + |x - x0| + |y - y0|) / 2^17 of the affine planes; those lines'
// deviation from the exact mapping as for affine. 256 wraps harmlessly in 16.16, but a gradient
// of 32768 texels a pixel or more saturates: no bound then. fast-table reads each span's lines moved
// by at most half a texel (TABLE_START, its start's fraction): a coordinate EXTRA = ½ further, and
// its clamped polygons a texel inside the texture.
template <bool TABLE>
ErrorBound planes_bound(const BoundContext& c, const Vertex* vertices, int count) {
    constexpr double EXTRA = TABLE ? 0.5 : 0.0;
    if (!mapper_accepts(c.mapper, c.tex)) return ErrorBound{false, true, 0};
    if (c.tex.wrap == Wrap::Clamp) {  // what the drivers refuse (reads_inside), it does not draw
        PolygonSetup own;
        const PolygonSetup* s = c.prepared && c.prepared->status == SetupStatus::Ok ? &c.prepared->setup : &own;
        if ((s != &own || setup_polygon(vertices, count, &own, PLANES_AFFINE) == SetupStatus::Ok) && !reads_inside(*s, c.tex, c.clip, TABLE ? 1 : 0))
            return ErrorBound{false, true, 0};
    }
    auto whole = [&](PolygonSpread& p, const PolygonSetup& s) {
        return planes_fit_16_16(s) ? spread_planes_bound(p, s, (1 + p.reach) * HALF_ULP_16_16 + EXTRA, c.budget) : NO_BOUND;
    };
    return bound_by_spans(c, vertices, count, PLANES_ALL, whole, [&](const Span& span, const PolygonSetup& s, bool* fits) {
        SpanLine l = span_line(s, c.axis, span);
        const double last = double(span.count - 1);
        double a[2], step[2];
        affine_lines(s, c.axis, span, a, step);
        *fits = *fits && planes_fit_16_16(s);
        // |x - x0| + |y - y0| is convex along the span: largest at a piece's ends
        auto reach = [&](double k) {
            int32_t px = span.x + (c.axis == Axis::Rows ? int32_t(k) : 0), py = span.y + (c.axis == Axis::Rows ? 0 : int32_t(k));
            return double(px > s.u_fx.x0 ? px - s.u_fx.x0 : s.u_fx.x0 - px) + double(py > s.u_fx.y0 ? py - s.u_fx.y0 : s.u_fx.y0 - py);
        };
        auto piece = [&](double k0, double k1) {
            return lines_bound(l, a, step, k0, k1, (1 + larger(reach(k0), reach(k1))) * HALF_ULP_16_16 + EXTRA);
        };
        return span_bound(c, 0, last, BOUND_PIECE, piece, piece);
    });
}

}  // namespace

ErrorBound bound(const BoundContext& c, const Vertex* vertices, int count) { return planes_bound<false>(c, vertices, count); }
ErrorBound table_bound(const BoundContext& c, const Vertex* vertices, int count) { return planes_bound<true>(c, vertices, count); }

}  // namespace raster::fast

namespace raster {

namespace {

// The lines of a run, and of the next one where there is one, as the NASM run loops walk them
// (rows: FastRunArgs; columns: FastColumnRunArgs): each line's two bounds stepped in place and its
// span clipped and tallied; line(lo, hi) for every line in order, lo > hi where it is empty.
template <typename Args, typename Line>
void walk_lines(const Args& a, Line&& line) {
    if (a.lines <= 0) return;
    EdgeBound *lower = a.lower, *upper = a.upper;
    for (int32_t lines = a.lines, part = 0; part < 2; ++part, lines = a.next_lines, lower = a.next_lower, upper = a.next_upper)
        for (int32_t n = 0; n < lines; ++n) {
            const int32_t lo = lower->q > a.clip_lo ? lower->q : a.clip_lo, hi = upper->q < a.clip_hi ? upper->q : a.clip_hi;
            lower->step();
            upper->step();
            if (lo <= hi) a.tally[0] += 1, a.tally[1] += uint32_t(hi - lo + 1);
            line(lo, hi);
        }
}

// The rows of a run, and of the next one where there is one, as both run loops walk them:
// span(row, lo, hi, u, v) draws pixels lo..hi of a non-empty row, u and v (16.16) the row's as
// FastRunArgs gives them.
template <typename Span>
void run_rows(const FastRunArgs& a, Span&& span) {
    uint8_t* row = a.row;
    uint32_t u = a.u_16_16, v = a.v_16_16;
    walk_lines(a, [&](int32_t lo, int32_t hi) {
        if (lo <= hi) span(row, lo, hi, u, v);
        row += a.pitch;
        u += a.u_row_16_16;
        v += a.v_row_16_16;
    });
}

}  // namespace

TriangleTaken fast_triangle(FastTriangleArgs* a) {
    if (setup_polygon_cpp(a->in, 3, a->setup, PLANES_AFFINE, Input::InRange) != SetupStatus::Ok) return TRIANGLE_TO_SETUP;
    return fast_triangle_runs(a);
}

TriangleTaken fast_triangle_enveloped(FastTriangleArgs* a) {
    if (setup_polygon_cpp(a->in, 3, a->setup, PLANES_AFFINE, Input::InRange) != SetupStatus::Ok) return TRIANGLE_TO_SETUP;
    if (!within_envelope(*a->setup, *a->envelope)) return TRIANGLE_OUTSIDE_ENVELOPE;
    return fast_triangle_runs(a);
}

TriangleTaken fast_triangle_runs(FastTriangleArgs* a) {
    const PolygonSetup& s = *a->setup;
    const Target& target = *a->target;
    TriangleRunsArgs t;
    t.setup = &s, t.clip_lo = target.clip.y0, t.clip_hi = target.clip.y1 - 1, t.lower = a->lower, t.upper = a->upper;
    if (!triangle_runs(&t)) return TRIANGLE_TO_WALKER;
    FastRunArgs& r = *a->run;
    r.lines = t.lines;
    if (t.lines == 0) return TRIANGLE_RUNS;
    r.lower = t.run_lower, r.upper = t.run_upper;
    r.next_lines = t.next_lines, r.next_lower = t.next_lower, r.next_upper = t.next_upper;
    r.pitch = target.pitch;
    r.clip_lo = target.clip.x0, r.clip_hi = target.clip.x1 - 1;
    r.row = target.base + t.line * target.pitch;
    r.u_16_16 = uint32_t(s.u_fx.value(0, t.line));
    r.v_16_16 = uint32_t(s.v_fx.value(0, t.line));
    r.u_row_16_16 = uint32_t(s.u_fx.dy), r.v_row_16_16 = uint32_t(s.v_fx.dy);
    r.du_16_16 = s.u_fx.dx, r.dv_16_16 = s.v_fx.dx;
    r.inside = fast::inside_columns(s, target.clip);
    return TRIANGLE_RUNS;
}

namespace {

// The NASM loops' texel pointer into a doubled copy (an offset here), stepped as they step it: the
// wholes of du and dv, and one more column or row on each fraction's carry; its pixels `stride`
// bytes apart from dst, from 16.16 u and v whose wholes are the column and row in the copy.
void doubled_pixels(const uint8_t* texture, int32_t pitch, int32_t du, int32_t dv, uint32_t u, uint32_t v, uint8_t* dst, int32_t count, int32_t stride) {
    const uint32_t p = uint32_t(pitch), du_fraction = uint32_t(du) << 16, dv_fraction = uint32_t(dv) << 16;
    const uint32_t step = uint32_t(dv >> 16) * p + uint32_t(du >> 16);
    uint32_t at = (v >> 16) * p + (u >> 16), u_fraction = u << 16, v_fraction = v << 16;
    for (int32_t n = 0; n < count; ++n, dst += stride) {
        *dst = texture[at];
        const uint32_t carry_v = v_fraction + dv_fraction < v_fraction, carry_u = u_fraction + du_fraction < u_fraction;
        v_fraction += dv_fraction;
        u_fraction += du_fraction;
        at += step + carry_v * p + carry_u;
    }
}

// The 8:16 core's pixels on the tiled block, (u whole & 255, v whole & 255), as doubled_pixels'.
void tiled_pixels(const uint8_t* block, int32_t du, int32_t dv, uint32_t u, uint32_t v, uint8_t* dst, int32_t count, int32_t stride) {
    for (int32_t n = 0; n < count; ++n, dst += stride) {
        *dst = texel256(block, u, v);
        u += uint32_t(du);
        v += uint32_t(dv);
    }
}

// run_rows' spans as runs of pixels: draw(dst, count, u, v), u and v at the span's first pixel.
template <typename Pixels>
void run_row_pixels(const FastRunArgs& a, Pixels&& draw) {
    run_rows(a, [&](uint8_t* row, int32_t lo, int32_t hi, uint32_t u, uint32_t v) {
        draw(row + lo, hi - lo + 1, u + uint32_t(lo) * uint32_t(a.du_16_16), v + uint32_t(lo) * uint32_t(a.dv_16_16));
    });
}

}  // namespace

void fast_run_loop(const void* raw) {
    const auto& a = *static_cast<const FastRunArgs*>(raw);
    run_row_pixels(a, [&](uint8_t* dst, int32_t count, uint32_t u, uint32_t v) {
        if (a.source == DOUBLED_COPY) doubled_pixels(a.texture, a.block_pitch, a.du_16_16, a.dv_16_16, u, v, dst, count, 1);
        else tiled_pixels(a.texture, a.du_16_16, a.dv_16_16, u, v, dst, count, 1);
    });
}

void wrapping_pixels(const Texture& tex, int32_t du, int32_t dv, uint32_t u, uint32_t v, uint8_t* dst, int32_t count, int32_t stride) {
    const TableBlock texture{tex.texels, uint32_t(tex.width - 1), uint32_t(tex.height - 1), tex.width};  // (the texture itself, by masks)
    for (int32_t n = 0; n < count; ++n, dst += stride) {
        *dst = *texture.at(u, v);
        u += uint32_t(du);
        v += uint32_t(dv);
    }
}

void fast_run_loop_wrapping(const FastRunArgs& a, const Texture& tex) {
    run_row_pixels(a, [&](uint8_t* dst, int32_t count, uint32_t u, uint32_t v) { wrapping_pixels(tex, a.du_16_16, a.dv_16_16, u, v, dst, count, 1); });
}

// 16.16 values modulo 2^32, whose wholes modulo a power of two up to 65536 are the floors' (2^32 is
// a multiple of 2^32 / 65536)
void build_offset_table(int32_t du_16_16, int32_t dv_16_16, int32_t length, int32_t* table, const TableBlock& block) {
    uint32_t u = TABLE_START, v = TABLE_START;
    for (int32_t k = 0; k < length; ++k) {
        table[k] = int32_t(((v >> 16) & block.v_mask) * uint32_t(block.pitch) + ((u >> 16) & block.u_mask));
        u += uint32_t(du_16_16);
        v += uint32_t(dv_16_16);
    }
}

void fast_table_loop(const void* raw) {
    const auto& a = *static_cast<const FastRunArgs*>(raw);
    const TableBlock block{a.texture, a.u_mask, a.v_mask, a.block_pitch};
    run_rows(a, [&](uint8_t* row, int32_t lo, int32_t hi, uint32_t u, uint32_t v) {
        const uint8_t* origin = block.at(u, v);  // the table's first pixel's texel
        for (int32_t x = lo; x <= hi; ++x) row[x] = origin[a.table[x]];
    });
}

void fast_table_column_loop(const void* raw) {
    const auto& a = *static_cast<const FastTableColumnArgs*>(raw);
    for (int32_t n = 0; n < a.count; ++n) a.dst[n * MODEX_ROW_BYTES] = a.source[a.table[n]];
}

void fast_column_run(const void* raw) {
    const auto& a = *static_cast<const FastColumnRunArgs*>(raw);
    const Target& t = *a.target;
    int32_t x = a.x;
    uint32_t u = a.u_16_16, v = a.v_16_16;
    walk_lines(a, [&](int32_t lo, int32_t hi) {
        if (lo <= hi) {
            if (t.select_plane) t.select_plane(t.ctx, x & 3);
            uint8_t* dst = t.base + (x & 3) * t.plane_bytes + lo * MODEX_ROW_BYTES + (x >> 2);
            const uint32_t su = u + uint32_t(lo) * uint32_t(a.du_16_16), sv = v + uint32_t(lo) * uint32_t(a.dv_16_16);  // at the first pixel
            if (a.block_pitch) doubled_pixels(a.texture, a.block_pitch, a.du_16_16, a.dv_16_16, su, sv, dst, hi - lo + 1, MODEX_ROW_BYTES);
            else tiled_pixels(a.texture, a.du_16_16, a.dv_16_16, su, sv, dst, hi - lo + 1, MODEX_ROW_BYTES);
        }
        ++x;
        u += a.u_column_16_16;
        v += a.v_column_16_16;
    });
}

namespace {

// fast_table_column_loop's block with the table it reads.
struct TableColumnCase {
    FastTableColumnArgs args;
    int32_t table[TABLE_LIMIT];
};

}  // namespace

template <>
void move_to_b(TableColumnCase& b, const TableColumnCase& a, const CheckBuffers& buf) {
    b.args.dst = buf.b + (a.args.dst - buf.a);
    b.args.table = b.table;
}

template <>
const void* check_block(const TableColumnCase& a) {
    return &a.args;
}

namespace {

// A doubled copy over the check's texels as a table block, of random power-of-two sides up to 1024
// (above256: one above 256, as fast-affine reads it) whose copy fits the buffer.
TableBlock random_doubled_block(Random& r, const CheckBuffers& buf, bool above256) {
    int32_t w, h;
    random_doubled_sides(r, &w, &h, above256);
    return TableBlock{buf.texels, uint32_t(w - 1), uint32_t(h - 1), doubled_pitch(w)};
}
// fast-affine's and fast-columns' texel pointer from the buffer's start, every start within it: wholes
// of u from 2300 to 4000 and of v from 150 to 300, u stepping by at most 4 texels a pixel or a row
// and v by a quarter, so over 330 pixels and 240 rows u stays within 20..6280 and v within 7..443:
// below 443 * 2064 + 6280 < 1 MiB (any fraction).
template <typename Args>
void random_doubled_uv(Random& r, Args& a) {
    a.u_16_16 = decltype(a.u_16_16)(uint32_t(r.range(2300, 3999)) << 16 | (r.next() & 0xFFFF));
    a.v_16_16 = decltype(a.v_16_16)(uint32_t(r.range(150, 299)) << 16 | (r.next() & 0xFFFF));
    a.du_16_16 = r.range(-0x40000, 0x40000);
    a.dv_16_16 = r.range(-0x4000, 0x4000);
}

}  // namespace

// Columns of 0 to 240 pixels from a random texel of a table block, the table of random steps.
LoopCheck check_fast_table_column(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<TableColumnCase>(m, other, seed, cases, buf, [&](Random& r, TableColumnCase& c) {
        FastTableColumnArgs& a = c.args;
        a.count = random_count(r, 0, 9, 240);
        const TableBlock block = random_doubled_block(r, buf, false);
        const uint32_t u = r.next(), v = r.next();
        a.source = block.at(u, v);
        const int32_t du = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        const int32_t dv = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        build_offset_table(du, dv, a.count, c.table, block);
        a.table = c.table;
        return place_span(buf, a, MODEX_ROW_BYTES);
    });
}

namespace {

// What a run loop updates, which must come out the same: its bounds and its tally.
struct RunState {
    EdgeBound lower, upper, next_lower, next_upper;
    uint32_t tally[2];
    // A run loop's block (FastRunArgs, FastColumnRunArgs) pointed at them, the tally cleared.
    template <typename Args>
    void attach(Args& a) {
        a.lower = &lower, a.upper = &upper, a.next_lower = &next_lower, a.next_upper = &next_upper;
        a.tally = tally;
        tally[0] = tally[1] = 0;
    }
    // The lines a run loop given `a` walks and the pixels it draws, from copies of the bounds (as
    // walk_lines walks them: the twins' walk).
    template <typename Args>
    uint32_t drawn(Args a, int32_t* lines) const {
        RunState copy = *this;
        copy.attach(a);
        int32_t walked = 0;
        walk_lines(a, [&](int32_t, int32_t) { ++walked; });
        *lines = walked;
        return copy.tally[1];
    }
    bool same(const RunState& o) const {
        auto same = [](const EdgeBound& x, const EdgeBound& y) { return x.q == y.q && x.r == y.r; };
        return same(lower, o.lower) && same(upper, o.upper) && same(next_lower, o.next_lower) && same(next_upper, o.next_upper) &&
               tally[0] == o.tally[0] && tally[1] == o.tally[1];
    }
};

// fast_run_loop's block (and fast_table_loop's) with what it updates and the offset table
// fast_table_loop reads.
struct RunCase : RunState {
    FastRunArgs args;
    int32_t table[TABLE_LIMIT];
};

}  // namespace

template <>
void move_to_b(RunCase& b, const RunCase& a, const CheckBuffers& buf) {
    b.args.row = buf.b + (a.args.row - buf.a);
    b.attach(b.args);
    b.args.table = b.table;
}

template <>
bool same_results(const RunCase& a, const RunCase& b) {
    return a.same(b);
}

template <>
const void* check_block(const RunCase& a) {
    return &a.args;
}

namespace {

// A random bound: q anywhere near the rows (often far outside the clip), steps of either sign,
// any remainder and divisor.
EdgeBound random_bound(Random& r, int32_t pitch) {
    EdgeBound b;
    b.first = b.last = 0;
    b.q = r.below(4) == 0 ? r.range(-100000, 100000) : r.range(-20, pitch + 20);
    b.dq = r.below(4) == 0 ? r.range(-400, 400) : r.range(-3, 3);
    b.d = r.below(4) == 0 ? 1 + r.next() % 0x80000000u : uint32_t(r.range(1, 4096));
    b.r = r.next() % b.d;
    b.dr = r.next() % b.d;
    return b;
}

}  // namespace

// fast_run_loop's and fast_table_loop's random cases: a run and the offset table of its steps.
LoopCheck check_fast_run(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<RunCase>(m, other, seed, cases, buf, [&](Random& r, RunCase& c) {
        FastRunArgs& a = c.args;
        // rows of up to 330 bytes; 240 of them fit the buffer with its guards
        a.pitch = r.below(2) ? 320 : r.range(1, 330);
        a.clip_lo = r.range(0, a.pitch - 1);
        a.clip_hi = r.below(8) == 0 ? a.clip_lo - 1 : r.range(a.clip_lo, a.pitch - 1);  // sometimes nothing
        // a third of the runs inside the clip (RUN_inside: its rows up to the first that leaves it)
        const bool inside = r.below(3) == 0 && a.clip_lo <= a.clip_hi;
        // a run's bounds and its rows, up to `most` (inside: up to the first row that leaves the clip)
        auto run = [&](EdgeBound& lower, EdgeBound& upper, int32_t most) {
            lower = random_bound(r, a.pitch);
            upper = random_bound(r, a.pitch);
            if (r.below(2)) upper.q = lower.q + r.range(0, a.pitch), upper.dq = lower.dq + r.range(-2, 2);  // a real-looking span
            if (!inside) return most;
            lower.q = r.range(a.clip_lo, a.clip_hi), lower.dq = r.range(-2, 2);
            upper.q = r.range(lower.q, a.clip_hi), upper.dq = lower.dq + r.range(-2, 2);
            EdgeBound lo = lower, hi = upper;
            int32_t n = 0;
            for (; n < most && (lo.q > hi.q || (lo.q >= a.clip_lo && hi.q <= a.clip_hi)); ++n) lo.step(), hi.step();
            return n;
        };
        a.lines = run(c.lower, c.upper, r.below(8) == 0 ? r.range(0, 3) : r.range(1, 240));
        // half of them with a next run right after (a polygon's second run in the same call), the
        // rows of both within 240; sometimes none said by 0 or less
        const int32_t room = 240 - (a.lines > 0 ? a.lines : 0);
        const int32_t most = r.below(4) == 0 || room < 1 ? r.range(-1, room < 3 ? room : 3) : r.range(1, room);
        a.next_lines = r.below(2) ? 0 : run(c.next_lower, c.next_upper, most);
        if (a.next_lines == 0) c.next_lower = c.next_upper = EdgeBound::constant(0);
        a.inside = inside ? 1 : 0;
        // the texture: fast-table's doubled copy (its pitch and masks), fast-affine's tiled block or a
        // third of the time a doubled copy
        const bool table = m.twin == fast_table_loop;
        a.source = table || r.below(3) == 0 ? DOUBLED_COPY : TILED_BLOCK;
        const TableBlock block = a.source == DOUBLED_COPY ? random_doubled_block(r, buf, !table) : TableBlock{check_aligned_texture(buf), 255, 255, 256};
        a.texture = block.block;
        a.u_mask = block.u_mask, a.v_mask = block.v_mask, a.block_pitch = block.pitch;
        a.u_16_16 = r.next();
        a.v_16_16 = r.next();
        a.u_row_16_16 = r.next();
        a.v_row_16_16 = r.next();
        a.du_16_16 = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        a.dv_16_16 = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        if (m.twin == fast_run_loop && a.source == DOUBLED_COPY) {
            random_doubled_uv(r, a);  // (its u and v at pixel 0 of the first row)
            a.u_row_16_16 = uint32_t(r.range(-0x40000, 0x40000));
            a.v_row_16_16 = uint32_t(r.range(-0x4000, 0x4000));
        }
        c.attach(a);
        // (fast-table: the offsets from a pixel at or left of clip_lo to the pitch's end)
        const int32_t table_x = r.range(0, a.clip_lo);
        build_offset_table(a.du_16_16, a.dv_16_16, a.pitch - table_x, c.table + table_x, block);
        a.table = c.table;
        a.row = buf.a + CHECK_GUARD_BYTES;
        int32_t lines;
        const uint32_t pixels = c.drawn(a, &lines);  // what the rows will draw
        return CheckWindow{0, CHECK_GUARD_BYTES + size_t(lines) * size_t(a.pitch) + CHECK_GUARD_BYTES, pixels};
    });
}


namespace {

// fast_column_run's block with its target and what it updates.
struct ColumnRunCase : RunState {
    FastColumnRunArgs args;
    Target target;
};

}  // namespace

template <>
void move_to_b(ColumnRunCase& b, const ColumnRunCase& a, const CheckBuffers& buf) {
    b.target.base = buf.b + (a.target.base - buf.a);
    b.args.target = &b.target;
    b.attach(b.args);
}

template <>
bool same_results(const ColumnRunCase& a, const ColumnRunCase& b) {
    return a.same(b);
}

template <>
const void* check_block(const ColumnRunCase& a) {
    return &a.args;
}

// Runs of columns into a planar target in the check's buffer (four planes of PLANE_BYTES between
// the guards; no plane selection: tests/asm/column_run_test.cpp calls a logged select_plane): one
// or two runs from a random column, bounds through and out of a random clip (and constant, as the
// driver's lone columns), steps of several texels; the tiled block, or a third of the time a
// doubled copy's pitch with u and v such that the walk stays in the texels (random_doubled_uv, the
// steps from column to column within a texel and a quarter).
LoopCheck check_fast_column_run(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<ColumnRunCase>(m, other, seed, cases, buf, [&](Random& r, ColumnRunCase& c) {
        FastColumnRunArgs& a = c.args;
        c.target = planar_target(buf.a + CHECK_GUARD_BYTES);
        a.clip_lo = r.range(0, SCREEN_HEIGHT - 1);
        a.clip_hi = r.below(8) == 0 ? a.clip_lo - 1 : r.range(a.clip_lo, SCREEN_HEIGHT - 1);  // sometimes nothing
        a.x = r.range(0, SCREEN_WIDTH - 1);
        const int32_t room = SCREEN_WIDTH - a.x;
        auto bound = [&] { return r.below(10) == 0 ? EdgeBound::constant(r.range(-20, SCREEN_HEIGHT + 20)) : random_bound(r, SCREEN_HEIGHT); };
        c.lower = bound(), c.upper = bound();
        if (r.below(2)) c.upper.q = c.lower.q + r.range(0, SCREEN_HEIGHT), c.upper.dq = c.lower.dq + r.range(-2, 2);  // a real-looking span
        c.next_lower = bound(), c.next_upper = bound();
        a.lines = r.below(8) == 0 ? r.range(0, 2) : r.range(1, room);
        a.next_lines = r.below(2) ? 0 : r.range(-1, room - (a.lines > 0 ? a.lines : 0));
        a.texture = check_aligned_texture(buf);
        a.block_pitch = 0;
        a.u_16_16 = r.next(), a.v_16_16 = r.next();
        a.u_column_16_16 = r.below(4) ? uint32_t(r.range(-0x40000, 0x40000)) : r.next();
        a.v_column_16_16 = r.below(4) ? uint32_t(r.range(-0x40000, 0x40000)) : r.next();
        a.du_16_16 = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        a.dv_16_16 = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        if (r.below(3) == 0) {
            int32_t w, h;
            random_doubled_sides(r, &w, &h);
            a.texture = buf.texels;
            a.block_pitch = doubled_pitch(w);
            random_doubled_uv(r, a);
            a.u_column_16_16 = uint32_t(r.range(-0x10000, 0x10000));
            a.v_column_16_16 = uint32_t(r.range(-0x4000, 0x4000));
        }
        a.target = &c.target;
        c.attach(a);
        int32_t lines;
        const uint32_t pixels = c.drawn(a, &lines);  // what the columns will draw
        return CheckWindow{0, CHECK_GUARD_BYTES + 4 * size_t(PLANE_BYTES) + CHECK_GUARD_BYTES, pixels};
    });
}

#if defined(MODEXLAB_OFFSETS)
// The block layouts of this family asm/fast.asm reads (core/asm_offsets.h); core's types' come
// from kernel/core (setup.cpp, walk.cpp, surface.cpp, envelope.cpp).
void fast_offsets() {
    ASM_FIELDS(TCOL, FastTableColumnArgs, dst, count, source, table)
    ASM_FIELDS(RUN, FastRunArgs, row, pitch, lines, clip_lo, clip_hi, lower, upper, next_lines, next_lower, next_upper, texture, u_16_16, v_16_16,
               u_row_16_16, v_row_16_16, du_16_16, dv_16_16, tally, table, inside, source, u_mask, v_mask, block_pitch)
    ASM_FIELDS(FTRI, FastTriangleArgs, in, setup, run, target, envelope, lower, upper)
    ASM_FIELDS(CRUN, FastColumnRunArgs, target, x, lines, clip_lo, clip_hi, lower, upper, next_lines, next_lower, next_upper, texture, block_pitch, u_16_16,
               v_16_16, u_column_16_16, v_column_16_16, du_16_16, dv_16_16, tally)
    ASM_CONSTANT(MODEX_ROW_BYTES, MODEX_ROW_BYTES);
    ASM_CONSTANT(SOURCE_TILED_BLOCK, TILED_BLOCK);
    ASM_CONSTANT(TRIANGLE_TO_SETUP, TRIANGLE_TO_SETUP);
    ASM_CONSTANT(TRIANGLE_RUNS, TRIANGLE_RUNS);
    ASM_CONSTANT(TRIANGLE_TO_WALKER, TRIANGLE_TO_WALKER);
    ASM_CONSTANT(TRIANGLE_OUTSIDE_ENVELOPE, TRIANGLE_OUTSIDE_ENVELOPE);
}
#endif

}  // namespace raster
