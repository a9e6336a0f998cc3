// Spans as lines of the exact mapping, and the extremes the bounds need along them.
#include "kernel/core/spanline.h"

#include "kernel/core/footprint.h"

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
// bound there (as drawn_line_bound, bound.cpp, and the spread, spread.cpp, say).
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

}  // namespace raster
