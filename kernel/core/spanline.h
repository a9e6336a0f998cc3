// Spans as lines of the exact mapping (docs/bounds.md): along one span, the deviation of a line
// from the exact mapping, the footprint and the steps, and the bounds over its pixels of a mapper
// that follows lines or chords there.
#pragma once

#include <stdint.h>

#include "kernel/core/setup.h"
#include "kernel/core/walk.h"

namespace raster {

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

}  // namespace raster
