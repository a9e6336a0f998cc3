// Under test: kernel/mappers/quake_draw16.h (single_chop).
// The twin's x87 model (24-bit precision, chop) against this machine's own single-precision
// arithmetic rounding toward zero, which IEEE 754 defines as the x87 under Quake's single_cw gives
// it for operands and results inside float's range.
#include <cfenv>
#include <cstdint>
#include <cstring>

#include <gtest/gtest.h>

#include "kernel/mappers/quake_draw16.h"

namespace {

using namespace raster::single_chop;

struct Bits {
    uint64_t state;
    uint32_t next() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return uint32_t(state >> 32);
    }
    // a float of random significand and sign, its exponent within `spread` of 2^centre
    float value(int centre, int spread) {
        const uint32_t exponent = uint32_t(127 + centre + int(next() % uint32_t(2 * spread + 1)) - spread);
        const uint32_t b = (next() & 0x807FFFFFu) | (exponent << 23);
        float f;
        std::memcpy(&f, &b, sizeof f);
        return f;
    }
};

// The operations done under FE_TOWARDZERO, out of line so that none moves across fesetround.
[[gnu::noinline]] float sum(float a, float b) {
    volatile float r = a + b;
    return r;
}
[[gnu::noinline]] float product(float a, float b) {
    volatile float r = a * b;
    return r;
}
[[gnu::noinline]] float quotient(float a, float b) {
    volatile float r = a / b;
    return r;
}

TEST(QuakeDraw16, TheModelChopsAsSinglePrecisionTowardZero) {
    const int rounding = std::fegetround();
    Bits r{20261121};
    uint64_t far_apart = 0, opposite = 0;
    for (int i = 0; i < 2000000; ++i) {
        const float a = r.value(0, 40), b = r.value(0, i % 4 == 0 ? 40 : 8), n = float(int(r.next() % 320));
        std::fesetround(FE_TOWARDZERO);
        const float s = sum(a, b), p = product(a, b), pn = product(n, a), q = quotient(65536.0f, a);
        std::fesetround(rounding);
        ASSERT_EQ(add(a, b), double(s)) << a << " + " << b;
        ASSERT_EQ(mul(a, b), double(p)) << a << " * " << b;
        ASSERT_EQ(mul(n, a), double(pn)) << n << " * " << a;
        ASSERT_EQ(quotient_65536(a), double(q)) << "65536 / " << a;
        const double ratio = double(a) / double(b);
        if (ratio > 0x1p29 || ratio < -0x1p29 || (ratio < 0x1p-29 && ratio > -0x1p-29)) far_apart++, opposite += ratio < 0;
    }
    EXPECT_GT(opposite, 1000u) << "sums of opposite signs beyond 28 exponents apart, of " << far_apart;
}

}  // namespace
