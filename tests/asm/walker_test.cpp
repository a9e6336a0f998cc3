// The walker's NASM routine for small triangles' rows (triangle_rows_asm, asm/walk.asm) against its
// C++ twin (triangle_rows): on random triangles under 64 pixels a side anywhere in the coordinate
// range, on and off the half-pixel grid, with edges along the rows (both refuse) and a clip cutting
// the rows now and then, the same answer and every byte of both chains the same, sentinels
// included.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "kernel/core/envelope.h"
#include "kernel/core/fixed.h"
#include "kernel/core/walk.h"
#include "kernel/mappers/fast.h"

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

// fast_triangle_asm (asm/fast_triangle.asm) against its twin (fast_triangle) on random triangles in range
// (both windings, small enough for the chains and not, on and off the half-pixel grid, edges along
// the rows, texture coordinates to beyond the 16.16 range, the clip cutting rows and columns now and
// then): where the NASM routine sets the triangle up, the same answer and every byte of the setup,
// the chains (each run's bounds at the same place) and the run loop's block; where it leaves it to
// C++, setup_triangle_affine_asm does too, and fast_triangle_runs_asm agrees with its twin from C++'s
// setup. `enveloped`: fast_triangle_enveloped_asm so, under random limits about each triangle's area
// and box, some steps past 32766 texels: 3 (the setup written) exactly where within_envelope says no.
void nasm_matches_the_twin(bool enveloped) {
    std::mt19937 rng(enveloped ? 20261201u : 20261127u);
    int unproven = 0;
    auto any = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    int walked = 0, drawn = 0, two = 0, empty = 0, left = 0, runs_alone = 0;
    static uint8_t screen[1];
    for (int n = 0; n < 200000; ++n) {
        const double size = n % 3 == 0 ? any(0.2, 4) : n % 11 == 0 ? any(50, 90) : any(0.2, 63.9);
        const double cx = any(-16000, 16000), cy = any(-16000, 16000);
        const double texels = n % 4 == 0 ? 256 : n % 4 == 1 ? any(0, 64) : n % 4 == 2 ? any(0, 20000) : any(-1e6, 1e6);
        Vertex v[3];
        for (Vertex& p : v) {
            p = Vertex{Fixed24_8::from_double(cx + any(0, size)), Fixed24_8::from_double(cy + any(0, size)), any(0.5, 100),
                       any(0, texels), any(0, texels)};
            if (n % 5 == 0) p.x.raw &= ~127, p.y.raw &= ~127;  // on the half-pixel grid: centres on edges and corners
        }
        if (n % 7 == 0) v[1].y = v[0].y;  // an edge along the rows
        const int32_t top = floor_i32(cy), left_x = floor_i32(cx), side = int32_t(size) + 1;
        ClipRect clip{left_x - 2, top - 2, left_x + side + 2, top + side + 2};
        if (n % 4 == 0) clip.y0 = top + int32_t(rng() % 8) - 2;
        if (n % 6 == 0) clip.y1 = top + side - int32_t(rng() % 8) + 2;
        if (n % 9 == 0) clip.x0 = left_x + int32_t(rng() % 8), clip.x1 = left_x + side - int32_t(rng() % 8);
        PolygonSetup setup[2];
        FastRunArgs run[2];
        FastTriangleArgs t[2];
        std::memset(setup, 0x5A, sizeof setup);
        std::memset(run, 0xA5, sizeof run);
        std::memset(t, 0x3C, sizeof t);
        Target target;  // (addresses only: never written)
        target.base = screen, target.pitch = 320 + 16 * int32_t(n % 5), target.clip = clip;
        // (limits about its own size: from a quarter of it to four times, both extents, or none)
        const double box = 256 * (size + 1), scale = std::exp2(any(-2, 2));
        EnvelopeLimits limits{n % 3 == 0 ? INT64_MAX : int64_t(box * box * scale), n % 4 == 0 ? INT32_MAX : int32_t(box * std::exp2(any(-2, 2))),
                              n % 5 == 0 ? INT32_MAX : int32_t(box * std::exp2(any(-2, 2)))};
        if (enveloped && n % 13 == 0) {  // a step about the guards' limit, 32766 texels a pixel, across or down, of u or v
            const double leg = any(0.5, 8), step = (rng() % 2 ? 1 : -1) * any(32764, 32769);
            v[1] = v[0], v[2] = v[0];
            v[1].x = Fixed24_8::from_double(v[0].x.to_double() + leg), v[2].y = Fixed24_8::from_double(v[0].y.to_double() + leg);
            double& coordinate = n % 2 ? (n % 4 < 2 ? v[1].u : v[2].u) : (n % 4 < 2 ? v[1].v : v[2].v);
            coordinate += step * leg;
        }
        for (int k = 0; k < 2; ++k) t[k].in = v, t[k].setup = &setup[k], t[k].run = &run[k], t[k].target = &target, t[k].envelope = &limits;
        const int by_nasm = enveloped ? fast_triangle_enveloped_asm(&t[1]) : fast_triangle_asm(&t[1]);
        if (by_nasm == 0) {
            PolygonSetup alone;
            ASSERT_EQ(setup_triangle_affine_asm(v, &alone), 0) << "triangle " << n;
            ++left;
            // from the rows on (fast_triangle_runs), on the C++ setup
            if (setup_polygon_cpp(v, 3, &setup[0], PLANES_AFFINE, Input::InRange) != SetupStatus::Ok) continue;
            setup[1] = setup[0];
            const int by_twin = fast_triangle_runs(&t[0]);
            ASSERT_EQ(fast_triangle_runs_asm(&t[1]), by_twin) << "triangle " << n;
            ASSERT_EQ(std::memcmp(&setup[0], &setup[1], sizeof setup[0]), 0) << "triangle " << n << ": the setup, read only";
            if (by_twin == 2) continue;
            ++runs_alone;
        }
        else {
            ASSERT_EQ(enveloped ? fast_triangle_enveloped(&t[0]) : fast_triangle(&t[0]), by_nasm) << "triangle " << n;
            ASSERT_EQ(std::memcmp(&setup[0], &setup[1], sizeof setup[0]), 0) << "triangle " << n << ": the setup";
            if (enveloped) {
                ASSERT_EQ(by_nasm == 3, !within_envelope(setup[0], limits)) << "triangle " << n;
            }
            if (by_nasm == 3) {
                ++unproven;
                continue;
            }
            if (by_nasm == 2) {
                ++walked;
                continue;
            }
        }
        ASSERT_EQ(std::memcmp(t[0].lower, t[1].lower, sizeof t[0].lower), 0) << "triangle " << n << ": lower bounds";
        ASSERT_EQ(std::memcmp(t[0].upper, t[1].upper, sizeof t[0].upper), 0) << "triangle " << n << ": upper bounds";
        // each run's bounds as their place in the block's chains, then every byte
        for (int k = 0; k < 2; ++k)
            for (EdgeBound** b : {&run[k].lower, &run[k].upper, &run[k].next_lower, &run[k].next_upper})
                if (run[k].lines > 0 && *b) *b = reinterpret_cast<EdgeBound*>(uintptr_t(reinterpret_cast<uint8_t*>(*b) - reinterpret_cast<uint8_t*>(&t[k])));
        ASSERT_EQ(std::memcmp(&run[0], &run[1], sizeof run[0]), 0) << "triangle " << n << ": the run loop's block";
        ++drawn;
        empty += run[0].lines == 0;
        two += run[0].lines > 0 && run[0].next_lines > 0;
    }
    const int at_least = enveloped ? 2 : 1;  // (a share of them unproven)
    EXPECT_GT(drawn * at_least, 60000);
    EXPECT_GT(walked * at_least, 20000) << "large boxes, edges along a row, vertices on a row's centre";
    EXPECT_GT(left, 5000) << "triangles setup_polygon sets up in C++";
    EXPECT_GT(runs_alone, 5000) << "of those, triangles walked from the rows on";
    EXPECT_GT(two * at_least, 30000) << "triangles in two runs";
    EXPECT_GT(empty * at_least, 1000) << "triangles between rows' centres, or clipped away";
    if (enveloped) {
        EXPECT_GT(unproven, 20000) << "triangles the envelope does not take";
    }
}

TEST(FastTriangle, NasmMatchesTheTwinBitForBit) { nasm_matches_the_twin(false); }
TEST(FastTriangle, EnvelopedNasmMatchesTheTwinBitForBit) { nasm_matches_the_twin(true); }

}  // namespace
