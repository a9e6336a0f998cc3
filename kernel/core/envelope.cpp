// The envelope's deviations and bound, and its limits' layout for the NASM loops.
#include "kernel/core/envelope.h"

#include "kernel/core/footprint.h"
#include "kernel/core/spread.h"

#if defined(MODEXLAB_OFFSETS)
#include "kernel/core/asm_offsets.h"
#endif

namespace raster {

namespace {

constexpr double EPSILON = 2.220446049250313e-16;  // 2^-52

}  // namespace

EnvelopeBound envelope_bound(const TriangleEnvelope& e) {
    EnvelopeBound b;
    b.envelope = e;
    envelope_deviation(e, b.deviation);
    b.footprint = footprint_error(b.deviation[0], b.deviation[1], 1);
    return b;
}

// The derivation, step by step, is docs/auto.md's ("The object's envelope"); each quantity
// below bounds the one of polygon_spread named beside it, q ones in units of the least 1/w at a
// corner (q_lo). A plane through three values of magnitude at most m and range at most r, on a
// triangle that passes the guards (kappa = ENVELOPE_CONDITION): |gx| W + |gy| H <= kappa r; its
// terms (spread.cpp's terms()) are at most (m + kappa r)(1 + 8 eps), its value at a corner at
// most eps (3 m + 8 kappa r) from the value given there.
void envelope_deviation(const TriangleEnvelope& e, double d[2]) {
    const double eps = EPSILON, kappa = ENVELOPE_CONDITION;
    if (!(e.depth_ratio >= 0 && e.depth_ratio < 1)) {
        d[0] = d[1] = NO_BOUND;
        return;
    }
    auto scale = [&](double m, double r) { return (m + kappa * r) * (1 + 8 * eps); };
    auto evaluated = [&](double m, double r) { return eps * (3 * m + 8 * kappa * r); };
    const double rho = (1 + e.depth_ratio) * (1 + 3 * eps) - 1;  // of the rounded 1/w
    const double q_eval = evaluated(1 + rho, rho), q_scale = scale(1 + rho, rho);
    const double q_off = q_eval + 8.1 * eps * q_scale;                  // Q at a corner, widened by q_err
    const double ratio = (rho + 2 * q_off) / (1 - q_off);              // (q_max - q_min) / q_min
    const double reach = double(ENVELOPE_REACH) + 2, rounding = (1 + reach) * HALF_ULP_16_16;
    for (int t = 0; t < 2; ++t) {
        const double a = e.texel_abs[t], range = e.texel_range[t];
        const double p_abs = a * (1 + rho) * (1 + 2 * eps), p_range = range * (1 + rho) + a * rho + 5 * eps * p_abs;  // u/w
        const double p_eval = evaluated(p_abs, p_range), p_scale = scale(p_abs, p_range);
        const double exact = (p_eval + 1.01 * a * q_eval) / (1 - q_eval) + 3.2 * eps * a;  // P/Q at a corner against u
        const double t_abs = a + exact;
        const double reference = 2 * (4 * eps * (p_scale + t_abs * q_scale) / (1 - q_off) + 2 * eps * t_abs);
        const double evaluation = reference + 4 * eps * scale(a, range);
        const double residual = (evaluated(a, range) + exact) * (1 + eps);
        const double spread = (range + 2 * exact + 2 * evaluation) * perspective_share(1, 1 + ratio);
        d[t] = ((residual + 2 * evaluation + spread) * (1 + 1e-9) + rounding + 2 * reference) * (1 + 0x1p-30);
    }
}

#if defined(MODEXLAB_OFFSETS)
// The envelope's limits, for the fast mappers' enveloped triangle (asm_offsets.h).
void envelope_offsets() {
    ASM_FIELDS(ENV, EnvelopeLimits, area2, extent_x, extent_y)
    ASM_CONSTANT(ENVELOPE_REACH_SUBPIXELS, ENVELOPE_REACH * SUBPIXEL_ONE);
}
#endif

}  // namespace raster
