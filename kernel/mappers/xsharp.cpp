// xsharp-dda, xsharp-row-out and xsharp-column: X-Sharp's texture mappers (Black Book listings 57.1,
// 57.2/58.1, 58.4) with their flaws (docs/classics.md); the twins and the loops' checks.
#include "kernel/mappers/xsharp.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/bound.h"
#include "kernel/core/footprint.h"
#include "kernel/core/selftest.h"

#include "kernel/mappers/classic.h"

namespace raster::xsharp {

namespace {

using classic::counting_fraction;
using classic::fixed_div;
using classic::fixed_mul;
using classic::round_fixed;
using classic::split;
using classic::SplitStep;
using classic::Vertex16;

// X-Sharp's texel coordinates put texel centres at integers.
constexpr double TEXEL_OFFSET = -0.5;

// One edge of the destination polygon, stepped one line (row or column) at a time: the source
// position in 16.16, and the destination's other coordinate by an all-integer Bresenham stepper.
struct Edge {
    int direction;             // through the vertex list
    int remaining, current_end;
    int32_t source_x, source_y, step_x, step_y;
    int32_t dest, int_step, dest_direction, err, adj_up, adj_down;
};

struct Polygon {
    Vertex16 v[classic::MAX_VERTICES];
    int n;
    int max_vert;
    bool columns;  // scanning columns: the roles of x and y swap
};

int32_t along(const Vertex16& v, bool columns) { return columns ? v.x : v.y; }   // the scan direction
int32_t across(const Vertex16& v, bool columns) { return columns ? v.y : v.x; }  // within a line

// The polygon in X-Sharp's terms (whole-pixel vertices, texture coordinates shifted into the
// texture), refused unless monotone along the scan; its first and last vertex along the scan
// (DRAWTEXP.C's MinVert and MaxVert, the first of equals); shift: the whole periods added, where given.
SetupStatus prepare(const Texture& tex, const Vertex* vertices, int count, bool columns, Polygon* p, int* min_vert, double* shift = nullptr) {
    p->columns = columns;
    SetupStatus status = classic::convert(vertices, count, tex, TEXEL_OFFSET, p->v, &p->n, shift);
    if (status != SetupStatus::Ok) return status;
    if (!classic::monotone(p->v, p->n, columns)) return SetupStatus::NotConvex;
    int lo = 0, hi = 0;
    for (int i = 1; i < p->n; ++i) {
        if (along(p->v[i], columns) < along(p->v[lo], columns)) lo = i;
        if (along(p->v[i], columns) > along(p->v[hi], columns)) hi = i;
    }
    if (along(p->v[lo], columns) >= along(p->v[hi], columns)) return SetupStatus::Degenerate;
    *min_vert = lo;
    p->max_vert = hi;
    return SetupStatus::Ok;
}

// DRAWTEXP.C's SetUpEdge, rows (X-Sharp 21) or columns (X-Sharp 22). Returns false when the edge
// chain has reached the far vertex.
bool set_up_edge(Edge& e, int start, const Polygon& p) {
    for (;;) {
        if (start == p.max_vert) return false;
        int next = start + e.direction;
        if (next >= p.n) next = 0;
        else if (next < 0) next = p.n - 1;
        e.remaining = along(p.v[next], p.columns) - along(p.v[start], p.columns);
        if (e.remaining != 0) {
            int32_t length = e.remaining << 16;
            e.current_end = next;
            e.source_x = p.v[start].u_16_16;
            e.source_y = p.v[start].v_16_16;
            e.step_x = fixed_div(p.v[next].u_16_16 - e.source_x, length);
            e.step_y = fixed_div(p.v[next].v_16_16 - e.source_y, length);
            int32_t width = across(p.v[next], p.columns) - across(p.v[start], p.columns);
            if (!p.columns) {
                // rows: DestX = ceil of the true edge x, both directions
                e.dest = across(p.v[start], false);
                if (width < 0) {
                    e.dest_direction = -1;
                    width = -width;
                    e.err = 1 - e.remaining;
                    e.int_step = -(width / e.remaining);
                } else {
                    e.dest_direction = 1;
                    e.err = 0;
                    e.int_step = width / e.remaining;
                }
            } else {
                // columns: floor(y) + 1 going down, ceil(y) going up or level, which keeps the
                // row filler's top-left convention ("tweaking the edge-scanning code", ch. 58)
                if (width <= 0) {
                    e.dest_direction = -1;
                    width = -width;
                    e.int_step = -(width / e.remaining);
                    e.dest = across(p.v[start], true);
                } else {
                    e.dest_direction = 1;
                    e.int_step = width / e.remaining;
                    e.dest = across(p.v[start], true) + 1;
                }
                e.err = 1 - e.remaining;
            }
            e.adj_up = width % e.remaining;
            e.adj_down = e.remaining;
            return true;
        }
        start = next;
    }
}

bool step_edge(Edge& e, const Polygon& p) {
    if (--e.remaining == 0) return set_up_edge(e, e.current_end, p);
    e.source_x += e.step_x;
    e.source_y += e.step_y;
    e.dest += e.int_step;
    if ((e.err += e.adj_up) > 0) {
        e.dest += e.dest_direction;
        e.err -= e.adj_down;
    }
    return true;
}

// A line (row or column) between two edges, as every X-Sharp ScanOutLine sets it up: steps from
// the unclipped length, the half-step, then the clip to [lo, hi) across. `first` is the line's
// first pixel across (x for rows, y for columns). Returns false when nothing is left to draw.
struct SpanSetup {
    int32_t first, count;
    int32_t source_x, source_y, step_x, step_y;
};

__attribute__((always_inline)) inline bool line_setup(const Edge& near, const Edge& far, int32_t lo, int32_t hi, SpanSetup* s) {
    int32_t end = far.dest, first = near.dest;
    if (end <= lo || first >= hi || end - first <= 0) return false;
    int32_t length = (end - first) << 16;
    s->step_x = fixed_div(far.source_x - near.source_x, length);
    s->step_y = fixed_div(far.source_y - near.source_y, length);
    s->source_x = near.source_x + (s->step_x >> 1);  // the half-step prestep (57.1)
    s->source_y = near.source_y + (s->step_y >> 1);
    if (end > hi) end = hi;
    if (first < lo) {
        s->source_x += fixed_mul(s->step_x, (lo - first) << 16);
        s->source_y += fixed_mul(s->step_y, (lo - first) << 16);
        first = lo;
    }
    s->first = first;
    s->count = end - first;
    return true;
}

// Sets up the two edge chains from the first vertex along the scan (rows: left and right; columns:
// top and bottom), calls ready() (the setup done), then line(m, SpanSetup) for every line m (a
// row, or a column) of the polygon with pixels in the clip, as DRAWTEXP.C walks them: both chains
// stepped together until either reaches the last vertex.
template <bool COLUMNS, typename R, typename F>
void for_each_line(const Polygon& p, int min_vert, const ClipRect& clip, R&& ready, F&& line) {
    constexpr bool columns = COLUMNS;
    Edge near, far;
    near.direction = columns ? 1 : -1;
    far.direction = -near.direction;
    set_up_edge(near, min_vert, p);
    set_up_edge(far, min_vert, p);
    ready();
    const int32_t start = columns ? clip.x0 : clip.y0, end = columns ? clip.x1 : clip.y1;
    const int32_t lo = columns ? clip.y0 : clip.x0, hi = columns ? clip.y1 : clip.x1;
    for (int32_t m = along(p.v[min_vert], columns);; ++m) {
        if (m >= end) break;
        SpanSetup s;
        if (m >= start && line_setup(near, far, lo, hi, &s)) line(m, s);
        if (!step_edge(near, p) || !step_edge(far, p)) break;
    }
}

using RowSpanFn = void (*)(const DrawContext& c, const SpanSetup& s, int32_t y);

// 57.1: ScanOutLine in C; WritePixelX per pixel.
void dda_span(const DrawContext& c, const SpanSetup& s, int32_t y) {
    const uint8_t* origin = bordered_origin(c.tex);
    const int32_t pitch = bordered_pitch(c.tex);
    int32_t sx = s.source_x, sy = s.source_y;
    for (int32_t x = s.first; x < s.first + s.count; ++x) {
        *pixel_at(c.target, x, y) = origin[round_fixed(sy) * pitch + round_fixed(sx)];
        sx = int32_t(uint32_t(sx) + uint32_t(s.step_x));
        sy = int32_t(uint32_t(sy) + uint32_t(s.step_y));
    }
}

// 57.2: the rounding folded into the initial texel pointer, only fractions stepped.
void row_out_span(const DrawContext& c, const SpanSetup& s, int32_t y) {
    const int32_t pitch = bordered_pitch(c.tex);
    int32_t sx = int32_t(uint32_t(s.source_x) + 0x8000), sy = int32_t(uint32_t(s.source_y) + 0x8000);
    SplitStep xs = split(s.step_x), ys = split(s.step_y);
    XSharpRowArgs a;
    const Target& t = c.target;
    a.dst = t.base + y * t.row_bytes + (s.first >> 2);
    a.plane_bytes = t.plane_bytes;
    a.count = s.count;
    a.mask = 0x11u << (s.first & 3);
    a.texel = bordered_origin(c.tex) + (sy >> 16) * pitch + (sx >> 16);
    a.x_frac = counting_fraction(sx, s.step_x);
    a.y_frac = counting_fraction(sy, s.step_y);
    a.x_step = xs.fraction;
    a.y_step = ys.fraction;
    a.x_base = xs.whole;
    a.x_carry = xs.carry_advance;
    a.y_base = ys.whole * pitch;
    a.y_carry = ys.carry_advance * pitch;
    a.select_plane = t.select_plane;
    a.ctx = t.ctx;
    c.loop(&a);
}

SetupStatus draw_rows(const DrawContext& c, const Vertex* vertices, int count, RowSpanFn span) {
    Polygon p;
    int min_vert;
    SetupStatus status = prepare(c.tex, vertices, count, false, &p, &min_vert);
    if (status != SetupStatus::Ok) return status;
    for_each_line<false>(p, min_vert, c.target.clip, [&] { setup_done(c); }, [&](int32_t y, const SpanSetup& s) {
        emit(c.stats->probe, c.stats, 1, uint32_t(s.count), [&] { span(c, s, y); });  // the span routine is the inner loop
    });
    return SetupStatus::Ok;
}

// X-Sharp 22's column ScanOutLine after the common setup: the rounding folded into the pointer,
// the fractions packed for the 58.4 loop.
void column_span(const DrawContext& c, const SpanSetup& s, int32_t x) {
    const int32_t pitch = bordered_pitch(c.tex);
    const int32_t sx = int32_t(uint32_t(s.source_x) + 0x8000), sy = int32_t(uint32_t(s.source_y) + 0x8000);
    SplitStep xs = split(s.step_x), ys = split(s.step_y);
    XSharpColumnArgs a;
    Target& t = c.target;
    int plane = x & 3;
    if (t.select_plane) t.select_plane(t.ctx, plane);  // the map mask, once per column
    a.dst = t.base + plane * t.plane_bytes + s.first * t.row_bytes + (x >> 2);
    a.count = s.count;
    a.texel = bordered_origin(c.tex) + (sy >> 16) * pitch + (sx >> 16);
    a.fractions = (counting_fraction(sx, s.step_x) << 16) | (counting_fraction(sy, s.step_y) >> 1);
    a.steps = (xs.fraction << 16) | (ys.fraction >> 1);  // the Y fraction keeps 15 bits
    a.base = xs.whole + ys.whole * pitch;
    a.row = ys.carry_advance * pitch;
    a.backwards = s.step_x < 0;
    emit(c, &a, 1, uint32_t(a.count));
}

// The texel index a loop reads after k steps from a 16.16 coordinate `start` (the rounding's
// 0x8000 folded in) moving by `step`: the start's whole part, k whole steps toward zero, and a
// carry (+1, or -1 for negative steps) each time a counting-up fraction of `bits` bits overflows
// (57.2's and 58.4's x: 16 bits; 58.4's y: 15, the step's and the start's low bit dropped). That
// is floor(a + b k) exactly, for a and b below (minus floor(n / m) is floor((m - 1 - n) / m) for
// integers n, m > 0); 57.1's round_fixed(start + k step) is the same line for 16 bits.
void counting_line(int32_t start, int32_t step, int bits, double* a, double* b) {
    const SplitStep split_step = split(step);
    const double one = double(1 << bits);
    const double fraction = double(counting_fraction(start, step) >> (16 - bits)), per_step = double(split_step.fraction >> (16 - bits));
    const double whole = double(start >> 16);
    if (step >= 0) {
        *a = whole + fraction / one, *b = double(split_step.whole) + per_step / one;
    } else {
        *a = whole + (one - 1 - fraction) / one, *b = double(split_step.whole) - per_step / one;
    }
}

// The bound (docs/bounds.md, "X-Sharp's lines"): DRAWTEXP.C's walk run again, and each line's
// texel indices, floor(a + b k) along u and v, against the exact mapping at its pixel centres
// (lines_bound, pieces of BOUND_PIECE pixels) over every pixel it draws. The loops read the
// bordered copy, whose border repeats the edge texels: where a line's indices reach the border
// the texel read may be one nearer than its index (one texel more in the bound), and beyond it no
// bound. No bound either where Q is not positive at a line's end.
ErrorBound bound(const BoundContext& c, const Vertex* vertices, int count, bool columns, int y_bits) {
    ErrorBound b;
    Polygon p;
    int min_vert;
    double shift[2];
    if (!mapper_accepts(c.mapper, c.tex) || prepare(c.tex, vertices, count, columns, &p, &min_vert, shift) != SetupStatus::Ok) return b;
    PolygonSetup own;
    const PolygonSetup* s = exact_setup(c, vertices, count, &own, &b);
    if (!s) return b;
    const Axis axis = columns ? Axis::Columns : Axis::Rows;
    const double size[2] = {double(c.tex.width), double(c.tex.height)};
    double worst = 0;
    bool fits = true;
    auto each_line = [&](int32_t m, const SpanSetup& line) {
        if (!fits || c.settled(worst)) return;
        double a[2], step[2], border = 0;
        counting_line(int32_t(uint32_t(line.source_x) + 0x8000), line.step_x, 16, &a[0], &step[0]);
        counting_line(int32_t(uint32_t(line.source_y) + 0x8000), line.step_y, y_bits, &a[1], &step[1]);
        for (int t = 0; t < 2; ++t) {
            fits = fits && within_border(a[t], step[t], double(line.count - 1), size[t], &border);
            a[t] -= shift[t];  // the unshifted coordinates, as the reference's
        }
        const Span span = columns ? Span{m, line.first, line.count} : Span{line.first, m, line.count};
        if (fits) worst = larger(worst, drawn_line_bound(*s, axis, span, a, step, border));
        fits = fits && worst < NO_BOUND;
    };
    if (columns) for_each_line<true>(p, min_vert, c.clip, [] {}, each_line);
    else for_each_line<false>(p, min_vert, c.clip, [] {}, each_line);
    b.footprint = fits ? worst : NO_BOUND;
    return b;
}

}  // namespace

ErrorBound bound_rows(const BoundContext& c, const Vertex* vertices, int count) { return bound(c, vertices, count, false, 16); }
ErrorBound bound_column(const BoundContext& c, const Vertex* vertices, int count) { return bound(c, vertices, count, true, 15); }

SetupStatus draw_dda(const DrawContext& c, const Vertex* vertices, int count) { return draw_rows(c, vertices, count, dda_span); }

SetupStatus draw_row_out(const DrawContext& c, const Vertex* vertices, int count) {
    return draw_rows(c, vertices, count, row_out_span);
}

SetupStatus draw_column(const DrawContext& c, const Vertex* vertices, int count) {
    Polygon p;
    int min_vert;
    SetupStatus status = prepare(c.tex, vertices, count, true, &p, &min_vert);
    if (status != SetupStatus::Ok) return status;
    for_each_line<true>(p, min_vert, c.target.clip, [&] { setup_done(c); }, [&](int32_t x, const SpanSetup& s) { column_span(c, s, x); });
    return SetupStatus::Ok;
}

}  // namespace raster::xsharp

namespace raster {

void xsharp_row_loop(const void* raw) {
    const auto& a = *static_cast<const XSharpRowArgs*>(raw);
    uint8_t* dst = a.dst;
    const uint8_t* texel = a.texel;
    uint32_t mask = a.mask & 0xFF, x_frac = a.x_frac, y_frac = a.y_frac;
    for (int32_t n = 0; n < a.count; ++n) {
        int plane = (mask & 0x0F) == 1 ? 0 : (mask & 0x0F) == 2 ? 1 : (mask & 0x0F) == 4 ? 2 : 3;  // the Map Mask's plane
        if (a.select_plane) a.select_plane(a.ctx, plane);  // out dx, al
        dst[plane * a.plane_bytes] = *texel;
        texel += a.x_base;
        x_frac += a.x_step;
        if (x_frac > 0xFFFF) {
            x_frac &= 0xFFFF;
            texel += a.x_carry;
        }
        texel += a.y_base;
        y_frac += a.y_step;
        if (y_frac > 0xFFFF) {
            y_frac &= 0xFFFF;
            texel += a.y_carry;
        }
        uint32_t carry = mask >> 7;  // rol al, 1; adc edi, 0
        mask = ((mask << 1) | carry) & 0xFF;
        dst += carry;
    }
}

void xsharp_column_loop(const void* raw) {
    const auto& a = *static_cast<const XSharpColumnArgs*>(raw);
    uint8_t* dst = a.dst;
    const uint8_t* texel = a.texel;
    uint32_t f = a.fractions;
    for (int32_t n = 0; n < a.count; ++n) {
        uint8_t b = *texel;
        uint32_t sum = f + a.steps;
        int32_t carry = sum < f;  // out of bit 31: the X fraction's carry
        f = sum;
        texel += a.backwards ? a.base - carry : a.base + carry;
        *dst = b;
        if (f & 0x8000) {  // the Y fraction's carry, caught in bit 15
            texel += a.row;
            f &= ~0x8000u;
        }
        dst += XSHARP_SCANWIDTH;
    }
}

// The loop's random cases (core/selftest.h).
LoopCheck check_xsharp_column(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<XSharpColumnArgs>(m, other, seed, cases, buf, [&](Random& r, XSharpColumnArgs& a) {
        int32_t pitch = random_texture_size(r) + 2;  // a bordered texture's pitch: 3..1026
        a.count = random_count(r, 1, 3, 240);
        a.texel = buf.texels + CHECK_TEXEL_MID + r.range(-1000, 1000);
        a.fractions = (r.next() & 0xFFFF0000u) | (r.next() & 0x7FFF);
        a.steps = (r.next() & 0xFFFF0000u) | (r.next() & 0x7FFF);
        if (r.below(4) == 0) a.steps &= 0xFFFF7FFFu & (r.below(2) ? 0x0000FFFFu : 0xFFFF0000u);  // one axis without a fraction
        a.base = r.range(-2, 2) + r.range(-1, 1) * pitch;
        a.row = r.below(2) ? pitch : -pitch;
        a.backwards = int32_t(r.below(2));
        return place_span(buf, a, XSHARP_SCANWIDTH);
    });
}

void random_xsharp_row(Random& r, const uint8_t* texels, XSharpRowArgs* a, int32_t* x, int32_t* y) {
    int32_t pitch = r.range(3, 600);
    *y = r.range(0, 239);
    *x = r.range(0, 319);
    a->count = r.range(1, 320 - *x);
    a->mask = 0x11u << (*x & 3);
    a->texel = texels + CHECK_TEXEL_MID + r.range(-1000, 1000);
    a->x_frac = r.next() & 0xFFFF;
    a->y_frac = r.next() & 0xFFFF;
    a->x_step = r.below(4) == 0 ? 0 : r.next() & 0xFFFF;
    a->y_step = r.below(4) == 0 ? 0 : r.next() & 0xFFFF;
    a->x_base = r.range(-3, 3);
    a->x_carry = r.below(2) ? 1 : -1;
    a->y_base = r.range(-1, 1) * pitch;
    a->y_carry = r.below(2) ? pitch : -pitch;
    a->select_plane = nullptr;
    a->ctx = nullptr;
}

#if defined(MODEXLAB_OFFSETS)
// The block layouts asm/xsharp.asm reads (core/asm_offsets.h).
void xsharp_offsets() {
    ASM_FIELDS(XROW, XSharpRowArgs, dst, count, mask, texel, x_frac, y_frac, x_step, y_step, x_base, x_carry, y_base, y_carry)
    ASM_FIELDS(XCOL, XSharpColumnArgs, dst, count, texel, fractions, steps, base, row, backwards)
    ASM_SIZE(XROW_ARGS_SIZE, XSharpRowArgs);
    ASM_CONSTANT(XSHARP_SCANWIDTH, XSHARP_SCANWIDTH);
}
#endif

}  // namespace raster
