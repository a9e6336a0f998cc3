// The exact integer helpers as the kernel builds them (i686, x87): floor_i32 and floor_i64 through
// the FPU's nearest-integer conversion, floor_div through one IDIV where the quotient fits in 32
// bits, against plain references on random and boundary values (ties, near-integers, both signs,
// the saturation limits, quotients at +-2^31), and under every x87 rounding mode; the fixed-point
// conversions built on them likewise.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "kernel/core/fixed.h"

namespace {

using namespace raster;

int64_t reference_floor_div(int64_t n, int64_t d) {
    int64_t q = n / d;  // 64-bit division in libgcc: the reference
    return n % d != 0 && (n < 0) != (d < 0) ? q - 1 : q;
}

// x87 rounding control (bits 10-11): 0 nearest, 1 down, 2 up, 3 toward zero
void set_rounding(int mode) {
    uint16_t cw;
    __asm__ volatile("fnstcw %0" : "=m"(cw));
    cw = uint16_t((cw & ~0x0C00) | (mode << 10));
    __asm__ volatile("fldcw %0" : : "m"(cw));
}

std::vector<double> samples() {
    std::mt19937_64 rng(20261124u);
    std::vector<double> v = {0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 1e-300, -1e-300, 0.999999999, -0.999999999,
                             2147483646.5, -2147483647.5, 2147483647.0, -2147483648.0, 4503599627370495.5, -4503599627370495.5,
                             4611686018427387903.0, -4611686018427387903.0,
                             // either side of the 32-bit path's edge (floor_small: below 2^31 - 1)
                             2147483646.9999998, -2147483646.9999998, -2147483647.0, 2147483647.5, -2147483647.5};
    std::uniform_real_distribution<double> unit(-1, 1);
    for (int i = 0; i < 200000; ++i) {
        const double scale = std::ldexp(1.0, int(rng() % 64) - 4);
        double x = unit(rng) * scale;
        if (i % 4 == 0) x = std::nearbyint(x) + (i % 8 == 0 ? 0.5 : 0.0);  // integers and ties
        v.push_back(x);
    }
    return v;
}

TEST(Floors, MatchTheReferenceUnderEveryRoundingMode) {
    const std::vector<double> xs = samples();
    for (int mode = 0; mode < 4; ++mode) {
        set_rounding(mode);
        for (double x : xs) {
            const double f = std::floor(x);
            const int32_t want32 = f >= 2147483647.0 ? INT32_MAX : f <= -2147483648.0 ? INT32_MIN : int32_t(f);
            const int64_t want64 = f >= 0x1p62 ? int64_t(1) << 62 : f <= -0x1p62 ? -(int64_t(1) << 62) : int64_t(f);
            ASSERT_EQ(floor_i32(x), want32) << x << " rounding mode " << mode;
            ASSERT_EQ(floor_i64(x), want64) << x << " rounding mode " << mode;
            // the fixed-point conversions: floor(x * 2^F + 1/2), saturated
            const double g16 = std::floor(x * 65536.0 + 0.5), g8 = std::floor(x * 256.0 + 0.5);
            ASSERT_EQ(Fixed16_16::from_double(x).raw, g16 >= 2147483647.0 ? INT32_MAX : g16 <= -2147483648.0 ? INT32_MIN : int32_t(g16)) << x;
            ASSERT_EQ(Fixed24_8::from_double(x).raw, g8 >= 2147483647.0 ? INT32_MAX : g8 <= -2147483648.0 ? INT32_MIN : int32_t(g8)) << x;
        }
    }
    set_rounding(0);
}

TEST(Floors, FloorDivisionMatchesTheReference) {
    std::mt19937_64 rng(1124u);
    int by_idiv = 0;
    for (int i = 0; i < 400000; ++i) {
        int64_t d = i % 3 == 0 ? int64_t(rng() % 1000) + 1 : int64_t(rng() % (uint64_t(1) << (1 + rng() % 40))) + 1;
        if (i % 4 == 1 || i % 4 == 2) d &= 0x7FFFFFFF, d += d == 0;  // (d << 31 in range)
        int64_t n;
        switch (i % 4) {
        case 0: n = int64_t(rng() >> (rng() % 64)) * (rng() % 2 ? 1 : -1); break;
        case 1: n = (d << 31) - int64_t(rng() % 3) + (rng() % 2 ? 0 : 1); break;  // at the quotient's 32-bit edge
        case 2: n = -(d << 31) + int64_t(rng() % 3) - (rng() % 2 ? 0 : 1); break;
        default: n = int64_t(rng() % 2000001) - 1000000;
        }
        by_idiv += d < (int64_t(1) << 31) && n >= -(d << 31) && n < (d << 31);
        ASSERT_EQ(floor_div(n, d), reference_floor_div(n, d)) << n << " / " << d;
    }
    EXPECT_GT(by_idiv, 100000);
}

}  // namespace
