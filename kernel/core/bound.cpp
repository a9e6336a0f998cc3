// Spans as lines of the exact mapping, and the extremes the bounds need along them.
#include "kernel/core/bound.h"

namespace raster {

namespace {

constexpr double EPSILON = 2.220446049250313e-16;  // 2^-52

// Q at the ends of pixels k0..k1: the smaller and the larger (Q is linear along a span).
double q_low(const SpanLine& l, double k0, double k1) {
    double a = l.q0 + l.qm * k0, b = l.q0 + l.qm * k1;
    return a < b ? a : b;
}
double q_high(const SpanLine& l, double k0, double k1) { return larger(l.q0 + l.qm * k0, l.q0 + l.qm * k1); }

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
    double x = centre_x(s, span.x), y = centre_y(s, span.y);
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
    double d[2];
    for (int t = 0; t < 2; ++t) d[t] = line_deviation(l, t, a[t], b[t], k0, k1) + rounding + 2 * exact_rounding(l, t);
    return footprint_error(d[0], d[1], min_footprint_along(l, k0, k1));
}

double max_step_along(const SpanLine& l, int t, double k0, double k1) {
    double q_lo = q_low(l, k0, k1);
    double rounding, k = k_magnitude(l, t, &rounding);
    return (k + rounding) / (q_lo * q_lo) * (1 + 1e-9);  // from above; the margin: this bound's own rounding
}

double chords_bound(const SpanLine& l, double h, double k0, double k1, double rounding) {
    double q_lo = q_low(l, k0, k1);
    double d[2];
    for (int t = 0; t < 2; ++t) {
        // h^2 / 8 * 2 |K| |Q'| / Q_lo^3, with |K| / Q_lo^2 from max_step_along
        double curvature = max_step_along(l, t, k0, k1) * 2 * magnitude(l.qm) / q_lo;
        d[t] = h * h / 8 * curvature * (1 + 1e-9) + rounding + 2 * exact_rounding(l, t);
    }
    return footprint_error(d[0], d[1], min_footprint_along(l, k0, k1));
}

bool fits_16_16(double start, double step, double steps, int32_t size, Wrap wrap) {
    constexpr double LIMIT = 32767;
    double travel = magnitude(step) * steps;
    if (!(magnitude(step) < LIMIT) || !(travel < 1e9)) return false;
    if (wrap == Wrap::Repeat) return (65536 % size == 0) || double(size) + travel < LIMIT;
    return magnitude(start) + travel < LIMIT;
}

void prepare_polygon(const Vertex* vertices, int count, Axis axis, const ClipRect& clip, PreparedPolygon* out, const PreparedPolygon* same) {
    out->count = 0, out->pixels = 0, out->first = 0;
    if (same) out->status = same->status, out->setup = same->setup;
    else out->status = setup_polygon(vertices, count, &out->setup, PLANES_ALL);
    if (out->status != SetupStatus::Ok) return;
    EdgeWalker walker(out->setup, axis, clip);
    Span span;
    while (walker.next(&span)) {
        if (out->count == PreparedPolygon::MAX_SPANS) {
            out->count = -1;
            return;
        }
        out->spans[out->count++] = span;
        out->pixels += span.count;
    }
}

void affine_lines(const PolygonSetup& s, Axis axis, const Span& span, double* a, double* step) {
    double x = centre_x(s, span.x), y = centre_y(s, span.y);
    const Plane* plane[2] = {&s.u, &s.v};
    for (int t = 0; t < 2; ++t) {
        a[t] = plane[t]->at(x, y);
        step[t] = (axis == Axis::Rows ? plane[t]->gx : plane[t]->gy) * double(SUBPIXEL_ONE);
    }
}

bool setup_takes(const BoundContext& c, const Vertex* vertices, int count) {
    if (c.prepared && c.prepared->count >= 0) return c.prepared->status == SetupStatus::Ok;
    PolygonSetup s;
    return setup_polygon(vertices, count, &s, PLANES_NONE) == SetupStatus::Ok;
}

ErrorBound unbounded(const BoundContext& c, const Vertex* vertices, int count) {
    ErrorBound b;
    b.draws = mapper_accepts(c.mapper, c.tex) && setup_takes(c, vertices, count);
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

}  // namespace raster
