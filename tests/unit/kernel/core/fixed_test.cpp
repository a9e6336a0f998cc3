// Under test: kernel/core/fixed.h.
// Fixed-point types and the exact double-to-integer helpers, at their range limits.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "kernel/core/fixed.h"

namespace {

using namespace raster;

TEST(Floor, I32AtTheLimits) {
    EXPECT_EQ(floor_i32(0.0), 0);
    EXPECT_EQ(floor_i32(-0.0), 0);
    EXPECT_EQ(floor_i32(0.999999), 0);
    EXPECT_EQ(floor_i32(-1e-300), -1);
    EXPECT_EQ(floor_i32(-1.0), -1);
    EXPECT_EQ(floor_i32(2147483646.75), 2147483646);
    EXPECT_EQ(floor_i32(2147483647.0), INT32_MAX);
    EXPECT_EQ(floor_i32(1e300), INT32_MAX);
    EXPECT_EQ(floor_i32(-2147483647.5), INT32_MIN);
    EXPECT_EQ(floor_i32(-2147483648.0), INT32_MIN);
    EXPECT_EQ(floor_i32(-1e300), INT32_MIN);
    EXPECT_EQ(floor_i32(std::numeric_limits<double>::infinity()), INT32_MAX);
    EXPECT_EQ(floor_i32(-std::numeric_limits<double>::infinity()), INT32_MIN);
    EXPECT_EQ(floor_i32(std::nan("")), 0);
}

TEST(Floor, I64AtTheLimits) {
    EXPECT_EQ(floor_i64(-0.5), -1);
    EXPECT_EQ(floor_i64(4503599627370495.5), 4503599627370495);
    EXPECT_EQ(floor_i64(-4503599627370495.5), -4503599627370496);
    EXPECT_EQ(floor_i64(1e19), int64_t(1) << 62);
    EXPECT_EQ(floor_i64(-1e19), -(int64_t(1) << 62));
    EXPECT_EQ(floor_i64(std::nan("")), 0);
}

TEST(Floor, DivisionRoundsDown) {
    EXPECT_EQ(floor_div(7, 2), 3);
    EXPECT_EQ(floor_div(-7, 2), -4);
    EXPECT_EQ(floor_div(-8, 2), -4);
    EXPECT_EQ(floor_div(0, 5), 0);
    EXPECT_EQ(floor_div(-1, 256), -1);
    EXPECT_EQ(floor_div(INT64_MIN + 1, 1), INT64_MIN + 1);
    EXPECT_EQ(floor_div(INT64_MAX, INT64_MAX), 1);
    EXPECT_EQ(floor_div(INT32_MIN, 1), INT32_MIN);
    EXPECT_EQ(floor_div(INT32_MIN, 3), -715827883);
    EXPECT_EQ(floor_div(int64_t(INT32_MIN) - 1, 2), -1073741825);
    EXPECT_EQ(floor_div(-5, int64_t(INT32_MAX) + 1), -1);
}

// Against 128-bit arithmetic, across the 32-bit fast path's edges and beyond.
TEST(Floor, DivisionMatchesWideArithmetic) {
    std::mt19937_64 rng(5);
    const int64_t edges[] = {0, 1, -1, INT32_MAX, INT32_MIN, int64_t(INT32_MAX) + 1, int64_t(INT32_MIN) - 1, INT64_MAX, INT64_MIN + 1};
    for (int trial = 0; trial < 200000; ++trial) {
        int bits_n = 1 + int(rng() % 63), bits_d = 1 + int(rng() % 62);  // |n| < 2^63, 0 < d <= 2^62
        int64_t n = int64_t(rng() >> (64 - bits_n)) * ((rng() & 1) ? -1 : 1);
        int64_t d = int64_t(rng() >> (64 - bits_d)) + 1;
        if (trial % 10 == 0) {  // near an edge, without overflowing
            n = edges[rng() % 9];
            int64_t off = int64_t(rng() % 5) - 2;
            if (!((off > 0 && n > INT64_MAX - off) || (off < 0 && n < INT64_MIN + 1 - off))) n += off;
        }
        if (trial % 10 == 1) d = edges[3 + rng() % 2 * 2] + int64_t(rng() % 3);
        __int128 q = __int128(n) / d;
        if (__int128(n) - q * d < 0) --q;
        ASSERT_EQ(floor_div(n, d), int64_t(q)) << n << " / " << d;
    }
}

TEST(Fixed16_16, RangeAndSaturation) {
    EXPECT_EQ(Fixed16_16::ONE, 65536);
    EXPECT_EQ(Fixed16_16::from_int(32767).raw, 32767 * 65536);
    EXPECT_EQ(Fixed16_16::from_int(32768).raw, INT32_MAX);
    EXPECT_EQ(Fixed16_16::from_int(-32768).raw, INT32_MIN);
    EXPECT_EQ(Fixed16_16::from_int(-32769).raw, INT32_MIN);
    EXPECT_EQ(Fixed16_16::from_double(32767.0 + 65535.0 / 65536).raw, INT32_MAX);  // the largest value, exactly
    EXPECT_EQ(Fixed16_16::from_double(32768.0).raw, INT32_MAX);                     // one step beyond: saturated
    EXPECT_EQ(Fixed16_16::from_double(1e12).raw, INT32_MAX);
    EXPECT_EQ(Fixed16_16::from_double(-1e12).raw, INT32_MIN);
    EXPECT_EQ(Fixed16_16::from_double(std::nan("")).raw, 0);
    EXPECT_EQ(Fixed16_16::from_double(-32768.0).raw, INT32_MIN);
}

TEST(Fixed16_16, RoundsToNearestTiesUp) {
    const double half_step = 0.5 / 65536;
    EXPECT_EQ(Fixed16_16::from_double(half_step).raw, 1);
    EXPECT_EQ(Fixed16_16::from_double(-half_step).raw, 0);
    EXPECT_EQ(Fixed16_16::from_double(3 * half_step).raw, 2);
    EXPECT_EQ(Fixed16_16::from_double(0.75).raw, 49152);
    EXPECT_EQ(Fixed16_16::from_double(-1.25).raw, -81920);
}

TEST(Fixed16_16, FloorIsExactForNegatives) {
    EXPECT_EQ(Fixed16_16::from_raw(-1).floor_int(), -1);
    EXPECT_EQ(Fixed16_16::from_raw(-65536).floor_int(), -1);
    EXPECT_EQ(Fixed16_16::from_raw(-65537).floor_int(), -2);
    EXPECT_EQ(Fixed16_16::from_raw(INT32_MIN).floor_int(), -32768);
    EXPECT_EQ(Fixed16_16::from_raw(INT32_MAX).floor_int(), 32767);
}

TEST(Fixed16_16, AddWrapsLikeTheAsmLoops) {
    auto a = Fixed16_16::from_raw(INT32_MAX) + Fixed16_16::from_raw(1);
    EXPECT_EQ(a.raw, INT32_MIN);
    auto b = Fixed16_16::from_raw(INT32_MIN) - Fixed16_16::from_raw(1);
    EXPECT_EQ(b.raw, INT32_MAX);
}

TEST(Fixed16_16, MultiplyRoundsAndSaturates) {
    EXPECT_EQ(Fixed16_16::from_double(1.5).mul(Fixed16_16::from_int(2)), Fixed16_16::from_int(3));
    EXPECT_EQ(Fixed16_16::from_raw(1).mul(Fixed16_16::from_raw(32768)).raw, 1);  // 2^-16 * 0.5 = half a step: up
    EXPECT_EQ(Fixed16_16::from_raw(-1).mul(Fixed16_16::from_raw(32768)).raw, 0);
    EXPECT_EQ(Fixed16_16::from_int(300).mul(Fixed16_16::from_int(300)).raw, INT32_MAX);
    EXPECT_EQ(Fixed16_16::from_int(-300).mul(Fixed16_16::from_int(300)).raw, INT32_MIN);
    EXPECT_EQ(Fixed16_16::from_raw(INT32_MIN).mul(Fixed16_16::from_raw(INT32_MIN)).raw, INT32_MAX);
}

TEST(Fixed24_8, SnapsScreenCoordinates) {
    EXPECT_EQ(Fixed24_8::from_double(1.0 / 512).raw, 1);   // a tie: up
    EXPECT_EQ(Fixed24_8::from_double(-1.0 / 512).raw, 0);
    EXPECT_EQ(Fixed24_8::from_double(160.25).raw, 41024);
    EXPECT_EQ(Fixed24_8::from_int(8388607).raw, 8388607 * 256);
    EXPECT_EQ(Fixed24_8::from_int(8388608).raw, INT32_MAX);
    EXPECT_EQ(Fixed24_8::from_double(16384.0).to_double(), 16384.0);
}

TEST(FixedN, FourFractionBitsRange) {  // the range formula at another width (28.4, Hecker's, which keeps plain ints)
    using Fixed28_4 = FixedN<4>;
    EXPECT_EQ(Fixed28_4::from_int(134217727).raw, 134217727 * 16);
    EXPECT_EQ(Fixed28_4::from_int(134217728).raw, INT32_MAX);
    EXPECT_EQ(Fixed28_4::from_int(-134217728).raw, INT32_MIN);
    EXPECT_EQ(Fixed28_4::from_double(0.03125).raw, 1);  // 1/32: a tie, up
    EXPECT_EQ(Fixed28_4::from_raw(-17).floor_int(), -2);
}

}  // namespace
