// Differential checks of inner loops: random argument blocks run through the C++ twin and another
// implementation (the NASM loop) into separate buffers, compared byte for byte, guard bytes
// included. Each mapper's cases live beside its twin (kernel/mappers/NAME.cpp, the registry's
// `check`); this is the machinery they share. Portable: the 32-bit host tests and the kernel's
// `selftest` command run the same cases.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/core/mapper.h"
#include "kernel/core/random.h"

namespace raster {

struct CheckBuffers {
    uint8_t* a;           // the twin's destination
    uint8_t* b;           // the other's
    size_t size;          // of each; at least CHECK_DST_BYTES
    uint8_t* texels;      // at least CHECK_TEXEL_BYTES
};
constexpr size_t CHECK_DST_BYTES = 320 * 330 + 2 * 64;  // a column of 320 pixels 330 bytes apart, guards
constexpr size_t CHECK_TEXEL_BYTES = 1024 * 1024;
constexpr uint8_t CHECK_GUARD = 0xC3;
constexpr size_t CHECK_GUARD_BYTES = 64;
// Texture walks of the pointer loops start in the middle of the texel buffer; each check bounds
// its random advances so that no walk can leave it: count * (|base| + 1 + |row|) < 512 KiB.
constexpr int32_t CHECK_TEXEL_MID = int32_t(CHECK_TEXEL_BYTES / 2);

struct LoopCheck {
    const char* loop;
    uint32_t cases = 0;
    uint32_t mismatches = 0;
    uint32_t first_mismatch = 0;  // case number, valid when mismatches > 0
    uint32_t pixels = 0;
};

// The mappers with a NASM loop, one per loop (of mappers sharing a loop, the first) in registry
// order, whether or not this build links the loops; those with NEED_VGA_FOR_ASM have no `check`:
// the kernel checks them on the VGA.
int checked_loops(const Mapper** out, int capacity);

// A case's destination window [lo, hi) of the buffers (its pixels and the guard bytes on either
// side), and the pixels it draws.
struct CheckWindow {
    size_t lo, hi;
    uint32_t pixels;
};

// Where a case's pointers into buffer a go in buffer b, what a loop gives back besides pixels, and
// the block the loop takes: specialised for argument blocks with more than a destination.
template <typename Args>
void move_to_b(Args& b, const Args& a, const CheckBuffers& buf) {
    b.dst = buf.b + (a.dst - buf.a);
}
template <typename Args>
bool same_results(const Args&, const Args&) {
    return true;
}
template <typename Args>
const void* check_block(const Args& a) {
    return &a;
}

// Random texels once per check; each case views what it needs of them.
void fill_check_texels(Random& r, uint8_t* texels);

// Runs `cases` random cases: make(r, a) fills an argument block drawing into buffer a and returns
// its window; both implementations run it, each into its own buffer, and the windows must agree
// byte for byte (and any other results).
template <typename Args, typename Make>
LoopCheck check_cases(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf, Make make) {
    LoopCheck result;
    result.loop = m.name;
    Random r(seed);
    fill_check_texels(r, buf.texels);
    for (uint32_t c = 0; c < cases; ++c) {
        Args a;
        CheckWindow w = make(r, a);
        Args b = a;
        move_to_b(b, a, buf);
        __builtin_memset(buf.a + w.lo, CHECK_GUARD, w.hi - w.lo);
        __builtin_memset(buf.b + w.lo, CHECK_GUARD, w.hi - w.lo);
        m.twin(check_block(a));
        other(check_block(b));
        const bool same = same_results(a, b) && __builtin_memcmp(buf.a + w.lo, buf.b + w.lo, w.hi - w.lo) == 0;
        ++result.cases;
        result.pixels += w.pixels;
        if (!same && result.mismatches++ == 0) result.first_mismatch = c;
    }
    return result;
}

// A span's pixel count: one case in eight short (short_lo..short_hi), the rest 1..longest.
inline int32_t random_count(Random& r, int32_t short_lo, int32_t short_hi, int32_t longest) {
    return r.below(8) == 0 ? r.range(short_lo, short_hi) : r.range(1, longest);
}
// Points a's destination at a span of a.count pixels `stride` bytes apart in buffer a (check_span)
// and returns its window.
template <typename Args>
CheckWindow place_span(const CheckBuffers& buf, Args& a, int32_t stride) {
    CheckWindow w;
    a.dst = check_span(buf, a.count, stride, &w);
    return w;
}

// A texture size the loops accept: 1..1024, often a power of two, sometimes an extreme.
int32_t random_texture_size(Random& r);
// Random power-of-two sides up to 1024 of a texture whose doubled copy fits the check's texels;
// above256: one side above 256 (beyond_tile).
void random_doubled_sides(Random& r, int32_t* w, int32_t* h, bool above256 = true);
// Makes the check's texels a doubled copy (make_doubled's layout, from buf.texels) of a w x h
// texture whose texel (u, v) is a hash of u, v and salt: a loop reading the copy anywhere reads the
// texel a read by masks from its origin reads.
void fill_check_doubled(const CheckBuffers& buf, int32_t w, int32_t h, uint32_t salt);
// A span of count pixels `stride` bytes apart (count >= 0, stride either way, not 0) between the
// guards in buffer a: its first pixel and its window.
uint8_t* check_span(const CheckBuffers& buf, int32_t count, int32_t stride, CheckWindow* w);
// A stride for loops that take any: 1 half the time, else -330..330 (80 for 0).
int32_t random_stride(Random& r);
// The texture fields of a block for loops that take any texture (texels, width, height, clamp):
// sizes 1..1024, repeat or clamp, over the check's texels.
template <typename Args>
void random_check_texture(Random& r, const CheckBuffers& buf, Args& a) {
    int32_t w = random_texture_size(r), h = random_texture_size(r);
    a.texels = buf.texels;
    a.width = w;
    a.height = h;
    a.clamp = int32_t(r.below(2));
}
// The 64 KiB-aligned texture the fatmap-style loops need: the first such address in the buffer.
const uint8_t* check_aligned_texture(const CheckBuffers& buf);
// Three planes (a0, gx, gy each): from a real set-up triangle most of the time, else raw values up
// to the extremes, now and then with 1/w zero everywhere (infinities and NaN).
void random_planes(Random& r, double* q, double* pu, double* pv);

// Random s/z, t/z and 1/z for the Quake loops, origins and steps a pixel across and down (in the
// argument block's own type, double or float): from random_planes, the origin moved along the row.
template <typename Args>
void random_span_planes(Random& r, Args& a) {
    double q[3], pu[3], pv[3];
    random_planes(r, q, pu, pv);
    using T = decltype(a.s_origin);
    auto per_pixel = [&](const double* p, T* origin, T* stepu, T* stepv) {
        *stepu = T(p[1] * 256), *stepv = T(p[2] * 256);
        *origin = T(p[0] + double(r.range(-100000, 100000)) * 1e-3 * (p[1] * 256));
    };
    per_pixel(pu, &a.s_origin, &a.s_stepu, &a.s_stepv);
    per_pixel(pv, &a.t_origin, &a.t_stepu, &a.t_stepv);
    per_pixel(q, &a.z_origin, &a.z_stepu, &a.z_stepv);
}

// Random 16.16 coordinates and steps for the 8:16 loops: anything at all a quarter of the time,
// else steps up to 4 texels a pixel.
template <typename Args>
void random_uv(Random& r, Args& a) {
    a.u_16_16 = int32_t(r.next());
    a.v_16_16 = int32_t(r.next());
    a.du_16_16 = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
    a.dv_16_16 = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
}

}  // namespace raster
