// quake-subdiv16 and quake-subdiv8: Quake's perspective span drawer (d_scan.c) on our walker's spans,
// with its rules (docs/classics.md); the twin and the loop's checks.
#include "kernel/mappers/quake.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/bound.h"
#include "kernel/core/footprint.h"
#include "kernel/core/prepared.h"
#include "kernel/core/selftest.h"

#include "kernel/core/spread.h"
#include "kernel/mappers/classic.h"
#include "kernel/mappers/subdiv.h"

namespace raster::quake {

namespace {

constexpr double MAX_UNSHIFTED = 32000;

// Whether the driver takes the polygon's texture coordinates, and the whole periods that shift them
// into the texture (sadjust, tadjust).
SetupStatus takes(const Vertex* vertices, int count, const Texture& tex, double* shift_u, double* shift_v) {
    SetupStatus status = classic::texture_shift(vertices, count, tex, shift_u, shift_v);
    if (status != SetupStatus::Ok) return status;
    for (int i = 0; i < count; ++i)  // s = (int)(s/z * z) must hold the unshifted u in 16.16
        if (vertices[i].u > MAX_UNSHIFTED || vertices[i].u < -MAX_UNSHIFTED || vertices[i].v > MAX_UNSHIFTED || vertices[i].v < -MAX_UNSHIFTED)
            return SetupStatus::OutOfRange;
    return SetupStatus::Ok;
}

}  // namespace

SetupStatus prepare(const DrawContext& c, const Vertex* vertices, int count, PolygonSetup* own, const PolygonSetup** setup, Gradients* g) {
    double shift_u, shift_v;
    SetupStatus status = takes(vertices, count, c.tex, &shift_u, &shift_v);
    if (status != SetupStatus::Ok) return status;
    // the setup auto made already, or one here
    if (!c.setup && (status = setup_polygon(vertices, count, own, PLANES_PERSPECTIVE, c.input)) != SetupStatus::Ok) return status;
    *setup = c.setup ? c.setup : own;
    // the whole periods in 16.16, modulo 2^32 (a shift can pass 32768 texels: u near -32000 in a
    // 999-texel texture; add_wrapping then lands on the shifted value, which fits)
    g->sadjust_16_16 = int32_t(uint32_t(int64_t(shift_u * 65536.0)));
    g->tadjust_16_16 = int32_t(uint32_t(int64_t(shift_v * 65536.0)));
    g->bbextents = (c.tex.width << 16) - 1;
    g->bbextentt = (c.tex.height << 16) - 1;
    // D_CalcGradients: the planes per screen pixel, origin at pixel (0, 0)
    const PolygonSetup& s = **setup;
    const double per_pixel = double(SUBPIXEL_ONE), x0 = centre_x(s, 0), y0 = centre_y(s, 0);
    auto plane = [&](const Plane& p, double* out) { out[0] = p.at(x0, y0), out[1] = p.gx * per_pixel, out[2] = p.gy * per_pixel; };
    plane(s.pu, g->s);
    plane(s.pv, g->t);
    plane(s.q, g->z);
    return SetupStatus::Ok;
}

namespace {

template <int SHIFT>
SetupStatus draw(const DrawContext& c, const Vertex* vertices, int count) {
    PolygonSetup own;
    const PolygonSetup* setup;
    Gradients g;
    SetupStatus status = prepare(c, vertices, count, &own, &setup, &g);
    if (status != SetupStatus::Ok) return status;
    constexpr double N = double(1 << SHIFT);
    QuakeArgs a;
    a.texels = c.tex.texels;
    a.pitch = c.tex.width;
    a.sadjust_16_16 = g.sadjust_16_16, a.tadjust_16_16 = g.tadjust_16_16;
    a.bbextents = g.bbextents, a.bbextentt = g.bbextentt;
    a.shift = SHIFT;
    a.reserved = 0;
    a.s_origin = g.s[0], a.s_stepu = g.s[1], a.s_stepv = g.s[2];
    a.t_origin = g.t[0], a.t_stepu = g.t[1], a.t_stepv = g.t[2];
    a.z_origin = g.z[0], a.z_stepu = g.z[1], a.z_stepv = g.z[2];
    a.s_stepu_n = a.s_stepu * N, a.t_stepu_n = a.t_stepu * N, a.z_stepu_n = a.z_stepu * N;
    draw_spans(c, *setup, a);
    return SetupStatus::Ok;
}

}  // namespace

SetupStatus draw16(const DrawContext& c, const Vertex* vertices, int count) { return draw<4>(c, vertices, count); }
SetupStatus draw8(const DrawContext& c, const Vertex* vertices, int count) { return draw<3>(c, vertices, count); }

namespace {

constexpr double EPSILON = 2.220446049250313e-16;  // 2^-52
constexpr double UNIT = 1.0 / 65536;                // a 16.16 unit, in texels

// Quake's arithmetic on a polygon (docs/bounds.md, "Quake's spans"), in texels from the chord
// between the exact values at its segment ends: each end is chop(s/z * z) + sadjust, clamped: the
// chop within a unit, Quake's own evaluation within `evaluation` below, and the clamp moving it by
// no more than the exact value's distance from its range (at most the low clamp, plus how far the
// vertices' values leave [0, size]); each step within r.per_step of the chord's slope, so the
// value drawn within j of them after j steps.
// NO_BOUND (as `fixed`) where the spread cannot say (Q not positive from the vertices) or s/z * z
// might not fit 32 bits.
SegmentArithmetic arithmetic(const BoundContext& c, const PolygonSetup& s, const PolygonSpread& p, const double* shift, int n, const Rounding& r) {
    SegmentArithmetic a;
    a.wraps = false;
    a.per_step = r.per_step;
    a.fixed = NO_BOUND;
    if (p.corners == 0) {  // nothing of the polygon inside the clip: no pixel to bound
        a.fixed = 0;
        return a;
    }
    if (!(p.q_min > 0)) return a;
    // every term summed into s/z, t/z and 1/z at a pixel of the clip: the plane at pixel (0, 0)
    // (two products, two sums), the rows down and the pixels across (two each), the segments' steps
    // (one sum each), the last (two) and the inputs' own rounding: each within r.op of the terms'
    // sum; the pixels across and the steps together reach at most the clip's far side (X counts it
    // twice: slack)
    const double one = double(SUBPIXEL_ONE);
    const double xs = larger(magnitude(double(c.clip.x0)), magnitude(double(c.clip.x1))), ys = larger(magnitude(double(c.clip.y0)), magnitude(double(c.clip.y1)));
    const double X = magnitude(centre_x(s, 0)) + 2 * xs * one, Y = magnitude(centre_y(s, 0)) + ys * one;
    auto terms = [&](const Plane& q) { return magnitude(q.a0) + magnitude(q.gy) * Y + magnitude(q.gx) * X; };
    const double operations = 10 + xs / n + 1 + r.inputs;
    const double dq = operations * r.op * terms(s.q) * (1 + 1e-9);
    if (!(dq < p.q_min / 2)) return a;
    const Plane* plane[2] = {&s.pu, &s.pv};
    const int32_t size[2] = {c.tex.width, c.tex.height};
    double worst = 0;
    for (int t = 0; t < 2; ++t) {
        const double most = p.t_abs[t] + p.evaluation[t];
        // (P + dP) / (Q - dQ) against P / Q, Q at least q_min and dQ at most half of it; then the
        // divide and the product, each within r.op (counted twice: slack)
        const double dp = operations * r.op * terms(*plane[t]) * (1 + 1e-9);
        const double evaluation = (2 * (dp + most * dq) / p.q_min + 4 * r.op * most) * (1 + 1e-9);
        if (!((most + evaluation) / UNIT < 2147483647.0 - 1)) return a;  // chop: 0x80000000 beyond
        const double lo = p.t_min[t] + shift[t] - p.evaluation[t], hi = p.t_max[t] + shift[t] + p.evaluation[t];
        const double outside = larger(0.0, larger(-lo, hi - double(size[t])));
        worst = larger(worst, UNIT + r.low_clamp + evaluation + outside);
    }
    a.fixed = worst;
    return a;
}

}  // namespace

ErrorBound bound_with(const BoundContext& c, const Vertex* vertices, int count, int n, const Rounding& r) {
    ErrorBound b;
    double shift[2];
    if (!mapper_accepts(c.mapper, c.tex) || takes(vertices, count, c.tex, &shift[0], &shift[1]) != SetupStatus::Ok) return b;
    // set up once for the arithmetic and the chords both: auto's polygon, or one prepared here
    PreparedPolygon own;
    BoundContext with = c;
    if (!with.prepared) prepare_setup(vertices, count, &own), with.prepared = &own;
    if (with.prepared->status != SetupStatus::Ok) return b;
    const SegmentArithmetic a = arithmetic(c, with.prepared->setup, prepared_spread(with.prepared, c.clip), shift, n, r);
    if (a.fixed < NO_BOUND) return segments_bound(with, vertices, count, n, a);
    b.draws = b.exact_coverage = true;
    b.footprint = NO_BOUND;
    return b;
}

namespace {

// d_scan.c's arithmetic: doubles rounding to nearest, the low clamp at n units, floored steps.
template <int SHIFT>
ErrorBound bound(const BoundContext& c, const Vertex* vertices, int count) {
    constexpr int n = 1 << SHIFT;
    return bound_with(c, vertices, count, n, Rounding{EPSILON / 2, 0, n * UNIT, UNIT});
}

}  // namespace

ErrorBound bound16(const BoundContext& c, const Vertex* vertices, int count) { return bound<4>(c, vertices, count); }
ErrorBound bound8(const BoundContext& c, const Vertex* vertices, int count) { return bound<3>(c, vertices, count); }

}  // namespace raster::quake

namespace raster {

namespace {

// (int) of a double as the x87's FISTP in chop mode gives it: truncation toward zero, and the
// "integer indefinite" 0x80000000 for NaN and anything beyond 32 bits (Quake ran with FP
// exceptions masked and let its clamps pull such values back).
int32_t chop(double x) {
    if (!(x == x) || x >= 2147483648.0 || x <= -2147483649.0) return INT32_MIN;
    return int32_t(x);
}

int32_t clamp(int32_t v, int32_t lo, int32_t hi) { return v > hi ? hi : v < lo ? lo : v; }

int32_t add_wrapping(int32_t a, int32_t b) { return int32_t(uint32_t(a) + uint32_t(b)); }

}  // namespace

void quake_span_loop(const void* raw) {
    const auto& a = *static_cast<const QuakeArgs*>(raw);
    const int32_t n = 1 << a.shift;
    uint8_t* pdest = a.dst;
    int32_t count = a.count;
    double du = double(a.x), dv = double(a.y);
    double sdivz = (a.s_origin + dv * a.s_stepv) + du * a.s_stepu;
    double tdivz = (a.t_origin + dv * a.t_stepv) + du * a.t_stepu;
    double zi = (a.z_origin + dv * a.z_stepv) + du * a.z_stepu;
    double z = 65536.0 / zi;
    int32_t s = clamp(add_wrapping(chop(sdivz * z), a.sadjust_16_16), 0, a.bbextents);
    int32_t t = clamp(add_wrapping(chop(tdivz * z), a.tadjust_16_16), 0, a.bbextentt);
    int32_t sstep = 0, tstep = 0;
    do {
        int32_t spancount = count < n ? count : n;
        count -= spancount;
        int32_t snext, tnext;
        if (count) {
            sdivz += a.s_stepu_n;
            tdivz += a.t_stepu_n;
            zi += a.z_stepu_n;
            z = 65536.0 / zi;
            snext = clamp(add_wrapping(chop(sdivz * z), a.sadjust_16_16), n, a.bbextents);
            tnext = clamp(add_wrapping(chop(tdivz * z), a.tadjust_16_16), n, a.bbextentt);
            sstep = (snext - s) >> a.shift;
            tstep = (tnext - t) >> a.shift;
        } else {
            // the last segment: aim at the span's last pixel
            double spancountminus1 = double(spancount - 1);
            sdivz += a.s_stepu * spancountminus1;
            tdivz += a.t_stepu * spancountminus1;
            zi += a.z_stepu * spancountminus1;
            z = 65536.0 / zi;
            snext = clamp(add_wrapping(chop(sdivz * z), a.sadjust_16_16), n, a.bbextents);
            tnext = clamp(add_wrapping(chop(tdivz * z), a.tadjust_16_16), n, a.bbextentt);
            if (spancount > 1) {
                sstep = (snext - s) / (spancount - 1);
                tstep = (tnext - t) / (spancount - 1);
            }
        }
        for (int32_t k = 0; k < spancount; ++k) {
            *pdest++ = a.texels[(s >> 16) + (t >> 16) * a.pitch];
            s += sstep;
            t += tstep;
        }
        s = snext;
        t = tnext;
    } while (count > 0);
}

// The loop's random cases (core/selftest.h).
LoopCheck check_quake(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<QuakeArgs>(m, other, seed, cases, buf, [&](Random& r, QuakeArgs& a) {
        int32_t w = random_texture_size(r), h = random_texture_size(r);
        a.texels = buf.texels;
        a.pitch = w;
        a.bbextents = (w << 16) - 1;
        a.bbextentt = (h << 16) - 1;
        a.sadjust_16_16 = r.below(2) ? 0 : r.range(-4, 4) * (w << 16);
        a.tadjust_16_16 = r.below(2) ? 0 : r.range(-4, 4) * (h << 16);
        a.shift = r.below(2) ? 4 : 3;
        a.reserved = 0;
        a.count = random_count(r, 1, 20, 320);
        a.x = r.range(0, 319);
        a.y = r.range(0, 239);
        // planes from a real triangle most of the time (then s/z * z is u in 16.16), else raw values
        random_span_planes(r, a);
        double n = double(1 << a.shift);
        a.s_stepu_n = a.s_stepu * n, a.t_stepu_n = a.t_stepu * n, a.z_stepu_n = a.z_stepu * n;
        return place_span(buf, a, 1);
    });
}

#if defined(MODEXLAB_OFFSETS)
// The block layouts asm/quake.asm reads (core/asm_offsets.h).
void quake_offsets() {
    ASM_FIELDS(QUAKE, QuakeArgs, dst, count, x, y, texels, pitch, sadjust_16_16, tadjust_16_16, bbextents, bbextentt, shift, s_origin, s_stepu, s_stepv, t_origin, t_stepu, t_stepv, z_origin, z_stepu, z_stepv, s_stepu_n, t_stepu_n, z_stepu_n)
}
#endif

}  // namespace raster
