// Differential checks of inner loops: random argument blocks run through the C++ twin and another
// implementation (the NASM loop) into separate buffers, compared byte for byte, guard bytes
// included. Portable: the 32-bit host tests and the kernel's `selftest` command run the same cases.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/mappers/loops.h"

namespace raster {

// xorshift32: small, portable, the same sequence everywhere.
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
};

struct CheckBuffers {
    uint8_t* a;           // the twin's destination
    uint8_t* b;           // the other's
    size_t size;          // of each; at least CHECK_DST_BYTES
    uint8_t* texels;      // at least CHECK_TEXEL_BYTES
};
constexpr size_t CHECK_DST_BYTES = 320 * 330 + 2 * 64;  // a column of 320 pixels 330 bytes apart, guards
constexpr size_t CHECK_TEXEL_BYTES = 1024 * 1024;

struct LoopCheck {
    const char* loop;
    uint32_t cases = 0;
    uint32_t mismatches = 0;
    uint32_t first_mismatch = 0;  // case number, valid when mismatches > 0
    uint32_t pixels = 0;
};

// The loops with NASM twins, one entry each. Loops that program the VGA cannot run on the host:
// the kernel checks those against the twin drawing into RAM planes (kernel/vga_selftest.cpp).
struct CheckedLoop {
    const char* name;
    LoopFn twin;
    LoopFn asm_loop;
    LoopCheck (*check)(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buffers);
    bool vga;  // the NASM loop writes VGA registers: `check` is null, the kernel checks it
};
extern const CheckedLoop CHECKED_LOOPS[];
extern const int CHECKED_LOOP_COUNT;

LoopCheck check_exact(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buffers);
LoopCheck check_hecker(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buffers);
LoopCheck check_fatmap(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buffers);
LoopCheck check_fatmap_lut(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buffers);
LoopCheck check_quake(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buffers);
LoopCheck check_fast_run(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf);
LoopCheck check_fast_column(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buffers);
LoopCheck check_xsharp_column(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buffers);

// Random XSharpRowArgs for a row of up to 320 pixels starting at plane offset `offset` of a page
// whose rows are 80 bytes (the kernel's VGA check), texel reads inside `texels` (CHECK_TEXEL_BYTES).
void random_xsharp_row(Random& r, const uint8_t* texels, XSharpRowArgs* a, int32_t* x, int32_t* y);

}  // namespace raster
