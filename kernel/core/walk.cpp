// Edge walking: the bounds of each line from the edge functions, stepped exactly in integers.
#include "kernel/core/walk.h"

// Why it works. On line L (row y, or column x) each edge's function is linear in the minor
// coordinate m: E = A*m + B(L), with B(L+1) = B(L) + C. Inside is E >= t, so an edge with A > 0
// bounds m from below by ceil((t - B)/A), one with A < 0 from above by floor((B - t)/-A), and one
// with A = 0 keeps or drops whole lines: it narrows the range of lines once, at the start.
//
// The polygon is convex, so every edge's line supports it: on line L the tightest lower bound is
// the one of an edge whose closed extent along the major axis holds L's centre (any other lower
// edge's line passes outside the polygon there, or through the same boundary point only when L's
// centre is within that edge's extent too). So each bound is stepped only on its own lines, at
// most two of a kind at once, and a triangle costs two bounds a line.
namespace raster {

namespace {

int64_t ceil_div_pos(int64_t n, int64_t d) { return -floor_div(-n, d); }

// The first and last line whose centre lies in [lo, hi] (subpixels): ceil and floor of
// (p - 128) / 256, as arithmetic shifts (which floor).
int64_t first_line(int64_t lo) { return (lo - SUBPIXEL_HALF + SUBPIXEL_ONE - 1) >> SUBPIXEL_BITS; }
int64_t last_line(int64_t hi) { return (hi - SUBPIXEL_HALF) >> SUBPIXEL_BITS; }

}  // namespace

void EdgeWalker::seal(Bound* list, int32_t count, int32_t never) {
    // insertion sort: a handful of edges, nearly in order already
    for (int32_t i = 1; i < count; ++i) {
        Bound key = list[i];
        int32_t j = i - 1;
        for (; j >= 0 && list[j].first > key.first; --j) list[j + 1] = list[j];
        list[j + 1] = key;
    }
    list[count] = Bound{INT32_MAX, INT32_MAX, never, 0, 0, 0, 1};
}

void EdgeBound::init(int64_t m, int64_t divisor, int64_t increment) {
    // the remainders are below d <= 2^31: exact in 32-bit arithmetic
    d = uint32_t(divisor);
    q = int32_t(floor_div(m, divisor));
    r = uint32_t(m) - uint32_t(q) * d;
    dq = int32_t(floor_div(increment, divisor));
    dr = uint32_t(increment) - uint32_t(dq) * d;
}

EdgeWalker::EdgeWalker(const PolygonSetup& s, Axis axis, const ClipRect& clip) : axis_(axis) {
    const bool rows = axis == Axis::Rows;
    // lines whose centre lies within the bounding box, inside the clip rectangle
    int64_t first = first_line(rows ? s.min_y : s.min_x);
    int64_t last = last_line(rows ? s.max_y : s.max_x);
    int32_t clip_lo = rows ? clip.y0 : clip.x0, clip_hi = (rows ? clip.y1 : clip.x1) - 1;
    if (first < clip_lo) first = clip_lo;
    if (last > clip_hi) last = clip_hi;
    minor_lo_ = rows ? clip.x0 : clip.y0;
    minor_hi_ = (rows ? clip.x1 : clip.y1) - 1;
    line_ = int32_t(first);
    last_line_ = int32_t(first) - 1;  // empty (and the bounds never looked at) until proven otherwise
    if (first > last) return;

    // E = dx*(Py - py) - dy*(Px - px) with P = (256*m + 128, centre) for rows, (centre, 256*m + 128)
    // for columns: A = -dy*256 and C = dx*256 for rows, A = dx*256 and C = -dy*256 for columns
    // (`sign` folds the two), B(L) as below.
    const int64_t sign = rows ? 1 : -1;
    auto b_at = [&](const Edge& e, int64_t line) {
        const int64_t centre = line * SUBPIXEL_ONE + SUBPIXEL_HALF;
        return rows ? e.dx * (centre - e.py) - e.dy * (SUBPIXEL_HALF - e.px)
                    : e.dx * (SUBPIXEL_HALF - e.py) - e.dy * (centre - e.px);
    };

    // edges along the lines (top and bottom for rows, left and right for columns) cut whole lines:
    // E(L) = B(L) = B(first) + (L - first) * C >= t, with C = +-(the edge's minor extent) * 256 != 0
    const int64_t line0 = first;
    for (int i = 0; i < s.edge_count; ++i) {
        const Edge& e = s.edges[i];
        if ((rows ? e.dy : e.dx) != 0) continue;
        const int64_t b = b_at(e, line0), c = sign * (rows ? e.dx : e.dy) * SUBPIXEL_ONE, t = e.threshold;
        if (c > 0) {
            int64_t from = line0 + ceil_div_pos(t - b, c);
            if (from > first) first = from;
        } else {
            int64_t to = line0 + floor_div(b - t, -c);
            if (to < last) last = to;
        }
    }
    if (first > last) return;
    line_ = int32_t(first);
    last_line_ = int32_t(last);

    int32_t lower_count = 0, upper_count = 0;
    for (int i = 0; i < s.edge_count; ++i) {
        const Edge& e = s.edges[i];
        const int64_t p = rows ? e.py : e.px, dp = rows ? e.dy : e.dx;
        if (dp == 0) continue;  // along the lines: done above
        int64_t lo = first_line(dp < 0 ? p + dp : p), hi = last_line(dp < 0 ? p : p + dp);
        if (lo < first) lo = first;
        if (hi > last) hi = last;
        if (lo > hi) continue;  // no line's centre within its extent
        const int64_t a = -sign * dp * SUBPIXEL_ONE, b = b_at(e, lo), c = sign * (rows ? e.dx : e.dy) * SUBPIXEL_ONE;
        Bound* bound;
        if (a > 0) {
            // m >= ceil((t - B)/A) = floor((t - B + A - 1)/A); the numerator falls by C each line
            bound = &lower_[lower_count++];
            bound->init(e.threshold - b + a - 1, a, -c);
        } else {
            // m <= floor((B - t)/-A); the numerator grows by C each line
            bound = &upper_[upper_count++];
            bound->init(b - e.threshold, -a, c);
        }
        bound->first = int32_t(lo);
        bound->last = int32_t(hi);
    }
    seal(lower_, lower_count, INT32_MIN);
    seal(upper_, upper_count, INT32_MAX);
}

}  // namespace raster
