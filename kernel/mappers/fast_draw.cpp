// fast-affine, fast-table, fast-columns and fast-table-columns: the polygon drivers and the bound
// (docs/mappers.md). The loops' twins and checks: fast.cpp; a frame's triangle set up in one call:
// fast_triangle.cpp.
#include "kernel/mappers/fast.h"

#include "kernel/core/bound.h"
#include "kernel/core/envelope.h"
#include "kernel/core/footprint.h"
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
