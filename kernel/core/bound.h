// Error bounds before drawing (docs/bounds.md): how far, in footprints, a mapper's
// texel can be from the reference's on a polygon, from what setup knows. The pieces the mappers'
// own bound functions are built from: spans, the deviation of a line from the exact mapping along
// them, the footprint along them, and the step from a coordinate error to a footprint error.
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"

namespace raster {

// The pieces a span's bound is taken over: a deviation and the footprint it is divided by belong
// to the same few pixels, not the whole span.
constexpr double BOUND_PIECE = 16;


// No bound can be given (a classic's arithmetic, an overflow): larger than any budget.
constexpr double NO_BOUND = 1e30;

// What a mapper promises for one polygon before drawing it.
struct ErrorBound {
    bool draws = false;           // whether the mapper draws the polygon (false: it refuses it, or it
                                  // is degenerate); for `unbounded` mappers: whether it may
    bool exact_coverage = false;  // it draws exactly the pixels the reference covers
    double footprint = 0;         // max footprint error on every pixel it draws (NO_BOUND: none)
};

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
double perspective_share(double q_lo, double q_hi);
// Its texel deviations d[t] before the footprint (what spread_planes_bound divides).
void spread_planes_deviation(const PolygonSpread& p, double rounding, double d[2]);

// The object's envelope (docs/auto.md, "The object's envelope"): what holds for every uncut
// triangle of an object in a frame, from the object (its mesh measured once, its nearest depth in
// the frame), so that the planes' bound above needs no spread per triangle. With the guards below,
// checked on the triangle's setup, every field of its spread is bounded a priori.
struct TriangleEnvelope {
    double texel_abs[2];    // A_t: the largest |u|, |v| (texels) at a corner, from above
    double texel_range[2];  // T_t: the largest range of u, v over a triangle's corners, from above
    double depth_ratio;     // rho: the largest w_max / w_min - 1 over a triangle's corners, from above
};
// The guards, on a triangle's setup (affine planes): its box of W x H subpixels and doubled area D
// (subpixels squared) have W + H <= ENVELOPE_REACH pixels (how far its 16.16 planes step from
// their anchor) and 4 W H <= ENVELOPE_CONDITION D (how badly its planes can be conditioned), and
// its 16.16 steps are within 32766 texels a pixel (so that planes_fit_16_16 holds).
constexpr double ENVELOPE_CONDITION = 65536;
constexpr int32_t ENVELOPE_REACH = 1024;
// (Inline, in integers, once a triangle of the mesh: the sides' sum within the reach first, so
// that each side is below 2^18 subpixels and W H, one 32-bit multiply, below 2^36; a D of 2^22 or
// more passes the second at once, and a smaller one times 16384 cannot overflow.)
inline bool envelope_guards(const PolygonSetup& s) {
    if (s.edge_count != 3) return false;
    // (the box within setup's range: its sides in 32 bits, from the low halves)
    const uint32_t w = uint32_t(s.max_x) - uint32_t(s.min_x), h = uint32_t(s.max_y) - uint32_t(s.min_y);
    if (w + h > uint32_t(ENVELOPE_REACH * SUBPIXEL_ONE) || w + h < w) return false;
    static_assert(ENVELOPE_CONDITION == 65536, "4 W H <= 65536 D is W H <= 16384 D");
    if ((s.area2 >> 22) == 0 && uint64_t(w) * h > uint64_t(uint32_t(s.area2)) << 14) return false;
    // the 16.16 steps within +-32766 texels (they saturate at +-2^31): the steps within 32767
    constexpr uint32_t STEP = 32766u << 16;
    auto fits = [](int32_t raw) { return uint32_t(raw) + STEP <= 2 * STEP; };
    return fits(s.u_fx.dx) && fits(s.u_fx.dy) && fits(s.v_fx.dx) && fits(s.v_fx.dy);
}
// What auto's envelope takes besides the guards (AutoPlan::enveloped_area2, enveloped_extent): the
// largest doubled area (subpixels squared) and the largest extents of the box (subpixels; INT32_MAX:
// unlimited) of a triangle it draws.
struct EnvelopeLimits {
    int64_t area2;
    int32_t extent_x, extent_y;
};
// The guards and the limits: the triangles auto's envelope draws (draw_enveloped; the drivers
// given DrawContext::envelope check it, fast_triangle_enveloped_asm in NASM).
inline bool within_envelope(const PolygonSetup& s, const EnvelopeLimits& e) {
    return envelope_guards(s) && s.area2 <= e.area2 && int32_t(s.max_y - s.min_y) <= e.extent_y && int32_t(s.max_x - s.min_x) <= e.extent_x;
}
// Upper bounds on spread_planes_deviation's d[t] for a triangle within the envelope that passes
// the guards, the planes' 16.16 rounding at the largest reach the guards allow included: the
// deviations of fast-affine's and fast-columns' coordinates from the reference's (NO_BOUND where
// rho is not finite and positive or at least 1).
void envelope_deviation(const TriangleEnvelope& e, double d[2]);
// What the envelope proves for an object in a frame: its deviations (envelope_deviation) and the
// bound auto takes, in footprints at a footprint of 1 (NO_BOUND: none).
struct EnvelopeBound {
    TriangleEnvelope envelope;
    double deviation[2];
    double footprint = NO_BOUND;
};
EnvelopeBound envelope_bound(const TriangleEnvelope& e);
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

// A polygon set up (every plane) once, for asking several mappers' bounds in turn (auto): the
// bounds take its spread, and its spans along either walker (walked when a bound first needs them)
// rather than setting up and walking again, from `first` on (the span that settled the last bound
// above its budget: the likeliest to settle the next one).
struct PreparedSpans {
    static constexpr int32_t MAX_SPANS = 512;  // a screen's rows or columns, and more
    static constexpr int32_t NOT_WALKED = -2;
    // spans; NOT_WALKED: not yet; -1: more than MAX_SPANS, the bounds walk the polygon themselves
    int32_t count = NOT_WALKED;
    int32_t pixels = 0;
    int32_t first = 0;
    Span spans[MAX_SPANS];
};
struct PreparedPolygon {
    SetupStatus status = SetupStatus::Degenerate;
    PolygonSetup setup;
    bool spread_known = false;
    PolygonSpread spread;
    PreparedSpans walked[2];  // [Axis]
};
// Sets the polygon up, not walked (`input`: as setup_polygon takes it).
void set_up_polygon(const Vertex* vertices, int count, PreparedPolygon* out, Input input = Input::Any);
// Walks it along the axis.
void walk_polygon(PreparedPolygon* p, Axis axis, const ClipRect& clip);
// Both.
void prepare_polygon(const Vertex* vertices, int count, Axis axis, const ClipRect& clip, PreparedPolygon* out);
// Its spread inside the clip, computed once (the clip is the same for every bound asked of it).
PolygonSpread& prepared_spread(PreparedPolygon* p, const ClipRect& clip);

struct BoundContext {
    const Mapper& mapper;
    const Texture& tex;  // with the copies prepare_texture builds
    Axis axis;           // the walker the mapper uses
    ClipRect clip;
    // What the caller asks (auto: its budget). Below 0: the tightest bound, every span piece by
    // piece. At or above 0: only whether the bound is within it, cheaply: a span whose coarse
    // bound (the whole span as one piece) is within it is not taken piece by piece, and once the
    // bound is above it the evaluation stops (the footprint returned is then only known to be
    // above the budget, not the polygon's bound).
    double budget = -1;
    PreparedPolygon* prepared = nullptr;  // the polygon set up and walked already, or nullptr
    // With a budget: the whole polygon at once only (from its vertices, never walked); where that
    // is not within the budget, NO_BOUND.
    bool whole_only = false;
    bool settled(double worst) const { return budget >= 0 && worst > budget; }
};

// Along one span: the line's pixels k = 0..count-1 at minor coordinate m = m0 + k (pixel centres),
// with the exact mapping t(m) = P(m) / Q(m) for t = u and v, P and Q linear in m.
struct SpanLine {
    double q0, qm;          // Q at the span's first pixel centre, and per pixel along it
    double p0[2], pm[2];    // P for u and v, likewise
    double scale_p[2];      // magnitudes of the terms P was evaluated from (rounding: exact_rounding)
    double scale_q;
    int32_t count;
};
SpanLine span_line(const PolygonSetup& s, Axis axis, const Span& span);

// The exact mapping at pixel k of the span, u (t = 0) or v (t = 1).
inline double span_exact(const SpanLine& l, int t, double k) { return (l.p0[t] + l.pm[t] * k) / (l.q0 + l.qm * k); }

// The largest |a + b k - t(k)| over k in [k0, k1] (continuous): the line against the exact mapping,
// at the ends and where the derivative of (line * Q - P) / Q vanishes.
double line_deviation(const SpanLine& l, int t, double a, double b, double k0, double k1);

// An upper bound on |t_reference - t_exact| at any pixel of the span: the double rounding of the
// reference's own evaluation (and of a mapper's exact points, computed the same way).
double exact_rounding(const SpanLine& l, int t);

// The smallest footprint over k in [k0, k1], from below: the step along the span alone, which is
// |P' Q - P Q'| / Q^2 (the numerator constant along the span), smallest where Q is largest.
double min_footprint_along(const SpanLine& l, double k0, double k1);

// The bound over pixels [k0, k1] of a span on which the mapper's u and v follow the lines
// a[t] + b[t] k to within `rounding` texels: each line's deviation from the exact mapping, the
// reference's own rounding, the rounding, as a footprint error over the smallest footprint there.
double lines_bound(const SpanLine& l, const double* a, const double* b, double k0, double k1, double rounding);

// The same over pixels k0..k1 where u and v follow chords between exact points at most h pixels
// apart, every chord lying within k0..k1 (each within `rounding`): a chord's deviation is at most
// h^2 / 8 of the largest |t''| between its ends, and t'' = -2 K Q' / Q^3 along the span
// (K = P' Q - P Q', constant), largest where Q is smallest.
double chords_bound(const SpanLine& l, double h, double k0, double k1, double rounding);
// The same in two steps: what is constant along the span, then a stretch of it with Q between
// q_lo and q_hi (persp-adaptive-B asks it for every run it tries).
struct ChordTerms {
    double k_high[2];     // |K| for u and v, from above
    double least_k;       // the larger |K|, from below (the footprint's numerator)
    double reference[2];  // the reference's rounding, counted twice
    double qm;            // |Q'|
};
ChordTerms chord_terms(const SpanLine& l);
double chords_bound(const ChordTerms& c, double h, double q_lo, double q_hi, double rounding);
// The largest |t'| over pixels [k0, k1], from above: |K| / Q^2 where Q is smallest.
double max_step_along(const SpanLine& l, int t, double k0, double k1);

// The bound over pixels k0..k1 of a span (k0 a multiple of `length`) from the bounds of its
// pieces: piece(a, b) bounds pixels a..b, pieces of `length` pixels from k0. With a budget
// (BoundContext::budget), first the whole range as one piece (`coarse(k0, k1)`, valid over any
// range of whole pieces), and where that is above the budget its halves, down to the pieces.
template <typename Coarse, typename Piece>
double span_bound(const BoundContext& c, double k0, double k1, double length, Coarse&& coarse, Piece&& piece) {
    double pieces = double(int64_t((k1 - k0) / length)) + 1;
    if (c.budget >= 0 && pieces > 1) {
        double whole = coarse(k0, k1);
        if (whole <= c.budget) return whole;
        double mid = k0 + double(int64_t(pieces / 2)) * length;
        double left = span_bound(c, k0, mid - 1, length, coarse, piece);
        if (c.settled(left)) return left;
        return larger(left, span_bound(c, mid, k1, length, coarse, piece));
    }
    double worst = 0;
    for (double a = k0; a <= k1 && !c.settled(worst); a += length) worst = larger(worst, piece(a, a + length - 1 < k1 ? a + length - 1 : k1));
    return worst;
}

// A coordinate off by at most `du` and `dv` texels reads a texel at most ceil(du), ceil(dv) away;
// over max(1, footprint) that is the footprint error.
double footprint_error(double du, double dv, double footprint);

// 16.16 rounding to nearest: half a unit in the last place.
constexpr double HALF_ULP_16_16 = 1.0 / 131072.0;
// Whether a 16.16 coordinate that starts at `start` (with repeat: reduced into [0, size) first, as
// our mappers do) and moves by `step` a pixel for `steps` pixels stays what it means: the step in
// range, and the values in range or wrapping harmlessly (a repeating size that divides 65536).
bool fits_16_16(double start, double step, double steps, int32_t size, Wrap wrap);

// Whether the polygon's affine planes' gradients hold in 16.16 (a step of 32768 texels a pixel or
// more saturates), for a repeating texture tiled over 256 x 256: the fast mappers' planes mean what they say.
// (fits_16_16 with no travel, 256 dividing 65536: the step's magnitude alone.)
inline bool planes_fit_16_16(const PolygonSetup& s) {
    constexpr double LIMIT = 32767.0 / double(SUBPIXEL_ONE);
    return magnitude(s.u.gx) < LIMIT && magnitude(s.u.gy) < LIMIT && magnitude(s.v.gx) < LIMIT && magnitude(s.v.gy) < LIMIT;
}

// For mappers whose error is not (yet) bounded: whether they may draw the polygon (they take the
// texture), and no bound.
ErrorBound unbounded(const BoundContext& c, const Vertex* vertices, int count);

// Calls f(span, setup) for every span of the polygon inside the clip (the prepared ones, or the
// walker's), f returning the bound so far; stops once that is above the context's budget
// (settled). False when setup does not take the polygon (refused, or degenerate: nothing to draw).
template <typename F>
bool for_each_span(const BoundContext& c, const Vertex* vertices, int count, SetupPlanes planes, F&& f) {
    if (PreparedPolygon* p = c.prepared; p && p->walked[int(c.axis)].count == PreparedSpans::NOT_WALKED) walk_polygon(p, c.axis, c.clip);
    if (PreparedPolygon* p = c.prepared; p && p->walked[int(c.axis)].count >= 0) {
        if (p->status != SetupStatus::Ok) return false;
        PreparedSpans& w = p->walked[int(c.axis)];
        for (int32_t i = 0, k = w.first; i < w.count; ++i, k = k + 1 < w.count ? k + 1 : 0)
            if (c.settled(f(w.spans[k], p->setup))) {
                w.first = k;
                break;
            }
        return true;
    }
    PolygonSetup s;
    if (setup_polygon(vertices, count, &s, planes) != SetupStatus::Ok) return false;
    EdgeWalker walker(s, c.axis, c.clip);
    Span span;
    while (walker.next(&span))
        if (c.settled(f(span, s))) break;
    return true;
}

// Whether setup takes the polygon (the prepared one's status, or a coverage-only setup).
bool setup_takes(const BoundContext& c, const Vertex* vertices, int count);

// Asked with a budget, the polygon's bound at once where that is within it: whole(spread, setup)
// (the spread to complete as needed) gives it (NO_BOUND where it cannot say, 16.16 included). True with *out set when it settles.
template <typename W>
bool whole_within(const BoundContext& c, const Vertex* vertices, int count, W&& whole, ErrorBound* out) {
    if (c.budget < 0) return false;
    PolygonSetup own_setup;
    PolygonSpread own_spread;
    const PolygonSetup* s = &own_setup;
    PolygonSpread* spread = &own_spread;
    if (c.prepared) {
        if (c.prepared->status != SetupStatus::Ok) return false;  // the walk says why
        s = &c.prepared->setup, spread = &prepared_spread(c.prepared, c.clip);
    } else {
        if (setup_polygon(vertices, count, &own_setup, PLANES_ALL) != SetupStatus::Ok) return false;
        polygon_spread(own_setup, c.clip, &own_spread);
    }
    double footprint = whole(*spread, *s);
    if (!(footprint <= c.budget)) return false;
    out->draws = out->exact_coverage = true;
    out->footprint = footprint;
    return true;
}

// The bound of a mapper that draws exactly the reference's pixels and is bounded span by span:
// span_bound_of(span, setup, &fits) gives a span's bound and clears `fits` where 16.16 does not
// hold the mapper's coordinates (no bound then); the polygon's is the largest. Asked with a budget,
// whole(spread, setup) first (whole_within).
template <typename W, typename F>
ErrorBound bound_by_spans(const BoundContext& c, const Vertex* vertices, int count, SetupPlanes planes, W&& whole, F&& span_bound_of) {
    ErrorBound b;
    if (whole_within(c, vertices, count, whole, &b)) return b;
    b.exact_coverage = true;
    if (c.whole_only) {
        b.draws = setup_takes(c, vertices, count);
        b.footprint = NO_BOUND;
        return b;
    }
    bool fits = true;
    double worst = 0;
    b.draws = for_each_span(c, vertices, count, planes, [&](const Span& span, const PolygonSetup& s) {
        double bound = span_bound_of(span, s, &fits);
        worst = bound > worst ? bound : worst;
        return fits ? worst : NO_BOUND;
    });
    b.footprint = fits ? worst : NO_BOUND;
    return b;
}

// For the classics' bounds, which run their own walk again, once the classic's own conversion has
// taken the polygon: *b says it draws, with no bound yet; asked for the whole polygon only, there
// is nothing cheaper than that walk (nullptr); else the polygon's setup for the exact mapping: the
// prepared one, or one set up into `own` (nullptr where setup does not take it).
const PolygonSetup* exact_setup(const BoundContext& c, const Vertex* vertices, int count, PolygonSetup* own, ErrorBound* b);
// The bound over a line the mapper draws (the span's pixels along the axis) reading texel
// floor(a[t] + b[t] k) at pixel k: each line against the exact mapping (lines_bound), BOUND_PIECE
// pixels at a time, with `extra` texels more; NO_BOUND where Q is not positive at either end (a
// pixel far outside the polygon).
double drawn_line_bound(const PolygonSetup& s, Axis axis, const Span& span, const double* a, const double* b, double extra);
// Whether the indices floor(a + b k), k in [0, last], stay in a bordered copy (-1 .. size, the
// border repeating the edge texels); where they reach the border the texel read may be one nearer
// the texture than the index, one texel further from the reference's: *extra becomes 1.
bool within_border(double a, double b, double last, double size, double* extra);

// The affine planes' lines along a span: u and v (t = 0, 1) at its first pixel centre, a[t], and
// their steps a pixel along it, step[t].
void affine_lines(const PolygonSetup& s, Axis axis, const Span& span, double* a, double* step);

}  // namespace raster
