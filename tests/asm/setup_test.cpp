// setup_polygon's NASM path for a frame's triangles (setup_triangle_affine_asm, asm/setup.asm)
// against its C++ twin (setup_polygon_cpp): on random triangles in range, both windings, tiny to
// across the whole coordinate range, with repeated corners, no area, texture coordinates from 0 to
// beyond the 16.16 range and steep enough to leave the 32-bit path, every byte of the setup the
// same wherever the NASM routine takes the triangle, and the same status where it leaves it to C++.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "kernel/core/setup.h"

namespace {

using namespace raster;

TEST(SetupTriangle, NasmMatchesTheTwinBitForBit) {
    std::mt19937 rng(4242u);
    auto any = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    int taken = 0, left = 0, left_ok = 0;
    for (int n = 0; n < 200000; ++n) {
        const double size = std::ldexp(1.0, int(rng() % 16) - 4);  // 1/16 to 2048 pixels
        const double cx = any(-15000, 15000), cy = any(-15000, 15000);
        const double texels = n % 4 == 0 ? 256 : n % 4 == 1 ? any(0, 64) : n % 4 == 2 ? any(0, 20000) : any(-1e6, 1e6);
        Vertex v[3];
        for (Vertex& p : v)
            p = Vertex{Fixed24_8::from_double(cx + any(0, size)), Fixed24_8::from_double(cy + any(0, size)), any(0.5, 100),
                       n % 8 == 0 ? any(-texels, texels) : any(0, texels), any(0, texels)};
        if (n % 10 == 3) {
            // on the 16.16 grid's half steps: corner 0 on a pixel centre with u and v there half a
            // step past a 16.16 value, the legs whole pixels along the axes, gradients half a step
            // past one: the floors meet x + 1/2 whole (a tie of the conversions)
            const double x0 = std::floor(cx) + 0.5, y0 = std::floor(cy) + 0.5, legs = double(1 + rng() % 40);
            const double u0 = (double(rng() % 4000000) + 0.5) / 65536, v0 = (double(rng() % 4000000) + 0.5) / 65536;
            auto step = [&] { return (double(int32_t(rng() % 200000) - 100000) + 0.5) / 65536 * legs; };
            v[0] = Vertex{Fixed24_8::from_double(x0), Fixed24_8::from_double(y0), 1, u0, v0};
            v[1] = Vertex{Fixed24_8::from_double(x0 + legs), Fixed24_8::from_double(y0), 1, u0 + step(), v0 + step()};
            v[2] = Vertex{Fixed24_8::from_double(x0), Fixed24_8::from_double(y0 + legs), 1, u0 + step(), v0 + step()};
        }
        if (n % 50 == 0) v[2] = v[0];                                           // a corner repeated,
        if (n % 50 == 17) v[1] = v[0];                                          // each pair of them
        if (n % 50 == 33) v[2] = v[1];
        if (n % 51 == 0) v[2].x.raw = 2 * v[1].x.raw - v[0].x.raw, v[2].y.raw = 2 * v[1].y.raw - v[0].y.raw;  // on a line
        if (!vertices_in_range(v, 3)) continue;
        PolygonSetup a, b;
        std::memset(&a, 0x5A, sizeof a);
        std::memset(&b, 0x5A, sizeof b);
        const SetupStatus twin = setup_polygon_cpp(v, 3, &a, PLANES_AFFINE, Input::InRange);
        if (setup_triangle_affine_asm(v, &b)) {
            ++taken;
            ASSERT_EQ(twin, SetupStatus::Ok) << "triangle " << n;
            ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "triangle " << n;
        } else {
            ++left;
            left_ok += twin == SetupStatus::Ok;
            // and setup_polygon, which takes the NASM routine first, still gives the twin's setup
            PolygonSetup c;
            std::memset(&c, 0x5A, sizeof c);
            ASSERT_EQ(setup_polygon(v, 3, &c, PLANES_AFFINE, Input::InRange), twin);
            ASSERT_TRUE(twin != SetupStatus::Ok || std::memcmp(&a, &c, sizeof a) == 0) << "triangle " << n;
        }
    }
    EXPECT_GT(taken, 80000);
    EXPECT_GT(left, 5000);
    EXPECT_GT(left_ok, 1000) << "triangles drawn whose values leave the 32-bit path";
}

}  // namespace
