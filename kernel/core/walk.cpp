// Edge walking: the bounds of each line from the edge functions, stepped exactly in integers.
#include "kernel/core/walk.h"

#if defined(MODEXLAB_OFFSETS)
#include "kernel/core/asm_offsets.h"
#endif

// Why it works (docs/accuracy.md, "Screen, grid and coverage"): on line L each edge's function is
// linear in the minor coordinate m, E = A*m + B(L) with B(L+1) = B(L) + C, so inside (E >= t) an edge
// with A > 0 bounds m from below by ceil((t - B)/A), one with A < 0 from above by floor((B - t)/-A),
// and one with A = 0 narrows the range of lines once, at the start. The polygon is convex, so the
// tightest bound on a side is that of an edge whose closed extent along the major axis holds L's
// centre: each bound is stepped only on its own lines, at most two of a kind at once, and a
// triangle costs two bounds a line.
namespace raster {

namespace {

// floor(n / d) for d > 0, in the width the walker computes in
int64_t floor_div_in(int64_t n, int64_t d) { return floor_div(n, d); }
int32_t floor_div_in(int32_t n, int32_t d) { return floor_div32(n, d); }
template <typename I>
I ceil_div_pos(I n, I d) { return -floor_div_in(I(-n), d); }

// The first and last line whose centre lies in [lo, hi] (subpixels): ceil and floor of
// (p - 128) / 256, as arithmetic shifts (which floor).
template <typename I>
I first_line(I lo) { return I((lo - I(SUBPIXEL_HALF) + I(SUBPIXEL_ONE) - 1) >> SUBPIXEL_BITS); }
template <typename I>
I last_line(I hi) { return I((hi - I(SUBPIXEL_HALF)) >> SUBPIXEL_BITS); }

}  // namespace

[[gnu::always_inline]] inline void EdgeWalker::seal(Bound* list, int32_t count, int32_t never) {
    // insertion sort: a handful of edges, nearly in order already (a triangle's one or two a side:
    // at most one swap, and none to copy when they are in order)
    for (int32_t i = 1; i < count; ++i) {
        if (list[i - 1].first <= list[i].first) continue;
        Bound key = list[i];
        int32_t j = i - 1;
        for (; j >= 0 && list[j].first > key.first; --j) list[j + 1] = list[j];
        list[j + 1] = key;
    }
    list[count] = Bound{INT32_MAX, INT32_MAX, never, 0, 0, 0, 1};
}

template <typename I>
void EdgeBound::init(I m, I divisor, I increment) {
    // the remainders are below d <= 2^31: exact in 32-bit arithmetic
    d = uint32_t(divisor);
    q = int32_t(floor_div_in(m, divisor));
    r = uint32_t(m) - uint32_t(q) * d;
    dq = int32_t(floor_div_in(increment, divisor));
    dr = uint32_t(increment) - uint32_t(dq) * d;
}

template <typename I>
void EdgeWalker::build(const PolygonSetup& s, I first, I last, int64_t origin_x, int64_t origin_y) {
    const int edges = s.edge_count;
    const bool rows = axis_ == Axis::Rows;
    // coordinates relative to the pixel corner (origin_x, origin_y); lines and the minor coordinate
    // too, given back absolute in the bounds (line0, minor0)
    const int64_t line0 = rows ? origin_y : origin_x, minor0 = rows ? origin_x : origin_y;
    const int64_t ox = origin_x * SUBPIXEL_ONE, oy = origin_y * SUBPIXEL_ONE;
    first = I(first - line0), last = I(last - line0);

    // E = dx*(Py - py) - dy*(Px - px) with P = (256*m + 128, centre) for rows, (centre, 256*m + 128)
    // for columns: A = -dy*256 and C = dx*256 for rows, A = dx*256 and C = -dy*256 for columns
    // (`sign` folds the two), B(L) as below.
    const I sign = rows ? 1 : -1, one = I(SUBPIXEL_ONE), half = I(SUBPIXEL_HALF);
    auto b_at = [&](I dx, I dy, I px, I py, I line) {
        const I centre = I(line * one + half);
        return rows ? I(dx * (centre - py) - dy * (half - px)) : I(dx * (half - py) - dy * (centre - px));
    };

    // edges along the lines (top and bottom for rows, left and right for columns) cut whole lines:
    // E(L) = B(L) = B(first) + (L - first) * C >= t, with C = +-(the edge's minor extent) * 256 != 0
    const I base = first;
    for (int i = 0; i < edges; ++i) {
        const Edge& e = s.edges[i];
        if ((rows ? e.dy : e.dx) != 0) continue;
        const I dx = I(e.dx), dy = I(e.dy), px = I(e.px - ox), py = I(e.py - oy);
        const I b = b_at(dx, dy, px, py, base), c = I(sign * (rows ? dx : dy) * one), t = I(e.threshold);
        if (c > 0) {
            I from = I(base + ceil_div_pos(I(t - b), c));
            if (from > first) first = from;
        } else {
            I to = I(base + floor_div_in(I(b - t), I(-c)));
            if (to < last) last = to;
        }
    }
    if (first > last) return;
    line_ = int32_t(first + line0);
    last_line_ = int32_t(last + line0);

    int32_t lower_count = 0, upper_count = 0;
    for (int i = 0; i < edges; ++i) {
        const Edge& e = s.edges[i];
        const I dx = I(e.dx), dy = I(e.dy), px = I(e.px - ox), py = I(e.py - oy);
        const I p = rows ? py : px, dp = rows ? dy : dx;
        if (dp == 0) continue;  // along the lines: done above
        I lo = first_line(I(dp < 0 ? p + dp : p)), hi = last_line(I(dp < 0 ? p : p + dp));
        if (lo < first) lo = first;
        if (hi > last) hi = last;
        if (lo > hi) continue;  // no line's centre within its extent
        const I a = I(-sign * dp * one), b = b_at(dx, dy, px, py, lo), c = I(sign * (rows ? dx : dy) * one);
        Bound* bound;
        if (a > 0) {
            // m >= ceil((t - B)/A) = floor((t - B + A - 1)/A); the numerator falls by C each line
            bound = &lower_[lower_count++];
            bound->init(I(e.threshold - b + a - 1), a, I(-c));
        } else {
            // m <= floor((B - t)/-A); the numerator grows by C each line
            bound = &upper_[upper_count++];
            bound->init(I(b - e.threshold), I(-a), c);
        }
        bound->q += int32_t(minor0);
        bound->first = int32_t(lo + line0);
        bound->last = int32_t(hi + line0);
    }
    seal(lower_, lower_count, INT32_MIN);
    seal(upper_, upper_count, INT32_MAX);
}

namespace {

// floor(n / d) and n - floor(n / d) * d, d > 0: one IDIV gives both (truncated), then the step down
[[gnu::always_inline]] inline void floor_div_rem32(int32_t n, int32_t d, int32_t* q, uint32_t* r) {
    int32_t quotient = n / d, remainder = n % d;
    if (remainder < 0) --quotient, remainder += d;
    *q = quotient;
    *r = uint32_t(remainder);
}

// build's arithmetic for three edges in 32 bits, term for term (FillRule's tests check both
// against covers()). Along the axis: major = the line's coordinate, minor = across it; for rows (major y)
// E = dmin * (centre - pmaj) - dmaj * (m*256 + 128 - pmin), for columns (major x) its negation.
// Returns false where an edge along the lines leaves no line (nothing written then); first and last
// come back cut by such an edge.
template <bool ROWS>
bool triangle_bounds(const Edge* edges, int32_t* first_io, int32_t* last_io, int32_t origin_x, int32_t origin_y, EdgeBound* lower_,
                     EdgeBound* upper_) {
    using Bound = EdgeBound;
    int32_t first = *first_io, last = *last_io;
    constexpr int32_t one = int32_t(SUBPIXEL_ONE), half = int32_t(SUBPIXEL_HALF);
    const int32_t line0 = ROWS ? origin_y : origin_x, minor0 = ROWS ? origin_x : origin_y;
    const int32_t omaj = line0 * one, omin = minor0 * one;
    first -= line0, last -= line0;
    // edge i's start and direction along and across the lines, relative to the origin (read from
    // the setup where used: a copy of them cost more than the reads)
    auto pmaj = [&](int i) __attribute__((always_inline)) { return (ROWS ? edges[i].py : edges[i].px) - omaj; };
    auto pmin = [&](int i) __attribute__((always_inline)) { return (ROWS ? edges[i].px : edges[i].py) - omin; };
    auto dmaj = [&](int i) __attribute__((always_inline)) { return ROWS ? edges[i].dy : edges[i].dx; };
    auto dmin = [&](int i) __attribute__((always_inline)) { return ROWS ? edges[i].dx : edges[i].dy; };
    // E at line L (relative), minor coordinate 0 (the pixel at origin's minor coordinate)
    auto b_at = [&](int i, int32_t line) __attribute__((always_inline)) {
        const int32_t value = dmin(i) * (line * one + half - pmaj(i)) - dmaj(i) * (half - pmin(i));
        return ROWS ? value : -value;
    };
    // an edge along the lines (at most one: the area is positive) cuts whole lines
    const int32_t base = first;
#pragma GCC unroll 3
    for (int i = 0; i < 3; ++i) {
        if (dmaj(i) != 0) continue;
        const int32_t b = b_at(i, base), c = (ROWS ? dmin(i) : -dmin(i)) * one, t = edges[i].threshold;
        if (c > 0) {
            const int32_t from = base - floor_div32(b - t, c);  // base + ceil((t - b) / c)
            if (from > first) first = from;
        } else {
            const int32_t to = base + floor_div32(b - t, -c);
            if (to < last) last = to;
        }
    }
    if (first > last) return false;
    *first_io = first + line0;
    *last_io = last + line0;

    // First each edge's lines and chain: a triangle's edges across the lines go both ways, so each
    // chain has one or two, put in order of first line (ties as they come). Then each bound is
    // written once, in its place (a Bound assigned whole is a copying loop on i686).
    int32_t lo[3], hi[3];
    int lower_edges[2], upper_edges[2];
    int32_t lower_count = 0, upper_count = 0;
#pragma GCC unroll 3
    for (int i = 0; i < 3; ++i) {
        const int32_t p = pmaj(i), d = dmaj(i);
        if (d == 0) continue;
        int32_t l = first_line(d < 0 ? p + d : p), h = last_line(d < 0 ? p : p + d);
        if (l < first) l = first;
        if (h > last) h = last;
        if (l > h) continue;  // no line's centre within its extent
        lo[i] = l, hi[i] = h;
        if ((ROWS ? -d : d) > 0) lower_edges[lower_count++] = i;  // A = -sign * dmaj * 256 > 0
        else upper_edges[upper_count++] = i;
    }
    auto order = [&lo](int* chain, int32_t count) __attribute__((always_inline)) {
        if (count == 2 && lo[chain[0]] > lo[chain[1]]) {
            const int t = chain[0];
            chain[0] = chain[1], chain[1] = t;
        }
    };
    order(lower_edges, lower_count);
    order(upper_edges, upper_count);
    auto fill = [&](Bound& bound, int i, bool lower) __attribute__((always_inline)) {
        const int32_t b = b_at(i, lo[i]), c = (ROWS ? dmin(i) : -dmin(i)) * one, t = edges[i].threshold;
        // lower: m >= ceil((t - B)/A), the numerator falling by C a line; upper: m <= floor((B - t)/-A)
        const int32_t d = (ROWS == lower ? -dmaj(i) : dmaj(i)) * one;
        floor_div_rem32(lower ? t - b + d - 1 : b - t, d, &bound.q, &bound.r);
        floor_div_rem32(lower ? -c : c, d, &bound.dq, &bound.dr);
        bound.d = uint32_t(d);
        bound.q += minor0;
        bound.first = lo[i] + line0;
        bound.last = hi[i] + line0;
    };
    for (int32_t k = 0; k < lower_count; ++k) fill(lower_[k], lower_edges[k], true);
    for (int32_t k = 0; k < upper_count; ++k) fill(upper_[k], upper_edges[k], false);
    // the sentinels, as seal() makes them
    auto sentinel = [](Bound& bound, int32_t never) __attribute__((always_inline)) {
        bound.first = bound.last = INT32_MAX;
        bound.q = never;
        bound.dq = 0, bound.r = 0, bound.dr = 0, bound.d = 1;
    };
    sentinel(lower_[lower_count], INT32_MIN);
    sentinel(upper_[upper_count], INT32_MAX);
    return true;
}

}  // namespace

bool triangle_rows(const TriangleRowsArgs* a) {
    if (a->edges[0].dy == 0 || a->edges[1].dy == 0 || a->edges[2].dy == 0) return false;
    int32_t first = a->first, last = a->last;
    return triangle_bounds<true>(a->edges, &first, &last, a->origin_x, a->origin_y, a->lower, a->upper);
}

bool triangle_runs(TriangleRunsArgs* a) {
    const PolygonSetup& s = *a->setup;
    const int32_t min_x = int32_t(s.min_x), min_y = int32_t(s.min_y), max_x = int32_t(s.max_x), max_y = int32_t(s.max_y);
    int32_t first, last;
    box_lines(min_y, max_y, a->clip_lo, a->clip_hi, &first, &last);
    a->line = first;
    a->lines = a->next_lines = 0;
    a->run_lower = a->run_upper = a->next_lower = a->next_upper = nullptr;
    if (first > last) return true;
    if (!small_box(min_x, min_y, max_x, max_y)) return false;
    const TriangleRowsArgs rows{s.edges, first, last, min_x >> SUBPIXEL_BITS, min_y >> SUBPIXEL_BITS, a->lower, a->upper};
    if (!triangle_rows(&rows)) return false;
    EdgeBound *lo = a->lower, *hi = a->upper;
    const int32_t lines = run_from(&lo, &hi, first, last);
    if (lines == 0) return false;
    const int32_t next = first + lines;
    int32_t next_lines = 0;
    if (next <= last) {
        a->next_lower = lo, a->next_upper = hi;  // (then moved on to the second run's bounds)
        next_lines = run_from(&a->next_lower, &a->next_upper, next, last);
        if (next_lines != last - next + 1) return false;  // (0, or a third run: not a triangle's)
    }
    a->lines = lines, a->next_lines = next_lines;
    a->run_lower = lo, a->run_upper = hi;
    return true;
}

template <bool ROWS>
void EdgeWalker::build_triangle(const PolygonSetup& s, int32_t first, int32_t last, int32_t origin_x, int32_t origin_y) {
#if defined(MODEXLAB_ASM_LOOPS)
    if (ROWS) {  // (its C++ twin: triangle_rows, which is triangle_bounds<true> without edges along the rows)
        const TriangleRowsArgs a{s.edges, first, last, origin_x, origin_y, lower_, upper_};
        if (triangle_rows_asm(&a)) {
            line_ = first, last_line_ = last;
            return;
        }
    }
#endif
    if (triangle_bounds<ROWS>(s.edges, &first, &last, origin_x, origin_y, lower_, upper_)) line_ = first, last_line_ = last;
}

EdgeWalker::EdgeWalker(const PolygonSetup& s, Axis axis, const ClipRect& clip) : axis_(axis) {
    if (axis == Axis::Rows) init<true>(s, clip);
    else init<false>(s, clip);
}

// (the inline constructor takes these)
template void EdgeWalker::build<int32_t>(const PolygonSetup&, int32_t, int32_t, int64_t, int64_t);
template void EdgeWalker::build<int64_t>(const PolygonSetup&, int64_t, int64_t, int64_t, int64_t);
template void EdgeWalker::build_triangle<true>(const PolygonSetup&, int32_t, int32_t, int32_t, int32_t);
template void EdgeWalker::build_triangle<false>(const PolygonSetup&, int32_t, int32_t, int32_t, int32_t);

#if defined(MODEXLAB_OFFSETS)
// The layouts asm/walk.asm and the fast mappers' run loops read (asm_offsets.h).
void walk_offsets() {
    ASM_FIELDS(BOUND, EdgeBound, first, last, q, dq, r, dr, d)
    ASM_SIZE(BOUND_SIZE, EdgeBound);
    ASM_FIELDS(TRI, TriangleRowsArgs, edges, first, last, origin_x, origin_y, lower, upper)
}
#endif

}  // namespace raster
