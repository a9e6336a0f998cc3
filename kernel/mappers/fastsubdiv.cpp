// fast-subdiv-N: exact points every N pixels on the fast 8:16 core (docs/mappers.md).
#include "kernel/mappers/fastsubdiv.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/bound.h"
#include "kernel/mappers/auto/choice.h"
#include "kernel/core/footprint.h"
#include "kernel/core/selftest.h"
#include "kernel/core/spanline.h"
#include "kernel/mappers/subdiv.h"

namespace raster {

namespace {

// The exact point at pixel k in 16.16, the low 32 bits of the nearest 64-bit integer (|u| stays
// far below 2^47 inside a polygon: MAX_UV).
void exact_16_16(const FastSubdivArgs& a, int32_t k, uint32_t* u, uint32_t* v) {
    const double x = a.x + double(k) * double(SUBPIXEL_ONE);
    const double q = a.c[0] + a.g[0] * x;
    *u = uint32_t(uint64_t(__builtin_llrint((a.c[1] + a.g[1] * x) / q * 65536.0)));
    *v = uint32_t(uint64_t(__builtin_llrint((a.c[2] + a.g[2] * x) / q * 65536.0)));
}

constexpr int log2(int n) { return n > 1 ? 1 + log2(n / 2) : 0; }

}  // namespace

void fast_subdiv_loop(const void* raw) {
    const auto& a = *static_cast<const FastSubdivArgs*>(raw);
    if (a.count <= 0) return;
    const int32_t n = int32_t(1) << a.shift;
    uint32_t u0, v0;
    exact_16_16(a, 0, &u0, &v0);
    uint8_t* dst = a.dst;
    // the texture's block: the tiled one, or its doubled copy's from the origin by masks
    const TableBlock block = a.texture ? TableBlock{a.texture, 255, 255, 256} : table_block(*a.source);
    for (int32_t k = 0; k < a.count;) {
        const int32_t len = a.count - k > n ? n : a.count - k;
        const int32_t end = k + len < a.count ? k + len : a.count - 1;  // the next exact point
        uint32_t u1 = u0, v1 = v0;
        if (end != k) exact_16_16(a, end, &u1, &v1);
        const int32_t d = end - k;
        int32_t du = 0, dv = 0;
        if (d == n) du = int32_t(u1 - u0) >> a.shift, dv = int32_t(v1 - v0) >> a.shift;
        else if (d > 0) du = int32_t(u1 - u0) / d, dv = int32_t(v1 - v0) / d;
        uint32_t u = u0, v = v0;
        for (int32_t i = 0; i < len; ++i) {
            *dst = *block.at(u, v);
            dst += a.stride;
            u += uint32_t(du);
            v += uint32_t(dv);
        }
        k += len;
        u0 = u1, v0 = v1;
    }
}

namespace {

// The loop's block for span s (all but the segments' shift): each plane along the span's line.
// (Inlined: called once a span; out of line, the block would cost a copy a span.)
[[gnu::always_inline]] inline void span_args(const PolygonSetup& setup, Axis axis, const Span& s, const Texture& tex, uint8_t* dst,
                                             int32_t stride, FastSubdivArgs* out) {
    FastSubdivArgs& a = *out;
    const double x = span_centre_x(setup, s.x), y = span_centre_y(setup, s.y);
    const bool rows = axis == Axis::Rows;
    a.dst = dst;
    a.stride = stride;
    a.count = s.count;
    a.texture = tex.aligned256;  // (null: a texture the mappers take has a doubled copy then)
    a.source = &tex;
    // (the walker tested once, the planes unrolled)
    auto along = [&](double across, double at, double Plane::*line, double Plane::*step) {
        a.x = at;
        a.c[0] = setup.q.a0 + setup.q.*line * across, a.g[0] = setup.q.*step;
        a.c[1] = setup.pu.a0 + setup.pu.*line * across, a.g[1] = setup.pu.*step;
        a.c[2] = setup.pv.a0 + setup.pv.*line * across, a.g[2] = setup.pv.*step;
    };
    if (rows) along(y, x, &Plane::gy, &Plane::gx);
    else along(x, y, &Plane::gx, &Plane::gy);
}

// fast-adaptive's shift for the block's span (the drawing and the bound's span path alike)
[[gnu::always_inline]] inline int32_t adaptive_shift(const FastSubdivArgs& a, double room) {
    // Q at the end it falls toward: the last pixel's where it falls along the span, else the first's
    // (rounding is monotonic, so that is the lesser of the two as computed: one evaluation, not two)
    const double g = a.g[0];
    const double q_lo = g < 0 ? a.c[0] + g * (a.x + double(a.count > 0 ? a.count - 1 : 0) * double(SUBPIXEL_ONE)) : a.c[0] + g * a.x;
    return fast_adaptive_shift(q_lo, q_lo, __builtin_fabs(g) * double(SUBPIXEL_ONE), room);
}

// fast-subdiv's arithmetic (fast_subdiv_bound)
constexpr SegmentArithmetic FAST_ARITHMETIC{true, HALF_ULP_16_16, 3 * HALF_ULP_16_16, 32767};

}  // namespace

template <int N>
void fast_subdiv_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride) {
    static_assert(N >= 2 && N <= 512 && (N & (N - 1)) == 0);
    FastSubdivArgs a;
    span_args(c.setup, c.axis, s, c.tex, dst, stride, &a);
    a.shift = log2(N);
    c.loop(&a);
}

template <int QUARTERS>
void fast_adaptive_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride) {
    static_assert(QUARTERS >= 4, "below one footprint no chord of two pixels is within (relative_chords_bound)");
    FastSubdivArgs a;
    span_args(c.setup, c.axis, s, c.tex, dst, stride, &a);
    constexpr double room = fast_adaptive_room(QUARTERS / 4.0);
    a.shift = adaptive_shift(a, room);
    c.loop(&a);
}

// The bound (docs/bounds.md): persp-subdiv-N's chords between the same exact
// points; the start rounded to nearest (half a 16.16 unit), each step off the chord's by less than
// 1.5 units (the difference of two rounded ends, within one unit of the exact one, divided and
// rounded toward zero or down), and the 32-bit difference of two ends holds a chord of less than
// 32767 texels.
template <int N>
ErrorBound fast_subdiv_bound(const BoundContext& c, const Vertex* vertices, int count) {
    if (!mapper_accepts(c.mapper, c.tex)) return ErrorBound{false, true, 0};
    return segments_bound(c, vertices, count, N, FAST_ARITHMETIC);
}

// fast-adaptive-B's bound (docs/bounds.md, "Adaptive segments on the fast core"). The whole
// polygon: where 16.16 holds chords of 511 steps and the rounding (FAST_ARITHMETIC's after 511
// steps, and twice the reference's) is within FAST_ADAPTIVE_ROUNDING, every span whose shift found
// chords within room is within B, and a span left at 2 pixels within the polygon's chords bound for
// 2 pixels: the larger of the two; else the chords bound for 512 (no chord is longer). The rule
// trusts Q as the span evaluates it, so Q's terms at a corner must be within 2^26 times its least.
// A span: its chords as drawn (segments_span_bound), or the relative chords bound at its own Q,
// whichever is less.
template <int QUARTERS>
ErrorBound fast_adaptive_bound(const BoundContext& c, const Vertex* vertices, int count) {
    if (!mapper_accepts(c.mapper, c.tex)) return ErrorBound{false, true, 0};
    constexpr double budget = QUARTERS / 4.0, room = fast_adaptive_room(budget);
    const bool rows = c.axis == Axis::Rows;
    auto whole = [&](PolygonSpread& p, const PolygonSetup& s) {
        const double last = p.lines[rows ? 0 : 1] - 1, steps = FAST_SPAN_LONG - 1 < last ? FAST_SPAN_LONG - 1 : last;
        if (!chords_fit(c, p, s, steps, FAST_ARITHMETIC.chord)) return NO_BOUND;
        const double rounding = FAST_ARITHMETIC.at(steps) + 2 * larger(p.reference[0], p.reference[1]);
        double terms = 0;  // Q's terms at the corners (relative to the reference vertex, as the planes)
        for (int i = 0; i < p.corners; ++i)
            terms = larger(terms, magnitude(s.q.a0) + magnitude(s.q.gx * p.corner_x[i]) + magnitude(s.q.gy * p.corner_y[i]));
        if (!(rounding <= FAST_ADAPTIVE_ROUNDING) || !(terms <= p.q_min * 67108864.0))
            return spread_chords_bound(p, s, c.axis, FAST_SPAN_LONG < last ? FAST_SPAN_LONG : last, FAST_ARITHMETIC.at(steps), c.budget);
        return larger(budget, spread_chords_bound(p, s, c.axis, 2 < last ? 2 : last, FAST_ARITHMETIC.at(1 < last ? 1 : last), c.budget));
    };
    return bound_by_spans(c, vertices, count, PLANES_PERSPECTIVE, whole, [&](const Span& span, const PolygonSetup& s, bool* fits) {
        FastSubdivArgs a;
        span_args(s, c.axis, span, c.tex, nullptr, 1, &a);
        const double n = double(int32_t(1) << adaptive_shift(a, room));
        const SpanLine l = span_line(s, c.axis, span);
        const double drawn = segments_span_bound(c, l, fits, n, FAST_ARITHMETIC);
        const double last = double(span.count - 1), h = n < last ? n : last;
        const double q_lo = larger(0.0, l.q0 < l.q0 + l.qm * last ? l.q0 : l.q0 + l.qm * last);
        const ChordTerms terms = chord_terms(l);
        const double relative = q_lo > 0 ? relative_chords_bound(h * h * magnitude(l.qm) / (4 * q_lo),
                                                                 FAST_ARITHMETIC.at(h) + larger(terms.reference[0], terms.reference[1]))
                                         : NO_BOUND;
        return drawn < relative ? drawn : relative;
    });
}

namespace {

constexpr double EPS = 2.220446049250313e-16, MARGIN = 1 + 1e-9;

// Q's least value at the corners of a polygon inside the clip (its vertices: the spread's corners)
// less twice the spread's widening (its own evaluation of Q may round otherwise), Q's terms there,
// and the corners' largest |x| and |y|: fast_certificate's, and fast_oriented_guard's.
struct QLeast {
    double q_min, scale_q, far_x, far_y;
    double terms(const Plane& p) const { return (magnitude(p.a0) + magnitude(p.gy) * far_y + magnitude(p.gx) * far_x) * MARGIN; }
};
QLeast q_least(const PolygonSetup& s) {
    QLeast l{0, 0, 0, 0};
    double q_lo = 0;
    for (int i = 0; i < s.edge_count; ++i) {
        const double x = double(s.edges[i].px - s.ref_x), y = double(s.edges[i].py - s.ref_y);
        const double q = s.q.at(x, y);
        q_lo = i && !(q < q_lo) ? q_lo : q;
        l.far_x = larger(l.far_x, magnitude(x)), l.far_y = larger(l.far_y, magnitude(y));
    }
    l.scale_q = l.terms(s.q);
    l.q_min = (q_lo - 16 * EPS * l.scale_q) * (1 - 1e-9);
    return l;
}

}  // namespace

FastCertificate fast_certificate(const PolygonSetup& s, const ClipRect& clip, const Texture& tex) {
    FastCertificate f;
    // (the mappers take the texture: its sides divide 65536)
    if (tex.wrap != Wrap::Repeat) return f;
    // inside the clip: the spread's corners are the vertices (spread_corners)
    if (!box_in_clip(s, clip)) return f;
    const QLeast l = q_least(s);
    const double q_min = l.q_min, scale_q = l.scale_q;
    auto terms = [&](const Plane& p) { return l.terms(p); };
    // Q above 0, and its terms within 2^26 of its least (fast-adaptive's whole bound's condition,
    // each corner's terms at most scale_q)
    if (!(q_min > 0) || !(scale_q <= q_min * 67108864.0)) return f;
    const Plane* exact[2] = {&s.pu, &s.pv};
    const Plane* affine[2] = {&s.u, &s.v};
    double reference = 0;
    for (int t = 0; t < 2; ++t) {
        const double scale_p = terms(*exact[t]), t_abs = scale_p / q_min * MARGIN;  // |P| / Q at every corner, from above
        const double ref = 2 * (4 * EPS * (scale_p + t_abs * scale_q) / q_min + 2 * EPS * t_abs) * MARGIN;
        const double evaluation = ref + 4 * EPS * terms(*affine[t]);
        // chords_fit without the steps: the range of t (at most 2 |t|) and the roundings
        const double range = (2 * t_abs + 2 * (evaluation + ref)) * MARGIN * MARGIN;
        // (fits_16_16 with a start of 0, one step and a side dividing 65536: the step below 32767)
        if (!(range < FAST_ARITHMETIC.chord)) return f;
        reference = larger(reference, ref);
    }
    f.holds = f.terms_within = true, f.q_min = q_min, f.reference = reference;
    // (the spread's lines inside the clip: the box's extent plus one)
    f.last[0] = double(s.max_x - s.min_x) / double(SUBPIXEL_ONE), f.last[1] = double(s.max_y - s.min_y) / double(SUBPIXEL_ONE);
    return f;
}

FastCertificate fast_certificate(const PolygonSpread& p) {
    FastCertificate f;
    if (!(p.q_min > 0)) return f;
    // (fits_16_16 with a start of 0, one step and a side dividing 65536 asks the step below 32767:
    // the chord's limit covers it, as in the setup's certificate above)
    static_assert(FAST_ARITHMETIC.chord <= 32767, "one test for both of chords_fit's");
    for (int t = 0; t < 2; ++t) {
        // chords_fit's first test, as it takes it (a repeating texture whose sides divide 65536)
        const double range = (p.t_max[t] - p.t_min[t] + 2 * (p.evaluation[t] + p.reference[t])) * (1 + 1e-9);
        if (!(range < FAST_ARITHMETIC.chord)) return f;
    }
    f.holds = true, f.q_min = p.q_min, f.reference = larger(p.reference[0], p.reference[1]);
    f.last[0] = p.lines[0] - 1, f.last[1] = p.lines[1] - 1;
    return f;
}

double fast_chords_bound(const FastCertificate& f, const PolygonSetup& s, Axis axis, double n) {
    constexpr double MARGIN = 1 + 1e-9;
    if (!f.holds) return NO_BOUND;
    // as segments_bound's whole bound takes them: the chords' pixels h and steps along a line
    const bool rows = axis == Axis::Rows;
    const double last = f.last[rows ? 0 : 1];
    const double h = n < last ? n : last, steps = n - 1 < last ? n - 1 : last;
    const double qa = magnitude(rows ? s.q.gx : s.q.gy) * double(SUBPIXEL_ONE);
    return relative_chords_bound(h * h * qa / (4 * f.q_min) * MARGIN, (FAST_ARITHMETIC.at(steps) + 2 * f.reference) * MARGIN);
}

template <int QUARTERS>
bool fast_adaptive_certain(const FastCertificate& f, const PolygonSetup& s, Axis axis) {
    // the rounding after the longest chord, and the chords of two pixels relative to each pixel's step
    if (!f.holds || !f.terms_within || !(FAST_ARITHMETIC.at(FAST_SPAN_LONG - 1) + 2 * f.reference <= FAST_ADAPTIVE_ROUNDING)) return false;
    constexpr double MARGIN = 1 + 1e-9;
    const double qa = magnitude(axis == Axis::Rows ? s.q.gx : s.q.gy) * double(SUBPIXEL_ONE);
    return relative_chords_bound(qa / f.q_min * MARGIN, (FAST_ARITHMETIC.at(1) + 2 * f.reference) * MARGIN) <= QUARTERS / 4.0;
}

template <int QUARTERS>
bool fast_adaptive_certain(const PolygonSetup& s, const ClipRect& clip, const Texture& tex, Axis axis) {
    return fast_adaptive_certain<QUARTERS>(fast_certificate(s, clip, tex), s, axis);
}

namespace {

// fast_oriented_guard's limits (docs/bounds.md, "fast-oriented-1's guard"), against Q's least over
// the pixels: t within GUARD_T of its value at the centre of their box, |t| within GUARD_T_ABS;
// Q's terms within GUARD_Q_TERMS of it and P's within GUARD_P_TERMS, so that the spread's
// reference rounding is within GUARD_REFERENCE; a cut polygon's corners moved by their slack
// within GUARD_MOVED texels; the affine planes' terms within GUARD_AFFINE; GUARD_SLACK covers
// each computed value's own rounding.
constexpr double GUARD_T = 15000, GUARD_T_ABS = 0x1p18, GUARD_Q_TERMS = 0x1p18, GUARD_P_TERMS = 0x1p37;
constexpr double GUARD_MOVED = 0x1p-10, GUARD_AFFINE = 1e18, GUARD_SLACK = 1 + 1e-12;
constexpr double GUARD_REFERENCE =
    2 * (4 * EPS * (GUARD_P_TERMS + GUARD_T_ABS * GUARD_Q_TERMS) + 2 * EPS * GUARD_T_ABS) * MARGIN * MARGIN * GUARD_SLACK;
static_assert(GUARD_Q_TERMS <= 67108864.0, "fast-adaptive's whole bound asks Q's terms within 2^26 of its least");
static_assert((2 * GUARD_T + 6 * GUARD_REFERENCE + 4 * GUARD_MOVED + 2 * 4 * EPS * GUARD_AFFINE) * MARGIN * MARGIN * GUARD_SLACK < FAST_ARITHMETIC.chord,
              "the range of t fits 16.16's chords (chords_fit's first test)");
static_assert(FAST_ARITHMETIC.at(FAST_SPAN_LONG - 1) + 2 * GUARD_REFERENCE <= FAST_ADAPTIVE_ROUNDING, "fast-adaptive's rounding");
// relative_chords_bound(X M, R) <= 1 where 2 X M (1 + 1e-9)^2 <= 1 - R (1 + 1e-9), R its rounding
// (at most GUARD_R): the two-pixel chords' |Q'| at most GUARD_CHORD times Q's least
constexpr double GUARD_R = (FAST_ARITHMETIC.at(1) + 2 * GUARD_REFERENCE) * MARGIN * GUARD_SLACK;
constexpr double GUARD_CHORD = (1 - GUARD_R * (1 + 2e-9)) / (2 * MARGIN * (1 + 2e-9)) / GUARD_SLACK;
// A cut polygon's affine planes: terms and drift within A (1 + GUARD_CUT_AFFINE (n - 2) S^2 / area2)
constexpr double GUARD_CUT_AFFINE = 72;

}  // namespace

bool fast_oriented_guard_takes(double texel_most, const ClipRect& clip) {
    // the affine plane through the fan triangle of largest doubled area D (at least area2 / (n - 2),
    // area2 >= 1) has terms at most A (1 + 8 (n - 2) far_x far_y / area2), far_x and far_y within
    // the clip's sides (subpixels)
    const double w = double(clip.x1 - clip.x0) * double(SUBPIXEL_ONE), h = double(clip.y1 - clip.y0) * double(SUBPIXEL_ONE);
    return texel_most >= 0 && texel_most * (1 + 8.0 * (MAX_POLYGON_VERTICES - 2) * w * h) * (1 + 1e-6) * MARGIN <= GUARD_AFFINE;
}

double fast_oriented_guard(const PolygonSetup& s, const ClipRect& clip, Axis axis, double texel_most) {
    // the pixels' box: the polygon's inside the clip, relative to the reference vertex (a cut
    // polygon's spread corners lie within `slack` of it: spread_corners)
    const bool cut = !box_in_clip(s, clip);
    double x_lo = double(int32_t(s.min_x - s.ref_x)), x_hi = double(int32_t(s.max_x - s.ref_x));
    double y_lo = double(int32_t(s.min_y - s.ref_y)), y_hi = double(int32_t(s.max_y - s.ref_y));
    double reach = 0;  // a cut polygon: its vertices' reach from the reference vertex, for the slack
    if (cut) {
        const double one = double(SUBPIXEL_ONE), ref_x = double(s.ref_x), ref_y = double(s.ref_y);
        reach = larger(-x_lo, x_hi) + larger(-y_lo, y_hi);
        x_lo = larger(x_lo, clip.x0 * one - ref_x), x_hi = -larger(-x_hi, ref_x - clip.x1 * one);
        y_lo = larger(y_lo, clip.y0 * one - ref_y), y_hi = -larger(-y_hi, ref_y - clip.y1 * one);
        if (x_lo > x_hi || y_lo > y_hi) return 0;  // (nothing drawn)
    }
    const double slack = 64 * EPS * reach * MARGIN;
    QLeast l{0, 0, larger(-x_lo, x_hi) + slack, larger(-y_lo, y_hi) + slack};
    l.scale_q = l.terms(s.q);
    auto drift = [&](const Plane& p) { return (magnitude(p.gx) + magnitude(p.gy)) * slack * MARGIN; };
    const double drift_q = cut ? drift(s.q) : 0;
    // Q's least over the box (its corner where each term is least), within 4 eps of terms(Q) of the
    // exact, the spread's at a corner within 4 and its own 8 more, and a corner's slack twice
    const double q_lo = s.q.a0 + s.q.gy * (s.q.gy < 0 ? y_hi : y_lo) + s.q.gx * (s.q.gx < 0 ? x_hi : x_lo);
    const double gradient = magnitude(axis == Axis::Rows ? s.q.gx : s.q.gy) * double(SUBPIXEL_ONE);
    const double terms_p = larger(l.terms(s.pu), l.terms(s.pv)), drift_p = cut ? larger(drift(s.pu), drift(s.pv)) : 0;
    // t within GUARD_T of its value at the centre of the box (half its sides, a cut polygon's
    // corners up to `slack` beyond): t - t_c = (P - t_c Q) / Q, P - t_c Q = c_x (x - x_c) +
    // c_y (y - y_c), with the roundings of it, t_c and the c's within 12 eps of P's terms and |t_c|
    // Q's (a hundredth of Q's least here)
    auto t_within = [&](double q_min) {
        const double x_c = (x_lo + x_hi) / 2, y_c = (y_lo + y_hi) / 2, half_x = (x_hi - x_lo) / 2 + slack, half_y = (y_hi - y_lo) / 2 + slack;
        const double q_c = s.q.at(x_c, y_c);
        if (!(q_c > 0) || !(terms_p <= GUARD_P_TERMS * q_min)) return false;
        const Plane* planes[2] = {&s.pu, &s.pv};
        for (const Plane* p : planes) {
            const double t_c = p->at(x_c, y_c) / q_c, c_x = p->gx - t_c * s.q.gx, c_y = p->gy - t_c * s.q.gy;
            const double within = (magnitude(c_x) * half_x + magnitude(c_y) * half_y) * MARGIN;
            if (!(within <= (GUARD_T - 1) * q_min) || !(magnitude(t_c) <= GUARD_T_ABS - GUARD_T - 2)) return false;
        }
        return true;
    };
    // and first, |t| within GUARD_T everywhere (P's terms), which implies it
    auto holds = [&](double q_min) {
        if (!(q_min > 0) || !(l.scale_q <= GUARD_Q_TERMS * q_min) || !(gradient <= GUARD_CHORD * q_min)) return false;
        if (cut && !(drift_p + GUARD_T_ABS * drift_q <= GUARD_MOVED * q_min)) return false;
        return terms_p <= GUARD_T * q_min || t_within(q_min);
    };
    if (cut) {
        // the affine planes' terms (fast_oriented_guard_takes' bound, from the vertices' reach)
        const double n = double(s.edge_count - 2), area2 = double(s.area2);
        if (!(texel_most * (area2 + GUARD_CUT_AFFINE * n * reach * reach) * (1 + 1e-6) * MARGIN <= GUARD_AFFINE * area2)) return 0;
    }
    const double q_box = (q_lo - 24 * EPS * l.scale_q - 3 * drift_q) * (1 - 1e-9);
    if (holds(q_box)) return q_box;
    // where the box reaches where Q is far less (a slanted polygon): Q's least at the vertices
    // (q_least's, less what the spread's corners may take beyond)
    const QLeast v = q_least(s);
    const double q_vertices = cut ? (v.q_min - 8 * EPS * v.scale_q - 3 * drift_q) * (1 - 1e-9) : v.q_min;
    return q_vertices > q_box && holds(q_vertices) ? q_vertices : 0;
}

bool fast_constant_within(const PolygonSetup& s, const ClipRect& clip, Axis axis, double q_min, double room) {
    // fast_chords_bound's for 512 pixels at the certificate's Q_min (at least q_min) and rounding
    // (within FAST_ADAPTIVE_ROUNDING): X = h^2 |Q'| / (4 Q_min) M, h the box's extent inside the
    // clip along the lines
    const bool rows = axis == Axis::Rows;
    const int64_t one = SUBPIXEL_ONE, first = int64_t(rows ? clip.x0 : clip.y0) * one, end = int64_t(rows ? clip.x1 : clip.y1) * one;
    const int64_t lo = rows ? s.min_x : s.min_y, hi = rows ? s.max_x : s.max_y;
    const double last = double((hi < end ? hi : end) - (lo > first ? lo : first)) / double(SUBPIXEL_ONE);
    const double h = last < FAST_SPAN_LONG ? last : FAST_SPAN_LONG;
    return h * h * magnitude(rows ? s.q.gx : s.q.gy) * double(SUBPIXEL_ONE) * MARGIN * GUARD_SLACK <= 4 * q_min * room;
}

Axis oriented_axis(const PolygonSetup& s, const PolygonSize size[2], double room) {
    const double one = double(SUBPIXEL_ONE);
    const double rows = size[int(Axis::Rows)].spans, columns = size[int(Axis::Columns)].spans, pixels = size[0].pixels;
    const double q = s.q.a0;
    if (!(q > 0)) return Axis::Rows;
    // segments beyond one a line: pixels / h_a = pixels sqrt(|Q_a| / (4 room q))
    const double scale = pixels / __builtin_sqrt(4 * room * q);
    const double by_rows = rows * (ORIENTED_LINE + ORIENTED_SEGMENT) + ORIENTED_SEGMENT * scale * __builtin_sqrt(__builtin_fabs(s.q.gx) * one);
    const double by_columns = columns * (ORIENTED_LINE + ORIENTED_SEGMENT) + ORIENTED_SEGMENT * scale * __builtin_sqrt(__builtin_fabs(s.q.gy) * one);
    return by_columns < by_rows ? Axis::Columns : Axis::Rows;
}

Axis oriented_axis(const PolygonSetup& s, const ClipRect& clip, double room) {
    PolygonSize size[2];
    polygon_sizes(s, clip, size);
    return oriented_axis(s, size, room);
}

template <int QUARTERS>
Axis fast_oriented_walker(const PolygonSetup& s, const ClipRect& clip) {
    return oriented_axis(s, clip, fast_adaptive_room(QUARTERS / 4.0));
}

template <int QUARTERS>
SetupStatus fast_oriented_draw(const DrawContext& c, const Vertex* vertices, int count) {
    PolygonSetup own;
    const PolygonSetup* s = c.setup;
    if (!s) {
        const SetupStatus status = setup_polygon(vertices, count, &own, PLANES_PERSPECTIVE, c.input);
        if (status != SetupStatus::Ok) return status;
        s = &own;
    }
    // (auto hands over its setup with the walker it picked as this does: choose_mapper's oriented candidate)
    const Axis axis = c.setup || c.axis == Axis::Columns ? c.axis : fast_oriented_walker<QUARTERS>(*s, c.target.clip);
    EdgeWalker walker(*s, axis, c.target.clip);
    setup_done(c);
    const SpanContext context{*s, c.tex, axis, c.loop};
    Span span;
    while (walker.next(&span)) {
        int32_t stride;
        uint8_t* dst = span_start(c.target, axis, span, &stride);
        emit(c.stats->probe, c.stats, 1, uint32_t(span.count), [&] { fast_adaptive_span<QUARTERS>(context, span, dst, stride); });
    }
    return SetupStatus::Ok;
}

template <int QUARTERS>
ErrorBound fast_oriented_bound(const BoundContext& c, const Vertex* vertices, int count) {
    if (c.axis == Axis::Columns) return fast_adaptive_bound<QUARTERS>(c, vertices, count);
    PolygonSetup own;
    const PolygonSetup* s = &own;
    if (c.prepared && c.prepared->status == SetupStatus::Ok) s = &c.prepared->setup;
    else if (setup_polygon(vertices, count, &own, PLANES_PERSPECTIVE) != SetupStatus::Ok) return fast_adaptive_bound<QUARTERS>(c, vertices, count);
    const BoundContext along{c.mapper, c.tex, fast_oriented_walker<QUARTERS>(*s, c.clip), c.clip, c.budget, c.prepared, c.whole_only};
    return fast_adaptive_bound<QUARTERS>(along, vertices, count);
}

// The loop's random cases (core/selftest.h): planes from real triangles and extremes (random_planes),
// rows and columns (strides either way) anywhere on and off the screen, segments of 2 to 512 pixels
// (512: one a span); a third of them on a doubled copy that fills the check's texels (its sides
// drawn again now and then: fill_check_doubled), where the NASM loop's pointer reads what the twin's
// masks read only if it stays in the copy.
LoopCheck check_fast_subdiv(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    Texture big;  // (its doubled copy: the check's texels, once filled)
    return check_cases<FastSubdivArgs>(m, other, seed, cases, buf, [&](Random& r, FastSubdivArgs& a) {
        a.count = random_count(r, 0, 3, 320);
        a.texture = check_aligned_texture(buf);
        a.source = nullptr;
        if (r.below(3) == 0) {
            if (!big.doubled || r.below(256) == 0) {
                random_doubled_sides(r, &big.width, &big.height);
                fill_check_doubled(buf, big.width, big.height, r.next());
                big.doubled = buf.texels;
            }
            a.texture = nullptr, a.source = &big;
        }
        a.shift = r.below(4) ? r.range(3, 5) : r.range(1, 9);
        a.stride = random_stride(r);
        CheckWindow window = place_span(buf, a, a.stride);
        double q[3], pu[3], pv[3];
        random_planes(r, q, pu, pv);
        const double y = double(r.range(-90000, 90000)) + 128;
        a.x = double(r.range(-120000, 120000)) + 128;
        const double* planes[3] = {q, pu, pv};
        for (int i = 0; i < 3; ++i) a.c[i] = planes[i][0] + planes[i][2] * y, a.g[i] = planes[i][1];
        return window;
    });
}

#if defined(MODEXLAB_OFFSETS)
// The block layout asm/fastsubdiv.asm reads (core/asm_offsets.h).
void fastsubdiv_offsets() {
    ASM_FIELDS(FSUB, FastSubdivArgs, dst, stride, count, texture, source, shift, x, c, g)
    ASM_FIELDS(FTEX, Texture, width, height, doubled)
    ASM_CONSTANT(SUBPIXEL_ONE, SUBPIXEL_ONE);
    ASM_CONSTANT(DOUBLED_LEAD, DOUBLED_LEAD);
}
#endif

template void fast_subdiv_span<8>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void fast_subdiv_span<16>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void fast_subdiv_span<32>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void fast_subdiv_span<FAST_SPAN_LONG>(const SpanContext&, const Span&, uint8_t*, int32_t);
template ErrorBound fast_subdiv_bound<8>(const BoundContext&, const Vertex*, int);
template ErrorBound fast_subdiv_bound<16>(const BoundContext&, const Vertex*, int);
template ErrorBound fast_subdiv_bound<32>(const BoundContext&, const Vertex*, int);
template ErrorBound fast_subdiv_bound<FAST_SPAN_LONG>(const BoundContext&, const Vertex*, int);
template void fast_adaptive_span<4>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void fast_adaptive_span<8>(const SpanContext&, const Span&, uint8_t*, int32_t);
template ErrorBound fast_adaptive_bound<4>(const BoundContext&, const Vertex*, int);
template ErrorBound fast_adaptive_bound<8>(const BoundContext&, const Vertex*, int);
template bool fast_adaptive_certain<4>(const PolygonSetup&, const ClipRect&, const Texture&, Axis);
template bool fast_adaptive_certain<8>(const PolygonSetup&, const ClipRect&, const Texture&, Axis);
template bool fast_adaptive_certain<4>(const FastCertificate&, const PolygonSetup&, Axis);
template bool fast_adaptive_certain<8>(const FastCertificate&, const PolygonSetup&, Axis);
template Axis fast_oriented_walker<4>(const PolygonSetup&, const ClipRect&);
template SetupStatus fast_oriented_draw<4>(const DrawContext&, const Vertex*, int);
template ErrorBound fast_oriented_bound<4>(const BoundContext&, const Vertex*, int);

}  // namespace raster
