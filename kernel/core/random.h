// Random numbers for the loop checks and the polygon fuzzer: xorshift32, small, portable, the same
// sequence on the host and in the kernel.
#pragma once

#include <stdint.h>

namespace raster {

struct Random {
    uint32_t state;
    explicit Random(uint32_t seed) : state(seed ? seed : 0x9E3779B9u) {}
    uint32_t next() {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return state;
    }
    uint32_t below(uint32_t n) { return n ? next() % n : 0; }
    int32_t range(int32_t lo, int32_t hi) { return lo + int32_t(below(uint32_t(hi - lo + 1))); }
    double unit() { return double(next()) / 4294967296.0; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    // 2^e (1 + f), e uniform in [e_lo, e_hi), f in [0, 1): spread evenly over the octaves
    double octaves(int e_lo, int e_hi) {
        const int e = e_lo + int(below(uint32_t(e_hi - e_lo)));
        double p = 1;
        for (int i = 0; i < e; ++i) p *= 2;
        for (int i = 0; i > e; --i) p *= 0.5;
        return p * (1 + unit());
    }
};

}  // namespace raster
