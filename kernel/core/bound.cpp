// Spans as lines of the exact mapping, and the extremes the bounds need along them.
#include "kernel/core/bound.h"

#if defined(MODEXLAB_OFFSETS)
#include "kernel/core/asm_offsets.h"
#endif

namespace raster {

namespace {

constexpr double EPSILON = 2.220446049250313e-16;  // 2^-52

// Q at the ends of pixels k0..k1: the smaller and the larger (Q is linear along a span).
double q_low(const SpanLine& l, double k0, double k1) {
    double a = l.q0 + l.qm * k0, b = l.q0 + l.qm * k1;
    return a < b ? a : b;
}
double q_high(const SpanLine& l, double k0, double k1) { return larger(l.q0 + l.qm * k0, l.q0 + l.qm * k1); }
// Whether Q > 0 all along the span (at both ends: it is linear). The span bounds need it: where Q
// is not positive the exact mapping has a pole or runs backwards, D = (lQ - P) / Q need not take
// its extremes at the ends or where D' = 0, the footprint is not smallest where Q is largest, and
// the reference's rounding (exact_rounding, over Q's least along the span) is not bounded. No
// bound there (as drawn_line_bound and the spread say).
bool q_positive(const SpanLine& l) { return l.q0 > 0 && l.q0 + l.qm * double(l.count - 1) > 0; }

// |K| = |P' Q - P Q'| for u (t = 0) or v, constant along the span, and the rounding of its
// evaluation (the bounds take it away or add it, as their direction needs).
double k_magnitude(const SpanLine& l, int t, double* rounding) {
    *rounding = 4 * EPSILON * (magnitude(l.pm[t] * l.q0) + magnitude(l.p0[t] * l.qm));
    return magnitude(l.pm[t] * l.q0 - l.p0[t] * l.qm);
}
// A plane's value at the span's first pixel centre and its change per pixel along the span, with
// the magnitude of the terms it is summed from (at either end: the larger).
void along(const Plane& p, double x, double y, Axis axis, int32_t count, double* at, double* per_pixel, double* scale) {
    *at = p.at(x, y);
    *per_pixel = (axis == Axis::Rows ? p.gx : p.gy) * double(SUBPIXEL_ONE);
    double last = double(count - 1) * double(SUBPIXEL_ONE);
    double x1 = axis == Axis::Rows ? x + last : x, y1 = axis == Axis::Rows ? y : y + last;
    *scale = larger(magnitude(p.a0) + magnitude(p.gy * y) + magnitude(p.gx * x), magnitude(p.a0) + magnitude(p.gy * y1) + magnitude(p.gx * x1));
}

}  // namespace

SpanLine span_line(const PolygonSetup& s, Axis axis, const Span& span) {
    SpanLine l;
    double x = span_centre_x(s, span.x), y = span_centre_y(s, span.y);
    l.count = span.count;
    along(s.q, x, y, axis, span.count, &l.q0, &l.qm, &l.scale_q);
    along(s.pu, x, y, axis, span.count, &l.p0[0], &l.pm[0], &l.scale_p[0]);
    along(s.pv, x, y, axis, span.count, &l.p0[1], &l.pm[1], &l.scale_p[1]);
    return l;
}

double line_deviation(const SpanLine& l, int t, double a, double b, double k0, double k1) {
    auto deviation = [&](double k) { return magnitude(a + b * k - span_exact(l, t, k)); };
    double worst = larger(deviation(k0), deviation(k1));
    // (line * Q - P) is A k^2 + B k + C; the deviation's derivative vanishes where
    // A qm k^2 + 2 A q0 k + (B q0 - C qm) = 0
    double A = b * l.qm, B = a * l.qm + b * l.q0 - l.pm[t], C = a * l.q0 - l.p0[t];
    double alpha = A * l.qm, beta = 2 * A * l.q0, gamma = B * l.q0 - C * l.qm;
    double roots[2];
    int n = 0;
    if (alpha == 0) {
        if (beta != 0) roots[n++] = -gamma / beta;
    } else {
        double disc = beta * beta - 4 * alpha * gamma;
        if (disc >= 0) {
            double r = __builtin_sqrt(disc);
            roots[n++] = (-beta + r) / (2 * alpha);
            roots[n++] = (-beta - r) / (2 * alpha);
        }
    }
    for (int i = 0; i < n; ++i)
        if (roots[i] > k0 && roots[i] < k1) worst = larger(worst, deviation(roots[i]));
    return worst;
}

double exact_rounding(const SpanLine& l, int t) {
    double last = double(l.count - 1);
    double q_min = q_low(l, last, 0);
    double t_max = larger(magnitude(span_exact(l, t, 0)), magnitude(span_exact(l, t, last)));
    // P and Q each within 3 ulps of their terms' sum, the quotient within one more: doubled for
    // the slack of evaluating this bound itself in double
    return 2 * (4 * EPSILON * (l.scale_p[t] + t_max * l.scale_q) / q_min + 2 * EPSILON * t_max);
}

double min_footprint_along(const SpanLine& l, double k0, double k1) {
    double q_max = q_high(l, k0, k1);
    double best = 0;
    for (int t = 0; t < 2; ++t) {
        double rounding, k = k_magnitude(l, t, &rounding);
        best = larger(best, k - rounding);  // from below
    }
    return best / (q_max * q_max);
}

double lines_bound(const SpanLine& l, const double* a, const double* b, double k0, double k1, double rounding) {
    if (!q_positive(l)) return NO_BOUND;
    double d[2];
    for (int t = 0; t < 2; ++t) d[t] = line_deviation(l, t, a[t], b[t], k0, k1) + rounding + 2 * exact_rounding(l, t);
    return footprint_error(d[0], d[1], min_footprint_along(l, k0, k1));
}

double max_step_along(const SpanLine& l, int t, double k0, double k1) {
    double q_lo = q_low(l, k0, k1);
    double rounding, k = k_magnitude(l, t, &rounding);
    return (k + rounding) / (q_lo * q_lo) * (1 + 1e-9);  // from above; the margin: this bound's own rounding
}

ChordTerms chord_terms(const SpanLine& l) {
    ChordTerms c;
    c.least_k = 0;
    c.qm = magnitude(l.qm);
    for (int t = 0; t < 2; ++t) {
        double rounding, k = k_magnitude(l, t, &rounding);
        c.k_high[t] = k + rounding;
        c.least_k = larger(c.least_k, k - rounding);
        c.reference[t] = 2 * exact_rounding(l, t);
    }
    return c;
}

double chords_bound(const ChordTerms& c, double h, double q_lo, double q_hi, double rounding) {
    if (!(q_lo > 0)) return NO_BOUND;  // t'' = -2 K Q' / Q^3 is largest where Q is least only where Q > 0
    double d[2];
    for (int t = 0; t < 2; ++t) {
        // h^2 / 8 * 2 |K| |Q'| / Q_lo^3, with |K| / Q_lo^2 as max_step_along has it
        double curvature = c.k_high[t] / (q_lo * q_lo) * (1 + 1e-9) * 2 * c.qm / q_lo;
        d[t] = h * h / 8 * curvature * (1 + 1e-9) + rounding + c.reference[t];
    }
    return footprint_error(d[0], d[1], c.least_k / (q_hi * q_hi));  // min_footprint_along
}

double chords_bound(const SpanLine& l, double h, double k0, double k1, double rounding) {
    if (!q_positive(l)) return NO_BOUND;  // chord_terms' reference rounding is the whole span's
    return chords_bound(chord_terms(l), h, q_low(l, k0, k1), q_high(l, k0, k1), rounding);
}

bool fits_16_16(double start, double step, double steps, int32_t size, Wrap wrap) {
    constexpr double LIMIT = 32767;
    double travel = magnitude(step) * steps;
    if (!(magnitude(step) < LIMIT) || !(travel < 1e9)) return false;
    if (wrap == Wrap::Repeat) return (65536 % size == 0) || double(size) + travel < LIMIT;
    return magnitude(start) + travel < LIMIT;
}

void set_up_polygon(const Vertex* vertices, int count, PreparedPolygon* out, Input input) {
    for (PreparedSpans& w : out->walked) w.count = PreparedSpans::NOT_WALKED, w.pixels = 0, w.first = 0;
    out->status = setup_polygon(vertices, count, &out->setup, PLANES_ALL, input);
    out->spread_known = false;
}

void walk_polygon(PreparedPolygon* p, Axis axis, const ClipRect& clip) {
    PreparedSpans& w = p->walked[int(axis)];
    w.count = 0, w.pixels = 0, w.first = 0;
    if (p->status != SetupStatus::Ok) return;
    EdgeWalker walker(p->setup, axis, clip);
    Span span;
    while (walker.next(&span)) {
        if (w.count == PreparedSpans::MAX_SPANS) {
            w.count = -1;
            return;
        }
        w.spans[w.count++] = span;
        w.pixels += span.count;
    }
}

void prepare_polygon(const Vertex* vertices, int count, Axis axis, const ClipRect& clip, PreparedPolygon* out) {
    set_up_polygon(vertices, count, out);
    walk_polygon(out, axis, clip);
}

PolygonSpread& prepared_spread(PreparedPolygon* p, const ClipRect& clip) {
    if (!p->spread_known) polygon_spread(p->setup, clip, &p->spread);
    p->spread_known = true;
    return p->spread;
}

namespace {

// A corner of the spread (PolygonSpread::corner_x, corner_y): relative to the reference vertex,
// where the planes are evaluated.
struct Corner {
    double x = 0, y = 0;
    Corner() = default;
    Corner(const PolygonSpread& p, int i) : x(p.corner_x[i]), y(p.corner_y[i]) {}
};
double terms(const Plane& p, const Corner& c) { return magnitude(p.a0) + magnitude(p.gy * c.y) + magnitude(p.gx * c.x); }
// How much a plane may change over `slack` subpixels in any direction.
double drift(const Plane& p, double slack) { return (magnitude(p.gx) + magnitude(p.gy)) * slack; }
// From the spread's steps (spread_steps): the largest |t'| along axis a where Q is at least q, from
// above, and the smallest footprint where Q is at most q, from below.
double max_step_at(const PolygonSpread& p, int t, int a, double q) { return p.k_max[t][a] / (q * q) * (1 + 1e-9); }
double footprint_at(const PolygonSpread& p, double q) { return p.least_k > 0 ? p.least_k / (q * q) * (1 - 1e-9) : 0.0; }

// Keeps the part of the polygon (n corners in x, y) on one side of the line x = at (axis 0) or
// y = at (axis 1), written to (to_x, to_y): where side > 0, the part at or above it. The cut corners
// by one division each. A convex polygon gains at most one corner a cut; -1 where the corners would
// not fit (a polygon the rounding of earlier cuts made crossed more than twice: the caller keeps
// the vertices).
int cut(const double* x, const double* y, int n, double* to_x, double* to_y, int axis, double at, double side) {
    constexpr int ROOM = PolygonSpread::CORNERS;
    const double* a = axis ? y : x;
    const double* b = axis ? x : y;
    double* ka = axis ? to_y : to_x;
    double* kb = axis ? to_x : to_y;
    int kept = 0;
    bool in_i = (a[0] - at) * side >= 0;
    for (int i = 0; i < n; ++i) {
        const int j = i + 1 < n ? i + 1 : 0;
        const bool in_j = (a[j] - at) * side >= 0;
        if (kept + 2 > ROOM) return -1;
        if (in_i) ka[kept] = a[i], kb[kept++] = b[i];
        if (in_i != in_j) ka[kept] = at, kb[kept++] = b[i] + (at - a[i]) * (b[j] - b[i]) / (a[j] - a[i]);
        in_i = in_j;
    }
    return kept;
}

// The spread's corners: the polygon's vertices where its box lies inside the clip widened by half
// a pixel (the pixel centres drawn lie at least half a pixel inside that), else the polygon cut by
// it. A cut corner is rounded: each cut moves it along its edge by a rounding of the division, at
// most a few units in the last place of the larger coordinate, and a later cut of an edge through
// it keeps it within that of the edge; so every pixel centre drawn lies in the cut polygon or
// within `slack` of it (a pixel centre near a cut corner lies half a pixel inside the cut line).
void spread_corners(const PolygonSetup& s, const ClipRect& clip, PolygonSpread* o) {
    const int64_t lo[2] = {int64_t(clip.x0) * SUBPIXEL_ONE, int64_t(clip.y0) * SUBPIXEL_ONE};
    const int64_t hi[2] = {int64_t(clip.x1) * SUBPIXEL_ONE, int64_t(clip.y1) * SUBPIXEL_ONE};
    auto vertices = [&] {
        o->corners = s.edge_count;
        o->slack = 0;
        for (int i = 0; i < s.edge_count; ++i) o->corner_x[i] = double(s.edges[i].px - s.ref_x), o->corner_y[i] = double(s.edges[i].py - s.ref_y);
    };
    vertices();
    if (box_in_clip(s, clip)) return;
    const double ref[2] = {double(s.ref_x), double(s.ref_y)};
    const int64_t box_lo[2] = {s.min_x, s.min_y}, box_hi[2] = {s.max_x, s.max_y};
    // (from one buffer to the other: the corners' and these; a side of the clip the box lies
    // strictly inside cuts nothing, every corner on its side by a whole subpixel less a few units
    // in the last place, and is skipped)
    double other_x[PolygonSpread::CORNERS], other_y[PolygonSpread::CORNERS];
    double *from_x = o->corner_x, *from_y = o->corner_y, *to_x = other_x, *to_y = other_y;
    for (int axis = 0; axis < 2 && o->corners > 0; ++axis)
        for (int end = 0; end < 2 && o->corners > 0; ++end) {
            if (end ? box_hi[axis] < hi[axis] : box_lo[axis] > lo[axis]) continue;
            o->corners = cut(from_x, from_y, o->corners, to_x, to_y, axis, double(end ? hi[axis] : lo[axis]) - ref[axis], end ? -1 : 1);
            if (o->corners < 0) return vertices();
            double *x = from_x, *y = from_y;
            from_x = to_x, from_y = to_y, to_x = x, to_y = y;
        }
    if (from_x != o->corner_x)
        for (int i = 0; i < o->corners; ++i) o->corner_x[i] = from_x[i], o->corner_y[i] = from_y[i];
    double far = 0;
    for (int i = 0; i < o->corners; ++i) far = larger(far, magnitude(o->corner_x[i]) + magnitude(o->corner_y[i]));
    for (int i = 0; i < s.edge_count; ++i) far = larger(far, magnitude(double(s.edges[i].px - s.ref_x)) + magnitude(double(s.edges[i].py - s.ref_y)));
    o->slack = 64 * EPSILON * far;
}

}  // namespace

void polygon_spread(const PolygonSetup& s, const ClipRect& clip, PolygonSpread* out) {
    PolygonSpread& o = *out;
    spread_corners(s, clip, &o);
    const Plane* exact[2] = {&s.pu, &s.pv};
    const Plane* affine[2] = {&s.u, &s.v};
    Corner far;  // the largest |x| and |y| of the corners: each plane's terms at most |a0| + |gx| |x| + |gy| |y| there
    o.q_min = o.q_max = 0;  // (no corner: nothing drawn, and no bound from the spread)
    for (int t = 0; t < 2; ++t) o.t_min[t] = o.t_max[t] = o.residual[t] = o.affine_abs[t] = 0;
    for (int i = 0; i < o.corners; ++i) {
        const Corner c(o, i);
        const double q = s.q.at(c.x, c.y);
        o.q_min = i ? (q < o.q_min ? q : o.q_min) : q;
        o.q_max = i ? larger(q, o.q_max) : q;
        far.x = larger(far.x, magnitude(c.x)), far.y = larger(far.y, magnitude(c.y));
        for (int t = 0; t < 2; ++t) {
            const double e = exact[t]->at(c.x, c.y) / q, l = affine[t]->at(c.x, c.y);
            o.t_min[t] = i ? (e < o.t_min[t] ? e : o.t_min[t]) : e;
            o.t_max[t] = i ? larger(e, o.t_max[t]) : e;
            o.residual[t] = i ? larger(o.residual[t], magnitude(l - e)) : magnitude(l - e);
            o.affine_abs[t] = i ? larger(o.affine_abs[t], magnitude(l)) : magnitude(l);
        }
    }
    const double scale_q = terms(s.q, far), scale_p[2] = {terms(s.pu, far), terms(s.pv, far)}, scale_l[2] = {terms(s.u, far), terms(s.v, far)};
    // Q's extremes widened by its rounding (a Q_min at or below 0 after that: no bound from the
    // spread); each vertex value within the reference's rounding of itself, and L within its terms'
    // (and by what the corners' slack may do to it)
    const double q_err = 8 * EPSILON * scale_q + drift(s.q, o.slack);
    o.q_min -= q_err, o.q_max += q_err;
    for (int t = 0; t < 2; ++t) {
        double moved = 0, l_moved = 0;  // what the slack may do to t and L (nothing: the polygon uncut)
        if (o.slack > 0) {
            moved = (drift(*exact[t], o.slack) + larger(magnitude(o.t_min[t]), magnitude(o.t_max[t])) * drift(s.q, o.slack)) / o.q_min;
            l_moved = drift(*affine[t], o.slack);
            o.t_min[t] -= moved, o.t_max[t] += moved;
            o.affine_abs[t] += l_moved;
        }
        o.t_abs[t] = larger(magnitude(o.t_min[t]), magnitude(o.t_max[t]));
        o.reference[t] = 2 * (4 * EPSILON * (scale_p[t] + o.t_abs[t] * scale_q) / o.q_min + 2 * EPSILON * o.t_abs[t]);
        o.evaluation[t] = o.reference[t] + 4 * EPSILON * scale_l[t] + moved + l_moved;
    }
    // pixels whose centres lie in the box (the polygon's, inside the clip's): at most its extent
    // plus one along each axis, each between the floors of the box's ends
    const double one = double(SUBPIXEL_ONE);
    auto inside = [](int64_t v, int32_t lo, int32_t hi) {
        const int64_t l = int64_t(lo) * SUBPIXEL_ONE, h = int64_t(hi) * SUBPIXEL_ONE;
        return v < l ? l : v > h ? h : v;
    };
    const int64_t min_x = inside(s.min_x, clip.x0, clip.x1), max_x = inside(s.max_x, clip.x0, clip.x1);
    const int64_t min_y = inside(s.min_y, clip.y0, clip.y1), max_y = inside(s.max_y, clip.y0, clip.y1);
    o.lines[0] = double(max_x - min_x) / one + 1;
    o.lines[1] = double(max_y - min_y) / one + 1;
    // (floors by an arithmetic shift: SUBPIXEL_ONE is 2^SUBPIXEL_BITS)
    const double x_lo = double(min_x >> SUBPIXEL_BITS), x_hi = double(max_x >> SUBPIXEL_BITS);
    const double y_lo = double(min_y >> SUBPIXEL_BITS), y_hi = double(max_y >> SUBPIXEL_BITS);
    const double ax = s.u_fx.x0, ay = s.u_fx.y0;
    o.reach = larger(magnitude(x_lo - ax), magnitude(x_hi - ax)) + larger(magnitude(y_lo - ay), magnitude(y_hi - ay));
    o.steps_known = false;
}

void spread_steps(const PolygonSetup& s, PolygonSpread* p) {
    PolygonSpread& o = *p;
    if (o.steps_known) return;
    o.steps_known = true;
    const double one = double(SUBPIXEL_ONE);
    const Plane* exact[2] = {&s.pu, &s.pv};
    // K = (P_a Q - P Q_a) per pixel is linear, and K_x does not change with x nor K_y with y:
    // K_x = (p_x q_0 - p_0 q_x) + (p_x q_y - p_y q_x) y, K_y = (p_y q_0 - p_0 q_y) + (p_y q_x - p_x q_y) x,
    // so its extremes over the polygon are at the corners' least and largest y (x). Each evaluated
    // so within 2 eps of its terms' magnitudes at the farthest corner (two products and their
    // difference twice, a product and a sum: at most 4 units of 2^-53 of them; counted 4 eps), and
    // within what the slack may do to P and Q (|P_a| and |Q_a| times their drift)
    double lo_c[2] = {0, 0}, hi_c[2] = {0, 0}, far[2] = {0, 0};  // [0]: x, [1]: y
    for (int i = 0; i < o.corners; ++i) {
        const double c[2] = {o.corner_x[i], o.corner_y[i]};
        for (int d = 0; d < 2; ++d) {
            lo_c[d] = i ? (c[d] < lo_c[d] ? c[d] : lo_c[d]) : c[d], hi_c[d] = i ? larger(c[d], hi_c[d]) : c[d];
            far[d] = larger(far[d], magnitude(c[d]));
        }
    }
    double lo[2][2] = {}, hi[2][2] = {}, err[2][2] = {};
    const double moved_q = drift(s.q, o.slack), moved_p[2] = {drift(s.pu, o.slack), drift(s.pv, o.slack)};  // (the slack's)
    for (int t = 0; t < 2; ++t) {
        const Plane& pt = *exact[t];
        for (int a = 0; a < 2; ++a) {
            const double pa = a ? pt.gy : pt.gx, qa = a ? s.q.gy : s.q.gx, pb = a ? pt.gx : pt.gy, qb = a ? s.q.gx : s.q.gy;
            const double c0 = pa * s.q.a0 - pt.a0 * qa, c1 = pa * qb - pb * qa;  // K_a = c0 + c1 (y for a = x, x for a = y)
            const double k0 = (c0 + c1 * lo_c[1 - a]) * one, k1 = (c0 + c1 * hi_c[1 - a]) * one;
            lo[t][a] = k0 < k1 ? k0 : k1, hi[t][a] = larger(k0, k1);
            err[t][a] = (magnitude(pa * s.q.a0) + magnitude(pt.a0 * qa) + (magnitude(pa * qb) + magnitude(pb * qa)) * far[1 - a]) * 4 * EPSILON * one +
                        (magnitude(pa) * moved_q + magnitude(qa) * moved_p[t]) * one;
        }
    }
    double least_k = 0;  // the largest over t and a of the least |K| over the polygon, from below
    for (int t = 0; t < 2; ++t)
        for (int a = 0; a < 2; ++a) {
            o.k_max[t][a] = (larger(magnitude(lo[t][a]), magnitude(hi[t][a])) + err[t][a]) * (1 + 1e-9);
            // the least |K| over the polygon: 0 where K changes sign (or may, within its rounding)
            const double least = lo[t][a] > 0 ? lo[t][a] : hi[t][a] < 0 ? -hi[t][a] : 0.0;
            least_k = larger(least_k, (least - err[t][a]) * (1 - 1e-9));
        }
    o.least_k = least_k > 0 && o.q_min > 0 ? least_k : 0.0;
    o.footprint = footprint_at(o, o.q_max);
}

double perspective_share(double q_lo, double q_hi) {
    // sum (l_i - m_i) t_i with sum (l_i - m_i) = 0 is at most (t_max - t_min) times the sum of
    // its positive weights, half of sum |l_i - m_i| = sum l_i |Q - Q_i| / Q: half the mean absolute
    // deviation of a distribution on [a, b] with mean Q, over Q. (x - Q)+ is convex, so below its
    // chord over [a, b]: the mean deviation is at most 2 (Q - a)(b - Q) / (b - a), and
    // (Q - a)(b - Q) / Q is largest at Q = sqrt(ab), where it is (sqrt(b) - sqrt(a))^2. So the share
    // is at most (b - a) / (sqrt(a) + sqrt(b))^2, and (sqrt(a) + sqrt(b))^2 >= 3a + b.
    return (q_hi - q_lo) / (3 * q_lo + q_hi);
}

void spread_planes_deviation(const PolygonSpread& p, double rounding, double d[2]) {
    for (int t = 0; t < 2; ++t) {
        // L - P/Q at a point of the polygon, with weights l_i of the vertices (sum 1) and
        // m_i = l_i Q_i / Q (also): sum l_i (L_i - t_i) + sum (l_i - m_i) t_i, the first at most
        // the largest residual, the second at most (t_max - t_min) times perspective_share
        const double spread = (p.t_max[t] - p.t_min[t] + 2 * p.evaluation[t]) * perspective_share(p.q_min, p.q_max);
        d[t] = (p.residual[t] + 2 * p.evaluation[t] + spread) * (1 + 1e-9) + rounding + 2 * p.reference[t];
    }
}

double spread_planes_bound(PolygonSpread& p, const PolygonSetup& s, double rounding, double budget) {
    if (!(p.q_min > 0)) return NO_BOUND;
    double d[2];
    spread_planes_deviation(p, rounding, d);
    const double texels = footprint_error(d[0], d[1], 1);  // a bound already: max(1, F) is at least 1
    if (texels == 0 || (budget >= 0 && texels <= budget)) return texels;
    // Within the budget only over a footprint of texels / budget everywhere; the least footprint
    // spread_steps finds is at most the footprint at the reference vertex (|K| there at least the
    // least |K|, Q there at most the largest), where that is one of the spread's corners (the
    // polygon uncut: no slack). Where that one is below it, the bound is above the budget whatever
    // the steps say: asked so, stop here (a value above the budget, as settled).
    if (budget > 0 && p.slack == 0) {
        const double at_vertex = texel_footprint(s, 0, 0) * (1 + 1e-6) + 1e-9;
        if (at_vertex < texels / budget) return texels / larger(1.0, at_vertex);
    }
    spread_steps(s, &p);
    return footprint_error(d[0], d[1], p.footprint);
}

EnvelopeBound envelope_bound(const TriangleEnvelope& e) {
    EnvelopeBound b;
    b.envelope = e;
    envelope_deviation(e, b.deviation);
    b.footprint = footprint_error(b.deviation[0], b.deviation[1], 1);
    return b;
}

// The derivation, step by step, is docs/auto.md's ("The object's envelope"); each quantity
// below bounds the one of polygon_spread named beside it, q ones in units of the least 1/w at a
// corner (q_lo). A plane through three values of magnitude at most m and range at most r, on a
// triangle that passes the guards (kappa = ENVELOPE_CONDITION): |gx| W + |gy| H <= kappa r; its
// terms (terms()) are at most (m + kappa r)(1 + 8 eps), its value at a corner at most
// eps (3 m + 8 kappa r) from the value given there.
void envelope_deviation(const TriangleEnvelope& e, double d[2]) {
    const double eps = EPSILON, kappa = ENVELOPE_CONDITION;
    if (!(e.depth_ratio >= 0 && e.depth_ratio < 1)) {
        d[0] = d[1] = NO_BOUND;
        return;
    }
    auto scale = [&](double m, double r) { return (m + kappa * r) * (1 + 8 * eps); };
    auto evaluated = [&](double m, double r) { return eps * (3 * m + 8 * kappa * r); };
    const double rho = (1 + e.depth_ratio) * (1 + 3 * eps) - 1;  // of the rounded 1/w
    const double q_eval = evaluated(1 + rho, rho), q_scale = scale(1 + rho, rho);
    const double q_off = q_eval + 8.1 * eps * q_scale;                  // Q at a corner, widened by q_err
    const double ratio = (rho + 2 * q_off) / (1 - q_off);              // (q_max - q_min) / q_min
    const double reach = double(ENVELOPE_REACH) + 2, rounding = (1 + reach) * HALF_ULP_16_16;
    for (int t = 0; t < 2; ++t) {
        const double a = e.texel_abs[t], range = e.texel_range[t];
        const double p_abs = a * (1 + rho) * (1 + 2 * eps), p_range = range * (1 + rho) + a * rho + 5 * eps * p_abs;  // u/w
        const double p_eval = evaluated(p_abs, p_range), p_scale = scale(p_abs, p_range);
        const double exact = (p_eval + 1.01 * a * q_eval) / (1 - q_eval) + 3.2 * eps * a;  // P/Q at a corner against u
        const double t_abs = a + exact;
        const double reference = 2 * (4 * eps * (p_scale + t_abs * q_scale) / (1 - q_off) + 2 * eps * t_abs);
        const double evaluation = reference + 4 * eps * scale(a, range);
        const double residual = (evaluated(a, range) + exact) * (1 + eps);
        const double spread = (range + 2 * exact + 2 * evaluation) * perspective_share(1, 1 + ratio);
        d[t] = ((residual + 2 * evaluation + spread) * (1 + 1e-9) + rounding + 2 * reference) * (1 + 0x1p-30);
    }
}

double spread_max_step(PolygonSpread& p, const PolygonSetup& s, int t, Axis axis) {
    spread_steps(s, &p);
    return max_step_at(p, t, axis == Axis::Rows ? 0 : 1, p.q_min);
}

double relative_chords_bound(double x, double r) {
    if (!(x >= 0 && r >= 0 && x + r < 1e15)) return NO_BOUND;
    x *= 1 + 1e-9, r *= 1 + 1e-9;  // (the margins: this bound's own rounding)
    const double n0 = footprint_error(x + r * (1 + 1e-15), 0, 1);  // ceil(X + r): at a footprint up to 1
    // above a footprint of 1, a whole texel more comes only at F > (n0 - r) / X
    return x > 0 ? larger(n0, (n0 + 1) * x / (n0 - r) * (1 + 1e-9)) : n0;
}

double spread_chords_bound(PolygonSpread& p, const PolygonSetup& s, Axis axis, double h, double rounding, double budget) {
    if (!(p.q_min > 0)) return NO_BOUND;
    const double qa = magnitude(axis == Axis::Rows ? s.q.gx : s.q.gy) * double(SUBPIXEL_ONE);
    const int a = axis == Axis::Rows ? 0 : 1;
    // each pixel's deviation within X times its own step along the axis, plus the rounding: no
    // steps to compute
    const double relative = relative_chords_bound(h * h * qa / (4 * p.q_min), rounding + 2 * larger(p.reference[0], p.reference[1]));
    if (budget >= 0 && relative <= budget) return relative;
    // the chords' texel deviations where Q is at least q_lo (h^2 / 8 of the largest |t''| =
    // 2 |K| |Q_a| / Q^3), over the footprint where Q is at most q_hi
    auto over = [&](double q_lo, double q_hi) {
        double d[2];
        for (int t = 0; t < 2; ++t) {
            const double curvature = max_step_at(p, t, a, q_lo) * 2 * qa / q_lo;
            d[t] = h * h / 8 * curvature * (1 + 1e-9) + rounding + 2 * p.reference[t];
        }
        return footprint_error(d[0], d[1], footprint_at(p, q_hi));
    };
    spread_steps(s, &p);
    const double whole = over(p.q_min, p.q_max);
    if ((budget >= 0 && whole <= budget) || p.q_max <= 2 * p.q_min) return whole < relative ? whole : relative;  // (one band: the whole)
    // By bands of Q (each twice the last): a pixel where Q lies in [q_i, q_i+1] is on a chord whose
    // ends are drawn pixels at most h away along the axis, so Q along the chord is at least
    // max(Q_min, q_i - h |Q_a|); its footprint at least the least |K| over q_i+1^2. The largest over
    // the bands, so that the curvature and the footprint are never taken at opposite ends of the
    // polygon's depth (on a wall 50 times deeper at one end than the other, 2500 times looser).
    double worst = 0;
    for (double q_i = p.q_min; q_i < p.q_max && worst < whole;) {
        const double next = q_i * 2 < p.q_max ? q_i * 2 : p.q_max, reach = q_i - h * qa;
        worst = larger(worst, over(reach > p.q_min ? reach : p.q_min, next));
        q_i = next;
    }
    worst = worst < whole ? worst : whole;
    return worst < relative ? worst : relative;
}

void affine_lines(const PolygonSetup& s, Axis axis, const Span& span, double* a, double* step) {
    double x = span_centre_x(s, span.x), y = span_centre_y(s, span.y);
    const Plane* plane[2] = {&s.u, &s.v};
    for (int t = 0; t < 2; ++t) {
        a[t] = plane[t]->at(x, y);
        step[t] = (axis == Axis::Rows ? plane[t]->gx : plane[t]->gy) * double(SUBPIXEL_ONE);
    }
}

const PolygonSetup* exact_setup(const BoundContext& c, const Vertex* vertices, int count, PolygonSetup* own, ErrorBound* b) {
    b->draws = true;
    b->footprint = NO_BOUND;
    if (c.whole_only) return nullptr;
    if (c.prepared && c.prepared->status == SetupStatus::Ok) return &c.prepared->setup;
    return setup_polygon(vertices, count, own, PLANES_PERSPECTIVE) == SetupStatus::Ok ? own : nullptr;
}

double drawn_line_bound(const PolygonSetup& s, Axis axis, const Span& span, const double* a, const double* b, double extra) {
    const SpanLine l = span_line(s, axis, span);
    const double last = double(span.count - 1);
    if (!(l.q0 > 0) || !(l.q0 + l.qm * last > 0)) return NO_BOUND;
    double worst = 0;
    for (double k0 = 0; k0 <= last; k0 += BOUND_PIECE) worst = larger(worst, lines_bound(l, a, b, k0, k0 + BOUND_PIECE - 1 < last ? k0 + BOUND_PIECE - 1 : last, extra));
    return worst;
}

bool within_border(double a, double b, double last, double size, double* extra) {
    const double end = a + b * last, lo = a < end ? a : end, hi = larger(a, end);
    if (lo < 0 || hi >= size) *extra = 1;
    return lo >= -1 && hi < size + 1;
}

bool setup_takes(const BoundContext& c, const Vertex* vertices, int count) {
    if (c.prepared) return c.prepared->status == SetupStatus::Ok;
    PolygonSetup s;
    return setup_polygon(vertices, count, &s, PLANES_NONE) == SetupStatus::Ok;
}

ErrorBound unbounded(const BoundContext& c, const Vertex* vertices, int count) {
    ErrorBound b;
    (void)vertices, (void)count;  // its own conversion decides (a sliver our setup finds degenerate may round to a triangle)
    b.draws = mapper_accepts(c.mapper, c.tex);
    b.exact_coverage = c.mapper.guarantee.exact_coverage;
    b.footprint = NO_BOUND;
    return b;
}

double footprint_error(double du, double dv, double footprint) {
    auto texels = [](double d) {  // ceil(d) for d >= 0, without libm
        if (d <= 0) return 0.0;
        if (d >= 1e15) return d;  // beyond any budget; and int64_t would not hold it
        double whole = double(int64_t(d));
        return whole < d ? whole + 1 : whole;
    };
    double e = larger(texels(du), texels(dv));
    return e / larger(1.0, footprint);
}

#if defined(MODEXLAB_OFFSETS)
// The envelope's limits, for the fast mappers' enveloped triangle (asm_offsets.h).
void bound_offsets() {
    ASM_FIELDS(ENV, EnvelopeLimits, area2, extent_x, extent_y)
    ASM_CONSTANT(ENVELOPE_REACH_SUBPIXELS, ENVELOPE_REACH * SUBPIXEL_ONE);
}
#endif

}  // namespace raster
