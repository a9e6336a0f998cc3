// fast-subdiv-N: exact points every N pixels on the fast 8:16 core (docs/mappers.md).
#include "kernel/mappers/fastsubdiv.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/bound.h"
#include "kernel/core/selftest.h"
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
            *dst = texel256(a.texture, u, v);
            dst += a.stride;
            u += uint32_t(du);
            v += uint32_t(dv);
        }
        k += len;
        u0 = u1, v0 = v1;
    }
}

template <int N>
void fast_subdiv_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride) {
    static_assert(N >= 2 && N <= 512 && (N & (N - 1)) == 0);
    const PolygonSetup& setup = c.setup;
    const double x = centre_x(setup, s.x), y = centre_y(setup, s.y);
    const bool rows = c.axis == Axis::Rows;
    FastSubdivArgs a;
    a.dst = dst;
    a.stride = stride;
    a.count = s.count;
    a.texture = c.tex.aligned256;
    a.shift = log2(N);
    a.x = rows ? x : y;
    const Plane* planes[3] = {&setup.q, &setup.pu, &setup.pv};
    for (int i = 0; i < 3; ++i) {
        const Plane& p = *planes[i];
        a.c[i] = rows ? p.a0 + p.gy * y : p.a0 + p.gx * x;
        a.g[i] = rows ? p.gx : p.gy;
    }
    c.loop(&a);
}

// The bound (docs/accuracy.md, "Error bounds"): persp-subdiv-N's chords between the same exact
// points; the start rounded to nearest (half a 16.16 unit), each step off the chord's by less than
// 1.5 units (the difference of two rounded ends, within one unit of the exact one, divided and
// rounded toward zero or down), and the 32-bit difference of two ends holds a chord of less than
// 32767 texels.
template <int N>
ErrorBound fast_subdiv_bound(const BoundContext& c, const Vertex* vertices, int count) {
    if (!mapper_accepts(c.mapper, c.tex)) return ErrorBound{false, true, 0};
    return segments_bound(c, vertices, count, N, SegmentArithmetic{true, HALF_ULP_16_16, 3 * HALF_ULP_16_16, 32767});
}

// The loop's random cases (core/selftest.h): planes from real triangles and extremes (random_planes),
// rows and columns (strides either way) anywhere on and off the screen, segments of 2 to 512 pixels
// (512: one a span).
LoopCheck check_fast_subdiv(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<FastSubdivArgs>(m, other, seed, cases, buf, [&](Random& r, FastSubdivArgs& a) {
        a.count = random_count(r, 0, 3, 320);
        a.texture = check_aligned_texture(buf);
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
    ASM_FIELDS(FSUB, FastSubdivArgs, dst, stride, count, texture, shift, x, c, g)
    ASM_CONSTANT(SUBPIXEL_ONE, SUBPIXEL_ONE);
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

}  // namespace raster
