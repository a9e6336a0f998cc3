// quake-d_draw16: WinQuake's d_draw16.s on our walker's spans (docs/classics.md): its driver and
// bound, the twin of asm/quake_draw16.asm at the x87's 24-bit precision with chop, the loop's checks.
#include "kernel/mappers/quake_draw16.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/bound.h"
#include "kernel/core/selftest.h"
#include "kernel/mappers/quake.h"

namespace raster::quake {

SetupStatus draw_d_draw16(const DrawContext& c, const Vertex* vertices, int count) {
    PolygonSetup own;
    const PolygonSetup* setup;
    Gradients g;
    SetupStatus status = prepare(c, vertices, count, &own, &setup, &g);
    if (status != SetupStatus::Ok) return status;
    QuakeDraw16Args a;
    a.texels = c.tex.texels;
    a.pitch = c.tex.width;
    a.sadjust_16_16 = g.sadjust_16_16, a.tadjust_16_16 = g.tadjust_16_16;
    a.bbextents = g.bbextents, a.bbextentt = g.bbextentt;
    // Quake's globals are floats: each plane rounded to the nearest one
    a.s_origin = float(g.s[0]), a.s_stepu = float(g.s[1]), a.s_stepv = float(g.s[2]);
    a.t_origin = float(g.t[0]), a.t_stepu = float(g.t[1]), a.t_stepv = float(g.t[2]);
    a.z_origin = float(g.z[0]), a.z_stepu = float(g.z[1]), a.z_stepv = float(g.z[2]);
    draw_spans(c, *setup, a);
    return SetupStatus::Ok;
}

// d_draw16.s's arithmetic: every x87 result within 2^-23 of itself (chop at 24 bits), the planes
// rounded to floats (one more rounding, within 2^-24), the low clamp at 4096 units; a full
// segment's steps exact (delta / 16 with 20 fraction bits), the last segment's delta / m by the
// reciprocal table: floored, and floor(2^31 / m) short of 2^31 / m by less than 1, so within
// 1 + |delta| / 2^31 units, |delta| below size * 65536.
ErrorBound bound_d_draw16(const BoundContext& c, const Vertex* vertices, int count) {
    constexpr double UNIT = 1.0 / 65536, CHOP = 1.0 / 8388608;  // a 16.16 unit; 2^-23
    const int32_t size = c.tex.width > c.tex.height ? c.tex.width : c.tex.height;
    if (size > MAX_TEXTURE_SIZE) return ErrorBound{};  // 2 (snext - s) must fit 32 bits
    return bound_with(c, vertices, count, 16, Rounding{CHOP, 1, 4096 * UNIT, (1 + double(size) / 32768) * UNIT});
}

}  // namespace raster::quake

namespace raster::single_chop {

// Derivation: the x87 under Quake's single_cw on doubles, exactly, on any FPU that rounds doubles
// correctly (the host's SSE2, the kernel's x87 at 53 bits). Every operand has at most 24
// significant bits (floats, the integers du, dv and spancount - 1 below 2^24, and results chopped
// here), and no value comes near double's exponent limits. A product of two is exact in double
// (48 bits): chop it. A sum is exact in double when the exponents differ by 28 or less (24 + 28
// bits and a carry); beyond that the smaller is below a sixteenth of the larger's 24-bit unit, so
// the chopped sum is the larger, or one unit toward zero from it where their signs differ. The
// quotient 2^16 / zi, zi = M 2^e with M a 24-bit integer, equals a 24-bit G 2^f or differs from it
// by at least 1 / (M G) > 2^-48 of it (2^(16-e-f) - M G a nonzero integer, or M G above it): a
// double's rounding (within 2^-53) never crosses a 24-bit value, so chopping the double is exact.
namespace {

constexpr uint64_t LOW29 = (uint64_t(1) << 29) - 1;  // the bits of a double's significand below 24

uint64_t bits(double x) {
    uint64_t b;
    __builtin_memcpy(&b, &x, sizeof b);
    return b;
}
double from_bits(uint64_t b) {
    double x;
    __builtin_memcpy(&x, &b, sizeof x);
    return x;
}
int exponent(double x) { return int((bits(x) >> 52) & 0x7FF); }
bool finite(double x) { return exponent(x) != 0x7FF; }
// the 24-bit value next to x (24 bits, not 0) toward zero
double toward_zero(double x) { return from_bits(bits(x) - (LOW29 + 1)); }

}  // namespace

// x with its significand truncated to 24 bits (toward zero); infinities and NaNs as they are
double chop24(double x) { return finite(x) ? from_bits(bits(x) & ~LOW29) : x; }
double mul(double a, double b) { return chop24(a * b); }

double add(double a, double b) {
    if (a == 0 || b == 0 || !finite(a) || !finite(b)) return chop24(a + b);
    const int d = exponent(a) - exponent(b);
    if (d <= 28 && d >= -28) return chop24(a + b);
    const double larger = d > 0 ? a : b, smaller = d > 0 ? b : a;
    return (larger > 0) == (smaller > 0) ? larger : toward_zero(larger);
}

// 65536 / zi, chopped (z: the divide d_draw16.s overlaps with the pixels)
double quotient_65536(double zi) { return chop24(65536.0 / zi); }

}  // namespace raster::single_chop

namespace raster {

using namespace single_chop;

namespace {

// FISTP: truncated (the value is already), the integer indefinite 0x80000000 beyond 32 bits
int32_t fistp(double x) {
    if (!(x == x) || x >= 2147483648.0 || x <= -2147483649.0) return INT32_MIN;
    return int32_t(x);
}

int32_t wrap_add(int32_t a, int32_t b) { return int32_t(uint32_t(a) + uint32_t(b)); }
int32_t wrap_sub(int32_t a, int32_t b) { return int32_t(uint32_t(a) - uint32_t(b)); }

// The first s and t: clamped to [0, bbextent] (above it unsigned: then high when above signed)
int32_t clamp_start(int32_t v, int32_t extent) { return uint32_t(v) > uint32_t(extent) ? (v > extent ? extent : 0) : v; }
// A segment's end: below 4096 units (1/16 texel) up to it, else unsigned above bbextent down to it
int32_t clamp_end(int32_t v, int32_t extent) { return v < 4096 ? 4096 : uint32_t(v) > uint32_t(extent) ? extent : v; }

// 1/m in 0.31 form, floored, m = 2..15 (d_draw16.s's reciprocal_table_16): the last segment's steps
constexpr int32_t RECIPROCAL[16] = {0, 0, 0x40000000, 0x2aaaaaaa, 0x20000000, 0x19999999, 0x15555555, 0x12492492,
                                    0x10000000, 0xe38e38e, 0xccccccc, 0xba2e8ba, 0xaaaaaaa, 0x9d89d89, 0x9249249, 0x8888888};

// The x87 stack's three values, stepped to the next segment's end and its z started.
struct Planes {
    double sdivz, tdivz, zi;
};
void to_next_segment(Planes& p, const QuakeDraw16Args& a) {
    p.zi = add(p.zi, double(a.z_stepu) * 16);  // the 16-pixel steps are exact: a power of two
    p.sdivz = add(p.sdivz, double(a.s_stepu) * 16);
    p.tdivz = add(p.tdivz, double(a.t_stepu) * 16);
}
void to_last_pixel(Planes& p, const QuakeDraw16Args& a, int32_t spancountminus1) {
    const double m = spancountminus1;
    p.zi = add(p.zi, mul(a.z_stepu, m));
    p.tdivz = add(p.tdivz, mul(a.t_stepu, m));
    p.sdivz = add(p.sdivz, mul(a.s_stepu, m));
}

// The integer side: the texel offset, the two fractions and their steps, the advance table.
struct Stepper {
    uint32_t offset, sfrac, tfrac, sstep, tstep;
    uint32_t advance[2];  // [0] t carried, [1] not
    void step() {
        const uint32_t t = tfrac + tstep, s = sfrac + sstep;
        const uint32_t t_carry = t < tfrac, s_carry = s < sfrac;
        tfrac = t, sfrac = s;
        offset += advance[1 - t_carry] + s_carry;
    }
    // whole s and t steps (each shifted right by `shift`) and fractions (left by 32 - shift)
    void set_steps(int32_t sdelta, int32_t tdelta, int shift, uint32_t pitch) {
        advance[1] = uint32_t(tdelta >> shift) * pitch + uint32_t(sdelta >> shift);
        advance[0] = advance[1] + pitch;
        sstep = uint32_t(sdelta) << (32 - shift), tstep = uint32_t(tdelta) << (32 - shift);
    }
};

}  // namespace

void quake_draw16_loop(const void* raw) {
    const auto& a = *static_cast<const QuakeDraw16Args*>(raw);
    const double du = a.x, dv = a.y;
    Planes p;
    p.sdivz = add(add(mul(du, a.s_stepu), mul(dv, a.s_stepv)), a.s_origin);
    p.tdivz = add(add(mul(du, a.t_stepu), mul(dv, a.t_stepv)), a.t_origin);
    p.zi = add(add(mul(dv, a.z_stepv), mul(du, a.z_stepu)), a.z_origin);
    double z = quotient_65536(p.zi);
    int32_t s = clamp_start(wrap_add(fistp(mul(z, p.sdivz)), a.sadjust_16_16), a.bbextents);
    int32_t t = clamp_start(wrap_add(fistp(mul(z, p.tdivz)), a.tadjust_16_16), a.bbextentt);
    int32_t left = a.count;  // pixels from the segment's first on
    // the divide for the first segment's end (none for a single pixel)
    if (left > 16) to_next_segment(p, a), z = quotient_65536(p.zi);
    else if (left > 1) to_last_pixel(p, a, left - 1), z = quotient_65536(p.zi);
    Stepper st;
    st.offset = uint32_t(s >> 16) + uint32_t(t >> 16) * uint32_t(a.pitch);
    st.sfrac = uint32_t(s) << 16, st.tfrac = uint32_t(t) << 16;
    uint8_t* pdest = a.dst;
    while (left > 16) {
        const int32_t snext = clamp_end(wrap_add(fistp(mul(z, p.sdivz)), a.sadjust_16_16), a.bbextents);
        const int32_t tnext = clamp_end(wrap_add(fistp(mul(z, p.tdivz)), a.tadjust_16_16), a.bbextentt);
        left -= 16;
        // 16 steps of exactly delta / 16: 20 bits of fraction
        st.set_steps(wrap_sub(snext, s), wrap_sub(tnext, t), 20, uint32_t(a.pitch));
        for (int k = 0; k < 16; ++k) {
            pdest[k] = a.texels[st.offset];
            st.step();
        }
        // the next end's divide, started after pixel 8 (its result the same whenever it runs)
        if (left > 16) to_next_segment(p, a), z = quotient_65536(p.zi);
        else if (left > 1) to_last_pixel(p, a, left - 1), z = quotient_65536(p.zi);
        pdest += 16;
        s = snext, t = tnext;
    }
    const int32_t m = left - 1;  // the last segment's steps
    pdest[0] = a.texels[st.offset];
    if (m == 0) return;
    const int32_t snext = clamp_end(wrap_add(fistp(mul(z, p.sdivz)), a.sadjust_16_16), a.bbextents);
    const int32_t tnext = clamp_end(wrap_add(fistp(mul(z, p.tdivz)), a.tadjust_16_16), a.bbextentt);
    int32_t sstep = wrap_sub(snext, s), tstep = wrap_sub(tnext, t);
    if (m > 1) {
        // (delta * 2) * floor(2^31 / m), its high dword
        sstep = int32_t((int64_t(wrap_add(sstep, sstep)) * RECIPROCAL[m]) >> 32);
        tstep = int32_t((int64_t(wrap_add(tstep, tstep)) * RECIPROCAL[m]) >> 32);
    }
    st.set_steps(sstep, tstep, 16, uint32_t(a.pitch));
    for (int32_t k = 1; k <= m; ++k) {
        st.step();
        pdest[k] = a.texels[st.offset];
    }
}

// The loop's random cases (core/selftest.h): spans of every length up to 40 (each segment boundary
// and the partial last segment of every length), then up to 320.
LoopCheck check_quake_draw16(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<QuakeDraw16Args>(m, other, seed, cases, buf, [&, c = uint32_t(0)](Random& r, QuakeDraw16Args& a) mutable {
        int32_t w = random_texture_size(r), h = random_texture_size(r);
        a.texels = buf.texels;
        a.pitch = w;
        a.bbextents = (w << 16) - 1;
        a.bbextentt = (h << 16) - 1;
        a.sadjust_16_16 = r.below(2) ? 0 : r.range(-4, 4) * (w << 16);
        a.tadjust_16_16 = r.below(2) ? 0 : r.range(-4, 4) * (h << 16);
        a.count = c < 40 ? int32_t(c) + 1 : r.below(8) == 0 ? r.range(1, 40) : random_count(r, 1, 20, 320);
        ++c;
        a.x = r.range(0, 319);
        a.y = r.range(0, 239);
        // planes from a real triangle most of the time (then s/z * z is u in 16.16), else raw values
        random_span_planes(r, a);
        if (r.below(16) == 0) {  // steps far below the values they add to: sums beyond 28 exponents apart
            a.s_stepu *= 0x1p-32f, a.t_stepu *= -0x1p-32f, a.z_stepu *= 0x1p-30f;
        }
        return place_span(buf, a, 1);
    });
}

#if defined(MODEXLAB_OFFSETS)
// The block layout asm/quake_draw16.asm reads (core/asm_offsets.h).
void quake_draw16_offsets() {
    ASM_FIELDS(QD16, QuakeDraw16Args, dst, count, x, y, texels, pitch, sadjust_16_16, tadjust_16_16, bbextents, bbextentt, s_origin, s_stepu, s_stepv, t_origin, t_stepu,
               t_stepv, z_origin, z_stepu, z_stepv)
}
#endif

}  // namespace raster
