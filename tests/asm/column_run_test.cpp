// fast-columns' run of columns (fast_column_run_asm, asm/fast.asm) against its C++ twin
// (fast_column_run): random runs of columns, one or two a call, their bounds stepping through and
// out of the clip (and constant, as the driver's lone columns are), u and v anywhere with steps of
// up to several texels, into a Mode X planar target in RAM filled with a guard byte, with and
// without a select_plane callback (each call logged): every byte of the planes, the tallies, the
// bounds after the call and the planes asked for the same. A random tiled block of texels, so that
// a wrong texel shows. (The registry's check, check_fast_column_run, covers the doubled copy and
// the kernel's selftest; this one the plane selection.)
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "kernel/core/surface.h"
#include "kernel/core/walk.h"
#include "kernel/mappers/fast.h"

namespace {

using namespace raster;

struct PlaneLog {
    std::vector<int> planes;
};
void log_plane(void* ctx, int plane) { static_cast<PlaneLog*>(ctx)->planes.push_back(plane); }

TEST(FastColumnRun, NasmMatchesTheTwinBitForBit) {
    std::mt19937 rng(20261129u);
    auto any = [&](int32_t lo, int32_t hi) { return std::uniform_int_distribution<int32_t>(lo, hi)(rng); };
    // the tiled block, 64 KiB-aligned, of random texels
    std::vector<uint8_t> texels(3 * 65536);
    for (uint8_t& t : texels) t = uint8_t(rng());
    const uint8_t* block = reinterpret_cast<const uint8_t*>((reinterpret_cast<uintptr_t>(texels.data()) + 0xFFFF) & ~uintptr_t(0xFFFF));
    auto bound = [&](int32_t most) {
        if (any(0, 9) == 0) return EdgeBound::constant(any(-20, most + 20));
        EdgeBound b;
        b.first = b.last = 0;
        b.d = uint32_t(any(1, any(0, 3) ? 300 : 1 << 30));
        b.q = any(-60, most + 60), b.dq = any(-4, 4), b.r = uint32_t(any(0, int32_t(b.d - 1))), b.dr = uint32_t(any(0, int32_t(b.d - 1)));
        return b;
    };
    int64_t pixels = 0;
    int called = 0, two_runs = 0;
    for (int n = 0; n < 30000; ++n) {
        std::vector<uint8_t> planes[2] = {std::vector<uint8_t>(4 * PLANE_BYTES, 0xC3), std::vector<uint8_t>(4 * PLANE_BYTES, 0xC3)};
        PlaneLog logs[2];
        Target targets[2];
        EdgeBound bounds[2][4];
        uint32_t tallies[2][2] = {};
        FastColumnRunArgs args[2];
        const int32_t clip_lo = any(0, 239), clip_hi = any(0, 7) == 0 ? clip_lo - 1 : any(clip_lo, 239);
        const int32_t x = any(0, 319), room = 320 - x;
        const int32_t lines = any(0, 7) == 0 ? any(0, 2) : any(1, room);
        const int32_t next = any(0, 1) ? 0 : any(-1, room - (lines > 0 ? lines : 0));
        const bool select = n % 2 == 0;
        for (int k = 0; k < 4; ++k) bounds[0][k] = bound(239);
        FastColumnRunArgs& a = args[0];
        a.block_pitch = 0;
        a.x = x, a.lines = lines, a.clip_lo = clip_lo, a.clip_hi = clip_hi, a.next_lines = next;
        a.texture = block;
        a.u_16_16 = uint32_t(rng()), a.v_16_16 = uint32_t(rng());
        a.u_column_16_16 = any(0, 3) ? uint32_t(any(-0x40000, 0x40000)) : uint32_t(rng());
        a.v_column_16_16 = any(0, 3) ? uint32_t(any(-0x40000, 0x40000)) : uint32_t(rng());
        a.du_16_16 = any(0, 3) ? any(-0x40000, 0x40000) : int32_t(rng());
        a.dv_16_16 = any(0, 3) ? any(-0x40000, 0x40000) : int32_t(rng());
        std::memcpy(bounds[1], bounds[0], sizeof bounds[0]);
        args[1] = args[0];
        for (int k = 0; k < 2; ++k) {
            targets[k] = planar_target(planes[k].data());
            if (select) targets[k].select_plane = log_plane, targets[k].ctx = &logs[k];
            args[k].target = &targets[k];
            args[k].lower = &bounds[k][0], args[k].upper = &bounds[k][1];
            args[k].next_lower = &bounds[k][2], args[k].next_upper = &bounds[k][3];
            args[k].tally = tallies[k];
        }
        fast_column_run(&args[0]);
        fast_column_run_asm(&args[1]);
        ASSERT_EQ(planes[0], planes[1]) << "case " << n;
        ASSERT_EQ(tallies[0][0], tallies[1][0]) << "case " << n;
        ASSERT_EQ(tallies[0][1], tallies[1][1]) << "case " << n;
        ASSERT_EQ(std::memcmp(bounds[0], bounds[1], sizeof bounds[0]), 0) << "case " << n;
        ASSERT_EQ(logs[0].planes, logs[1].planes) << "case " << n;
        pixels += tallies[0][1];
        called += int(logs[0].planes.size());
        two_runs += lines > 0 && next > 0 && tallies[0][0] > 0;
    }
    EXPECT_GT(pixels, 10000000);
    EXPECT_GT(called, 100000);
    EXPECT_GT(two_runs, 1000);
}

}  // namespace
