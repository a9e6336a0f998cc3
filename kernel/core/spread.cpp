// The polygon's spread from its corners, and the bounds over the whole polygon taken from it.
#include "kernel/core/spread.h"

#include "kernel/core/footprint.h"

namespace raster {

namespace {

constexpr double EPSILON = 2.220446049250313e-16;  // 2^-52

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

}  // namespace raster
