// quake-subdiv16 and quake-subdiv8: Quake's perspective span drawer (d_scan.c) on our walker's spans,
// with its rules (docs/mappers.md); the twin and the loop's checks.
#include "kernel/mappers/quake.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/selftest.h"

#include "kernel/mappers/classic.h"

namespace raster::quake {

namespace {

template <int SHIFT>
SetupStatus draw(const DrawContext& c, const Vertex* vertices, int count) {
    double shift_u, shift_v;
    SetupStatus status = classic::texture_shift(vertices, count, c.tex, &shift_u, &shift_v);
    if (status != SetupStatus::Ok) return status;
    for (int i = 0; i < count; ++i)  // s = (int)(s/z * z) must hold the unshifted u in 16.16
        if (vertices[i].u > 32000 || vertices[i].u < -32000 || vertices[i].v > 32000 || vertices[i].v < -32000) return SetupStatus::OutOfRange;
    PolygonSetup setup;
    status = setup_polygon(vertices, count, &setup, PLANES_PERSPECTIVE);
    if (status != SetupStatus::Ok) return status;

    constexpr double N = double(1 << SHIFT);
    const double per_pixel = double(SUBPIXEL_ONE);
    QuakeArgs a;
    a.texels = c.tex.texels;
    a.pitch = c.tex.width;
    a.sadjust_16_16 = int32_t(shift_u * 65536.0);
    a.tadjust_16_16 = int32_t(shift_v * 65536.0);
    a.bbextents = (c.tex.width << 16) - 1;
    a.bbextentt = (c.tex.height << 16) - 1;
    a.shift = SHIFT;
    a.reserved = 0;
    // D_CalcGradients: the planes per screen pixel, origin at pixel (0, 0)
    double x0 = centre_x(setup, 0), y0 = centre_y(setup, 0);
    a.s_origin = setup.pu.at(x0, y0), a.s_stepu = setup.pu.gx * per_pixel, a.s_stepv = setup.pu.gy * per_pixel;
    a.t_origin = setup.pv.at(x0, y0), a.t_stepu = setup.pv.gx * per_pixel, a.t_stepv = setup.pv.gy * per_pixel;
    a.z_origin = setup.q.at(x0, y0), a.z_stepu = setup.q.gx * per_pixel, a.z_stepv = setup.q.gy * per_pixel;
    a.s_stepu_n = a.s_stepu * N, a.t_stepu_n = a.t_stepu * N, a.z_stepu_n = a.z_stepu * N;

    EdgeWalker walker(setup, Axis::Rows, c.target.clip);
    setup_done(c);
    Span span;
    while (walker.next(&span)) {
        a.dst = c.target.base + span.y * c.target.pitch + span.x;
        a.count = span.count;
        a.x = span.x;
        a.y = span.y;
        emit(c, &a, 1, uint32_t(span.count));
    }
    return SetupStatus::Ok;
}

}  // namespace

SetupStatus draw16(const DrawContext& c, const Vertex* vertices, int count) { return draw<4>(c, vertices, count); }
SetupStatus draw8(const DrawContext& c, const Vertex* vertices, int count) { return draw<3>(c, vertices, count); }

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
        double q[3], pu[3], pv[3];
        random_planes(r, q, pu, pv);
        auto per_pixel = [&](const double* p, double* origin, double* stepu, double* stepv) {
            *stepu = p[1] * 256, *stepv = p[2] * 256;
            *origin = p[0] + double(r.range(-100000, 100000)) * 1e-3 * (*stepu);
        };
        per_pixel(pu, &a.s_origin, &a.s_stepu, &a.s_stepv);
        per_pixel(pv, &a.t_origin, &a.t_stepu, &a.t_stepv);
        per_pixel(q, &a.z_origin, &a.z_stepu, &a.z_stepv);
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
