// Fixed-point numbers with the format in the type's name, and exact double-to-integer helpers.
// Portable, freestanding: kernel and host compute the same bits.
#pragma once

#include <stdint.h>

namespace raster {

// |t| and the larger of two, without libm (NaN stays NaN through magnitude: it fails any test).
inline double magnitude(double t) { return __builtin_fabs(t); }
inline double larger(double a, double b) { return a > b ? a : b; }

// The integer nearest x by the FPU's rounding mode, whatever it is (one FIST or CVTSD2SI): within
// 1 of x, |x| < 2^63. The floors below take it and step down where it lies above x, which gives
// floor(x) exactly under any rounding mode (a truncating conversion changes the x87's rounding
// mode and back around a FISTP).
inline int64_t nearby_i64(double x) { return __builtin_llrint(x); }

// floor(x) for |x| < SMALL_FLOOR, in 32 bits (a 32-bit FIST within 1 of x, no overflow): the floors
// below take this path first, with none of their range checks (NaN fails the test), and give the
// same value, cheaper on i686.
constexpr double SMALL_FLOOR = 2147483647.0;
inline int32_t floor_small(double x) {
    const int32_t t = int32_t(__builtin_lrint(x));
    return double(t) > x ? t - 1 : t;
}

// floor(x) as an integer, saturated to [INT32_MIN, INT32_MAX]; NaN gives 0.
inline int32_t floor_i32(double x) {
    if (magnitude(x) < SMALL_FLOOR) return floor_small(x);
    if (!(x == x)) return 0;
    if (x >= 2147483647.0) return INT32_MAX;
    if (x <= -2147483648.0) return INT32_MIN;
    const int64_t t = nearby_i64(x);
    return int32_t(double(t) > x ? t - 1 : t);
}

// floor(x) as a 64-bit integer, saturated to +-2^62; NaN gives 0.
inline int64_t floor_i64(double x) {
    constexpr double LIMIT = 4611686018427387904.0;  // 2^62
    if (magnitude(x) < SMALL_FLOOR) return floor_small(x);
    if (!(x == x)) return 0;
    if (x >= LIMIT) return int64_t(1) << 62;
    if (x <= -LIMIT) return -(int64_t(1) << 62);
    const int64_t t = nearby_i64(x);
    return double(t) > x ? t - 1 : t;
}

// floor(n / d) for d > 0, in 32 bits.
inline int32_t floor_div32(int32_t n, int32_t d) {
    const int32_t q = n / d;  // d > 0: no INT32_MIN / -1
    return n - q * d < 0 ? q - 1 : q;
}

// Floor division for a positive divisor: floor(n / d), d > 0. One division: on i686 (where a
// 64-bit one is a libgcc call) one IDIV of n by a 32-bit d wherever the quotient fits in 32 bits
// (checked first: beyond, IDIV faults); elsewhere in 32 bits when both fit.
inline int64_t floor_div(int64_t n, int64_t d) {
#if defined(__i386__)
    if (d == int64_t(int32_t(d)) && n >= -(d << 31) && n < (d << 31)) {
        int32_t q, r;
        __asm__("idivl %4" : "=a"(q), "=d"(r) : "a"(uint32_t(uint64_t(n))), "d"(int32_t(uint64_t(n) >> 32)), "rm"(int32_t(d)) : "cc");
        return r < 0 ? q - 1 : q;
    }
#else
    if (n == int64_t(int32_t(n)) && d == int64_t(int32_t(d))) return floor_div32(int32_t(n), int32_t(d));
#endif
    int64_t q = n / d;
    return n - q * d < 0 ? q - 1 : q;
}

// FixedN<F> holds a 32-bit two's-complement raw value r meaning r / 2^F.
//   Fixed16_16: range [-32768, 32768 - 2^-16], step 2^-16      (texture coordinates)
//   Fixed24_8:  range [-8388608, 8388608 - 2^-8], step 2^-8    (snapped screen coordinates)
// Overflow behaviour, by operation:
//   from_double, from_int, mul: round to nearest (ties up, toward +inf), then saturate to the range;
//                               NaN becomes 0.
//   add, sub:                   wrap modulo 2^32, as the asm inner loops do (no UB: done in uint32).
//   floor_int:                  arithmetic shift, exact floor.
template <int FRAC>
struct FixedN {
    static_assert(FRAC > 0 && FRAC < 31);
    static constexpr int FRAC_BITS = FRAC;
    static constexpr int32_t ONE = int32_t(1) << FRAC;
    static constexpr double SCALE = double(ONE);

    int32_t raw = 0;

    static constexpr FixedN from_raw(int32_t r) { return FixedN{r}; }

    static constexpr FixedN from_int(int32_t i) {
        constexpr int32_t MAX_INT = INT32_MAX >> FRAC;
        constexpr int32_t MIN_INT = INT32_MIN >> FRAC;
        if (i > MAX_INT) return FixedN{INT32_MAX};
        if (i < MIN_INT) return FixedN{INT32_MIN};
        return FixedN{int32_t(uint32_t(i) << FRAC)};
    }

    static FixedN from_double(double x) {
        const double y = x * SCALE + 0.5;
        return FixedN{magnitude(y) < SMALL_FLOOR ? floor_small(y) : saturate(floor_i64(y))};
    }

    constexpr int32_t floor_int() const { return raw >> FRAC; }
    constexpr double to_double() const { return double(raw) / SCALE; }

    // wraps modulo 2^32
    constexpr FixedN operator+(FixedN o) const { return FixedN{int32_t(uint32_t(raw) + uint32_t(o.raw))}; }
    constexpr FixedN operator-(FixedN o) const { return FixedN{int32_t(uint32_t(raw) - uint32_t(o.raw))}; }

    // rounds to nearest (ties up) and saturates
    constexpr FixedN mul(FixedN o) const {
        int64_t p = int64_t(raw) * int64_t(o.raw) + (int64_t(1) << (FRAC - 1));
        return FixedN{saturate(p >> FRAC)};
    }

    constexpr bool operator==(const FixedN&) const = default;

private:
    static constexpr int32_t saturate(int64_t v) {
        return v > INT32_MAX ? INT32_MAX : v < INT32_MIN ? INT32_MIN : int32_t(v);
    }
};

using Fixed16_16 = FixedN<16>;
using Fixed24_8 = FixedN<8>;

}  // namespace raster
