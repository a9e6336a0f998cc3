// The polygon's spread: the extremes over the whole polygon at once, from its vertices, and the
// planes' and chords' bounds over the polygon taken from them.
#pragma once

#include "kernel/core/setup.h"
#include "kernel/core/walk.h"

namespace raster {

// The whole polygon at once (docs/bounds.md, "The whole polygon at once"): the extremes over it of
// what the span bounds take span by span. Linear functions (Q, the affine planes, K below), P/Q
// (monotone along any line where Q > 0) and sums of magnitudes of linear terms take their extremes
// over a convex polygon at its vertices, so all of it comes from the vertices: the polygon's own,
// or, where it reaches outside the clip, those of its part that holds every pixel drawn (a polygon
// far larger than the screen says nothing useful from its own). Looser than span by span, and
// cheap: auto asks it first and walks only the polygons it does not settle.
struct PolygonSpread {
    double q_min, q_max;                 // Q
    double t_min[2], t_max[2], t_abs[2]; // the exact u and v (t = 0, 1): least, largest, largest magnitude
    double residual[2];                  // |L - P/Q| at the vertices, L the affine planes (0 at a triangle's)
    double affine_abs[2];                // |L|
    double evaluation[2];                // how far these vertex values may be off: their own rounding
    double reference[2];                 // the reference's own rounding at any pixel (exact_rounding)
    double lines[2];                     // the most pixels a row (a = 0) or a column (a = 1) can have
    double reach;                        // the most |x - x0| + |y - y0| of a pixel from the 16.16 anchor
    // the corners all this is taken over (relative to the reference vertex, subpixels): the
    // polygon's, or, where it reaches outside the clip, those of its part inside the clip widened
    // by half a pixel, the cut ones within `slack` subpixels of where they should be (0: uncut)
    static constexpr int CORNERS = MAX_POLYGON_VERTICES + 4;  // (four cuts of a convex polygon)
    double corner_x[CORNERS], corner_y[CORNERS];
    int corners;
    double slack;
    // the steps, when a bound first needs them (spread_steps)
    bool steps_known = false;
    double k_max[2][2];                  // |K| = |P_a Q - P Q_a| per pixel, for t along axis a (0: x, 1: y)
    double footprint;                    // the smallest footprint over the polygon, from below
    double least_k;                      // its numerator: the largest least |K| (footprint = least_k / Q_max^2)
};
void polygon_spread(const PolygonSetup& s, const ClipRect& clip, PolygonSpread* out);
void spread_steps(const PolygonSetup& s, PolygonSpread* p);

// The deviation bound over the polygon of a mapper whose u and v follow the affine planes to within
// `rounding` texels, and of one that follows chords between exact points at most h pixels apart
// along the axis, each within `rounding`: footprint errors (before fits_16_16, the mapper's own).
// With a budget (at or above 0), the planes' bound divides by the footprint only where the texels
// alone are above it.
double spread_planes_bound(PolygonSpread& p, const PolygonSetup& s, double rounding, double budget);
// How far the exact mapping can leave a plane through its values at the corners, as a share of
// their range, over a polygon where Q lies in [q_lo, q_hi] (0 < q_lo <= q_hi): (q_hi - q_lo) /
// (3 q_lo + q_hi), about a quarter of the relative change of Q (docs/bounds.md, "Planes").
inline double perspective_share(double q_lo, double q_hi) {
    // sum (l_i - m_i) t_i with sum (l_i - m_i) = 0 is at most (t_max - t_min) times the sum of
    // its positive weights, half of sum |l_i - m_i| = sum l_i |Q - Q_i| / Q: half the mean absolute
    // deviation of a distribution on [a, b] with mean Q, over Q. (x - Q)+ is convex, so below its
    // chord over [a, b]: the mean deviation is at most 2 (Q - a)(b - Q) / (b - a), and
    // (Q - a)(b - Q) / Q is largest at Q = sqrt(ab), where it is (sqrt(b) - sqrt(a))^2. So the share
    // is at most (b - a) / (sqrt(a) + sqrt(b))^2, and (sqrt(a) + sqrt(b))^2 >= 3a + b.
    return (q_hi - q_lo) / (3 * q_lo + q_hi);
}
// Its texel deviations d[t] before the footprint (what spread_planes_bound divides).
void spread_planes_deviation(const PolygonSpread& p, double rounding, double d[2]);
// The chords' bound relative to each pixel's own step (docs/bounds.md, "Chords, relative to the step"): where every
// pixel's deviation from the exact mapping is within X times its own texel step along the axis plus
// r texels, its footprint error is at most max(n0, (n0 + 1) X / (n0 - r)), n0 = ceil(X + r),
// whatever its footprint. NO_BOUND where X or r is not finite and at least 0.
double relative_chords_bound(double x, double r);
// The least of that (X = h^2 |Q_a| / (4 Q_min)), which needs no steps and settles it alone where
// within a budget (at or above 0), and of the bound from the steps, which goes by bands of Q only
// where the whole polygon's is above the budget.
double spread_chords_bound(PolygonSpread& p, const PolygonSetup& s, Axis axis, double h, double rounding, double budget);
// The largest |t'| along the axis over the polygon, from above.
double spread_max_step(PolygonSpread& p, const PolygonSetup& s, int t, Axis axis);

}  // namespace raster
