// The walker's NASM routine for small triangles' rows (triangle_rows_asm, asm/fast.asm) against its
// C++ twin (triangle_rows): on random triangles under 64 pixels a side anywhere in the coordinate
// range, on and off the half-pixel grid, with edges along the rows (both refuse) and a clip cutting
// the rows now and then, the same answer and every byte of both chains the same, sentinels
// included.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "kernel/core/walk.h"

namespace {

using namespace raster;

TEST(TriangleRows, NasmMatchesTheTwinBitForBit) {
    std::mt19937 rng(20261125u);
    auto any = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    int drawn = 0, refused = 0, swapped = 0;
    for (int n = 0; n < 200000; ++n) {
        const double size = n % 3 == 0 ? any(0.2, 4) : any(0.2, 63.9);
        const double cx = any(-16000, 16000), cy = any(-16000, 16000);
        Vertex v[3];
        for (Vertex& p : v) {
            p = Vertex{Fixed24_8::from_double(cx + any(0, size)), Fixed24_8::from_double(cy + any(0, size)), 1, 0, 0};
            if (n % 5 == 0) p.x.raw &= ~127, p.y.raw &= ~127;  // on the half-pixel grid: centres on edges and corners
        }
        if (n % 7 == 0) v[1].y = v[0].y;  // an edge along the rows
        PolygonSetup s;
        if (setup_polygon(v, 3, &s, PLANES_NONE) != SetupStatus::Ok) continue;
        if (s.max_x - s.min_x >= (64 << SUBPIXEL_BITS) || s.max_y - s.min_y >= (64 << SUBPIXEL_BITS)) continue;
        // the rows as EdgeWalker takes them: those whose centre lies in the box, clipped
        int32_t first = int32_t((s.min_y - SUBPIXEL_HALF + SUBPIXEL_ONE - 1) >> SUBPIXEL_BITS);
        int32_t last = int32_t((s.max_y - SUBPIXEL_HALF) >> SUBPIXEL_BITS);
        if (n % 4 == 0 && last > first) first += int32_t(rng() % uint32_t(last - first + 1));
        if (n % 6 == 0 && last > first) last -= int32_t(rng() % uint32_t(last - first + 1));
        if (first > last) continue;
        EdgeBound lower[2][3], upper[2][3];
        std::memset(lower, 0xA5, sizeof lower);
        std::memset(upper, 0xA5, sizeof upper);
        const int32_t ox = int32_t(s.min_x >> SUBPIXEL_BITS), oy = int32_t(s.min_y >> SUBPIXEL_BITS);
        const TriangleRowsArgs twin{s.edges, first, last, ox, oy, lower[0], upper[0]};
        const TriangleRowsArgs nasm{s.edges, first, last, ox, oy, lower[1], upper[1]};
        const bool by_twin = triangle_rows(&twin);
        const bool by_nasm = triangle_rows_asm(&nasm) != 0;
        ASSERT_EQ(by_twin, by_nasm) << "triangle " << n;
        ASSERT_EQ(std::memcmp(lower[0], lower[1], sizeof lower[0]), 0) << "triangle " << n << ": lower bounds";
        ASSERT_EQ(std::memcmp(upper[0], upper[1], sizeof upper[0]), 0) << "triangle " << n << ": upper bounds";
        if (!by_twin) {
            ++refused;
            continue;
        }
        ++drawn;
        for (const EdgeBound* chain : {lower[0], upper[0]})
            if (chain[1].first != INT32_MAX && chain[0].first < chain[1].first && chain[0].last < chain[1].first) ++swapped;
    }
    EXPECT_GT(drawn, 100000);
    EXPECT_GT(refused, 5000);
    EXPECT_GT(swapped, 10000) << "chains of two, both orders";
}

}  // namespace
