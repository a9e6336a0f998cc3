// persp-subdiv-N: our subdividing perspective mapper (docs/mappers.md).
#include "kernel/mappers/subdiv.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/bound.h"
#include "kernel/core/selftest.h"

namespace raster {

// persp-subdiv-N: exact u, v (the reference's perspective divide, unfloored) at the span's first
// pixel centre, every N pixels after it and at its last pixel; 16.16 steps between them, rounded
// to nearest (the divisor is the pixel count between the exact points, so the last pixel of each
// piece lands on the exact value). Repeat: both ends of a piece reduced by the same whole number of
// periods, so the piece never straddles a wrap. Each piece is one call of the context's loop
// (step_loop or asm/subdiv.asm).
namespace {

uint32_t wrap_mask(int32_t size) { return (size & (size - 1)) == 0 ? uint32_t(size - 1) : 0; }

}  // namespace

void step_loop(const void* raw) {
    const auto& a = *static_cast<const StepArgs*>(raw);
    const Texture tex{a.texels, a.width, a.height, a.clamp ? Wrap::Clamp : Wrap::Repeat};
    uint8_t* dst = a.dst;
    Fixed16_16 u = Fixed16_16::from_raw(a.u_16_16), v = Fixed16_16::from_raw(a.v_16_16);
    const Fixed16_16 du = Fixed16_16::from_raw(a.du_16_16), dv = Fixed16_16::from_raw(a.dv_16_16);
    for (int32_t n = 0; n < a.count; ++n) {
        *dst = texel(tex, u.floor_int(), v.floor_int());
        dst += a.stride;
        u = u + du;
        v = v + dv;
    }
}

namespace {

// Draws span s in runs: length(k) pixels from pixel k (at least 1), each on the chord from the exact
// point at its first pixel to the one at the next run's first pixel (or at the span's last).
template <typename Length>
void runs_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride, Length&& length) {
    const PolygonSetup& setup = c.setup;
    const bool rows = c.axis == Axis::Rows;
    double x = span_centre_x(setup, s.x), y = span_centre_y(setup, s.y);
    auto exact_at = [&](int32_t k, double* u, double* v) {
        double px = rows ? x + double(k) * SUBPIXEL_ONE : x, py = rows ? y : y + double(k) * SUBPIXEL_ONE;
        double q = setup.q.at(px, py);
        *u = setup.pu.at(px, py) / q;
        *v = setup.pv.at(px, py) / q;
    };
    auto period = [&](double t, int32_t size) {  // whole periods below t (repeat), else none
        return c.tex.wrap == Wrap::Repeat ? double(size) * double(floor_i64(t / double(size))) : 0.0;
    };
    double u0, v0;
    exact_at(0, &u0, &v0);
    for (int32_t k = 0; k < s.count;) {
        int32_t len = length(k);  // pixels in this run
        int32_t end = k + len < s.count ? k + len : s.count - 1;  // the next exact point
        double u1, v1;
        if (end != k) exact_at(end, &u1, &v1);
        else u1 = u0, v1 = v0;
        double pu = period(u0, c.tex.width), pv = period(v0, c.tex.height);
        Fixed16_16 u = Fixed16_16::from_double(u0 - pu), v = Fixed16_16::from_double(v0 - pv);
        int32_t divisor = end - k;
        Fixed16_16 du{}, dv{};
        if (divisor > 0) {
            du = Fixed16_16::from_double(((u1 - pu) - (u0 - pu)) / divisor);
            dv = Fixed16_16::from_double(((v1 - pv) - (v0 - pv)) / divisor);
        }
        StepArgs a{dst, stride, len, c.tex.texels, c.tex.width, c.tex.height, c.tex.wrap == Wrap::Clamp,
                   wrap_mask(c.tex.width), wrap_mask(c.tex.height), u.raw, v.raw, du.raw, dv.raw};
        c.loop(&a);
        dst += stride * len;
        k += len;
        u0 = u1, v0 = v1;
    }
}

}  // namespace

// Whether 16.16 holds chords of up to `steps` steps anywhere on the polygon (the whole-polygon
// bounds): from the largest |t| (clamp; repeat reduces the start first) by the largest |t'|; a
// chord's ends, two exact values at pixels drawn, at most the spread's range of t apart (each
// within the reference's rounding of the exact value, the range's ends within their evaluation's).
bool chords_fit(const BoundContext& c, PolygonSpread& p, const PolygonSetup& s, double steps, double chord) {
    const int32_t size[2] = {c.tex.width, c.tex.height};
    for (int t = 0; t < 2; ++t) {
        const double start = c.tex.wrap == Wrap::Repeat ? 0.0 : p.t_abs[t];
        const double range = (p.t_max[t] - p.t_min[t] + 2 * (p.evaluation[t] + p.reference[t])) * (1 + 1e-9);
        // a chord's step is its ends' difference over at least one pixel, and it travels at most
        // that difference: within the range (no steps to compute where that fits)
        if (fits_16_16(start, range, 1, size[t], c.tex.wrap) && range < chord) continue;
        const double step = spread_max_step(p, s, t, c.axis);
        const double reach = step * (steps + 1) < range ? step * (steps + 1) : range;
        if (!fits_16_16(start, step, steps, size[t], c.tex.wrap) || !(reach < chord)) return false;
    }
    return true;
}

namespace {

// The bound over pixels k0..k1 of the run whose chord goes from exact point `from` to `end`: the
// chord's deviation (lines_bound), within the arithmetic's rounding after k1 - from steps; clears
// `fits` where 16.16 may not hold it.
double run_bound(const SpanLine& l, const Texture& tex, const SegmentArithmetic& arithmetic, double from, double end, double k0, double k1,
                 bool* fits) {
    const int32_t size[2] = {tex.width, tex.height};
    double a[2], step[2];
    for (int t = 0; t < 2; ++t) {
        double t0 = span_exact(l, t, from), t1 = span_exact(l, t, end);
        step[t] = end > from ? (t1 - t0) / (end - from) : 0.0;
        a[t] = t0 - step[t] * from;
        double start = tex.wrap == Wrap::Repeat ? 0.0 : t0;  // repeat: reduced into [0, size) first
        *fits = *fits && (!arithmetic.wraps || fits_16_16(start, step[t], k1 - from, size[t], tex.wrap)) && magnitude(t1 - t0) < arithmetic.chord;
    }
    return lines_bound(l, a, step, k0, k1, arithmetic.at(k1 - from));
}

}  // namespace

template <int N>
void subdiv_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride) {
    runs_span(c, s, dst, stride, [&](int32_t k) { return s.count - k > N ? N : s.count - k; });
}

int32_t adaptive_run(const SpanLine& l, const ChordTerms& terms, int32_t k, double budget) {
    const int32_t left = l.count - k;
    if (left <= 1) return left;
    const double last = double(l.count - 1), q = l.q0 + l.qm * double(k);
    auto within = [&](double h) {  // the chord from k over h pixels (or to the last), by chords_bound
        const double end = double(k) + h < last ? double(k) + h : last, q_end = l.q0 + l.qm * end;
        return chords_bound(terms, h, q < q_end ? q : q_end, larger(q, q_end), (1 + h) * HALF_ULP_16_16) <= budget;
    };
    double h = double(left < ADAPTIVE_LONGEST ? left : ADAPTIVE_LONGEST);
    if (within(h)) return int32_t(h);
    // from the curvature at k: h^2 / 8 * |t''| within the texels the budget allows there (less a
    // margin for the rounding), then shorter by a quarter until chords_bound agrees
    const double room = double(int64_t(budget * larger(1.0, terms.least_k / (q * q)))) - 1.0 / 64;
    const double curvature = larger(terms.k_high[0], terms.k_high[1]) / (q * q) * 2 * terms.qm / q;
    if (room > 0 && curvature > 0) {
        const double guess = __builtin_sqrt(8 * room / curvature);
        h = guess < h ? double(int64_t(guess)) : h;
    } else {
        h = 1;
    }
    while (h > 1 && !within(h)) h = double(int64_t(h * 0.75));
    return h < 1 ? 1 : int32_t(h);
}

template <int QUARTERS>
void adaptive_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride) {
    const SpanLine l = span_line(c.setup, c.axis, s);
    const ChordTerms terms = chord_terms(l);
    runs_span(c, s, dst, stride, [&](int32_t k) { return adaptive_run(l, terms, k, QUARTERS / 4.0); });
}

// The bound (docs/bounds.md): each segment runs from the exact value at its
// first pixel along the chord to the exact value at the next exact point, to within the
// arithmetic's rounding; the chord's deviation from the exact mapping is measured piece by piece (a
// segment, or BOUND_PIECE pixels of a longer one), each over its own smallest footprint.
double segments_span_bound(const BoundContext& c, const SpanLine& l, bool* fits, double N, const SegmentArithmetic& a) {
    const int32_t size[2] = {c.tex.width, c.tex.height};
    const double length = N < BOUND_PIECE ? N : BOUND_PIECE;
    const double last = double(l.count - 1);
    auto segment = [&](double k) { return double(int64_t(k / N)) * N; };  // the first pixel of k's segment
    auto next_exact = [&](double k) { return segment(k) + N < last ? segment(k) + N : last; };
    // coarse, over pixels k0..k1: the chords through them run from the start of k0's segment
    // to the exact point after k1, and everything is taken over that whole stretch (a chord's
    // error depends on t'' all along it): every chord at most N pixels and the span long, its
    // steps at most the largest |t'|, its start (clamp) at most the larger end (t is monotonic
    // along a span); where that may not fit 16.16, no coarse bound: the pieces one by one
    auto coarse = [&](double k0, double k1) {
        const double from = segment(k0), reach = next_exact(k1), h = N < last ? N : last, steps = N - 1 < last ? N - 1 : last;
        for (int t = 0; t < 2 && a.wraps; ++t) {
            double start = c.tex.wrap == Wrap::Repeat ? 0.0 : larger(magnitude(span_exact(l, t, from)), magnitude(span_exact(l, t, reach)));
            const double step = max_step_along(l, t, from, reach);
            if (!fits_16_16(start, step, steps, size[t], c.tex.wrap) || !(step * (steps + 1) < a.chord)) return NO_BOUND;
        }
        return chords_bound(l, h, from, reach, a.at(steps));
    };
    auto piece = [&](double k0, double k1) { return run_bound(l, c.tex, a, segment(k0), next_exact(k0), k0, k1, fits); };  // on its chord
    return span_bound(c, 0, last, length, coarse, piece);
}

ErrorBound segments_bound(const BoundContext& c, const Vertex* vertices, int count, double N, const SegmentArithmetic& a) {
    auto whole = [&](PolygonSpread& p, const PolygonSetup& s) {  // the coarse bound below, over the polygon
        const double last = p.lines[c.axis == Axis::Rows ? 0 : 1] - 1, h = N < last ? N : last, steps = N - 1 < last ? N - 1 : last;
        return !a.wraps || chords_fit(c, p, s, steps, a.chord) ? spread_chords_bound(p, s, c.axis, h, a.at(steps), c.budget) : NO_BOUND;
    };
    return bound_by_spans(c, vertices, count, PLANES_PERSPECTIVE, whole,
                          [&](const Span& span, const PolygonSetup& s, bool* fits) { return segments_span_bound(c, span_line(s, c.axis, span), fits, N, a); });
}

template <int N>
ErrorBound subdiv_bound(const BoundContext& c, const Vertex* vertices, int count) {
    return segments_bound(c, vertices, count, N, SegmentArithmetic{});
}

// persp-adaptive-B's bound: its runs as it draws them, each on its chord (run_bound, pieces of at
// most BOUND_PIECE). Asked with a budget, the polygon at once: every run the chooser did not have to
// cut to one pixel is within B by chords_bound; a run of one pixel is within the whole polygon's
// chords bound for one pixel; and 16.16 holds runs of up to ADAPTIVE_LONGEST pixels.
template <int QUARTERS>
ErrorBound adaptive_bound(const BoundContext& c, const Vertex* vertices, int count) {
    const double budget = QUARTERS / 4.0;
    auto whole = [&](PolygonSpread& p, const PolygonSetup& s) {
        const double last = p.lines[c.axis == Axis::Rows ? 0 : 1] - 1, steps = ADAPTIVE_LONGEST - 1 < last ? ADAPTIVE_LONGEST - 1 : last;
        return chords_fit(c, p, s, steps, 1e300) ? larger(budget, spread_chords_bound(p, s, c.axis, 1, 2 * HALF_ULP_16_16, c.budget)) : NO_BOUND;
    };
    return bound_by_spans(c, vertices, count, PLANES_PERSPECTIVE, whole, [&](const Span& span, const PolygonSetup& s, bool* fits) {
        const SpanLine l = span_line(s, c.axis, span);
        const ChordTerms terms = chord_terms(l);
        const double last = double(span.count - 1);
        double worst = 0;
        for (int32_t k = 0; k < span.count && !c.settled(worst);) {
            const int32_t len = adaptive_run(l, terms, k, budget);
            const double from = double(k), end = k + len < span.count ? double(k + len) : last;
            for (double k0 = from; k0 < double(k + len); k0 += BOUND_PIECE) {
                const double k1 = k0 + BOUND_PIECE - 1 < double(k + len - 1) ? k0 + BOUND_PIECE - 1 : double(k + len - 1);
                worst = larger(worst, run_bound(l, c.tex, SegmentArithmetic{}, from, end, k0, k1, fits));
            }
            k += len;
        }
        return worst;
    });
}

// The loop's random cases (core/selftest.h): any texture size, repeat and clamp, coordinates and
// steps over the whole 16.16 range (wrapping adds), strides either way.
LoopCheck check_step(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<StepArgs>(m, other, seed, cases, buf, [&](Random& r, StepArgs& a) {
        random_check_texture(r, buf, a);
        const int32_t w = a.width, h = a.height;
        a.width_mask = wrap_mask(w), a.height_mask = wrap_mask(h);
        a.count = random_count(r, 0, 3, 320);
        a.stride = random_stride(r);
        CheckWindow window = place_span(buf, a, a.stride);
        // near the texture most of the time, anywhere now and then; steps from a hundredth of a
        // texel to whole periods, and the extremes
        auto coordinate = [&](int32_t size) { return r.below(4) ? r.range(-2 * size, 3 * size) * 65536 + r.range(0, 65535) : int32_t(r.next()); };
        auto step = [&]() { return r.below(8) ? r.range(-4 << 16, 4 << 16) : int32_t(r.next()); };
        a.u_16_16 = coordinate(w), a.v_16_16 = coordinate(h);
        a.du_16_16 = step(), a.dv_16_16 = step();
        return window;
    });
}

#if defined(MODEXLAB_OFFSETS)
// The block layout asm/subdiv.asm reads (core/asm_offsets.h).
void subdiv_offsets() {
    ASM_FIELDS(STEP, StepArgs, dst, stride, count, texels, width, height, clamp, width_mask, height_mask, u_16_16, v_16_16, du_16_16,
               dv_16_16)
    ASM_SIZE(STEP_ARGS_SIZE, StepArgs);
}
#endif

template void subdiv_span<4>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void subdiv_span<8>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void subdiv_span<16>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void subdiv_span<32>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void subdiv_span<SPAN_LONG>(const SpanContext&, const Span&, uint8_t*, int32_t);
template ErrorBound subdiv_bound<4>(const BoundContext&, const Vertex*, int);
template ErrorBound subdiv_bound<8>(const BoundContext&, const Vertex*, int);
template ErrorBound subdiv_bound<16>(const BoundContext&, const Vertex*, int);
template ErrorBound subdiv_bound<32>(const BoundContext&, const Vertex*, int);
template ErrorBound subdiv_bound<SPAN_LONG>(const BoundContext&, const Vertex*, int);
template void adaptive_span<2>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void adaptive_span<4>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void adaptive_span<8>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void adaptive_span<16>(const SpanContext&, const Span&, uint8_t*, int32_t);
template ErrorBound adaptive_bound<2>(const BoundContext&, const Vertex*, int);
template ErrorBound adaptive_bound<4>(const BoundContext&, const Vertex*, int);
template ErrorBound adaptive_bound<8>(const BoundContext&, const Vertex*, int);
template ErrorBound adaptive_bound<16>(const BoundContext&, const Vertex*, int);

}  // namespace raster
