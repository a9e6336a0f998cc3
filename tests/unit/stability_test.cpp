// Stability at the extremes: huge and tiny polygons, slivers, coordinates and w at their limits,
// every mapper, both walkers, linear and planar targets: nothing is written outside the clip
// rectangle (guard bytes), the texture is never read outside (AddressSanitizer build), coverage
// stays the definition's.
#include <gtest/gtest.h>

#include "tests/unit/raster_helpers.h"

namespace {

using namespace rastertest;

constexpr uint8_t GUARD = 0xA5;
constexpr int32_t G = 8;  // guard pixels around the surface

std::vector<std::vector<Vertex>> extreme_polygons(uint32_t seed) {
    std::mt19937 rng(seed);
    auto pick = [&](std::initializer_list<double> values) { return *(values.begin() + rng() % values.size()); };
    auto any = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    const double L = MAX_COORD_PIXELS;
    std::vector<std::vector<Vertex>> out;
    for (int k = 0; k < 400; ++k) {
        std::vector<Vertex> p;
        int n = k % 5 == 0 ? 3 + int(rng() % 6) : 3;
        for (int i = 0; i < n; ++i) {
            double x = pick({any(-L, L), any(-2, 322), pick({-L, L, 0.0, 319.999, 160.5}), any(150, 151)});
            double y = pick({any(-L, L), any(-2, 242), pick({-L, L, 0.0, 239.999, 120.5}), any(100, 100.01)});
            double w = pick({MIN_W, MAX_W, 1.0, any(MIN_W, 1), any(1, MAX_W)});
            double u = pick({MAX_UV, -MAX_UV, any(-MAX_UV, MAX_UV), any(-2, 2), 32767.9, -32768.1});
            double v = pick({MAX_UV, -MAX_UV, any(-MAX_UV, MAX_UV), any(-2, 2), 65535.5});
            p.push_back(vertex(x, y, w, u, v));
        }
        out.push_back(p);
    }
    // the whole screen, under a triangle a thousand screens wide
    out.push_back({vertex(-L, -L, MIN_W, -MAX_UV, -MAX_UV), vertex(L, -L, MAX_W, MAX_UV, 0), vertex(0, L, 1, 0, MAX_UV)});
    return out;
}

TEST(Stability, NothingIsWrittenOutsideTheClipAndCoverageHolds) {
    const int32_t pitch = SCREEN_WIDTH + 2 * G;
    for (int m = 0; m < MAPPER_COUNT; ++m) {
        for (Axis axis : {Axis::Rows, Axis::Columns}) {
            for (Wrap wrap : {Wrap::Repeat, Wrap::Clamp}) {
                for (int32_t size : {1, 3, 64, 1024}) {
                    std::vector<uint8_t> texels(size_t(size) * size_t(size));  // exactly the size: ASan sees any stray read
                    generate_texture(TextureKind::Xor, size, size, texels.data());
                    Texture tex{texels.data(), size, size, wrap};
                    std::vector<uint8_t> surface(size_t(pitch) * size_t(SCREEN_HEIGHT + 2 * G), GUARD);
                    Target t = linear_target(surface.data() + G * pitch + G, SCREEN_WIDTH, SCREEN_HEIGHT, pitch);
                    t.clip = ClipRect{1, 2, SCREEN_WIDTH - 3, SCREEN_HEIGHT - 4};  // inner clip: its border is guarded too
                    RenderStats stats;
                    for (const auto& p : extreme_polygons(uint32_t(size))) draw_polygon(p.data(), int(p.size()), tex, MAPPERS[m], axis, t, &stats);
                    size_t written_outside = 0;
                    for (int32_t y = 0; y < SCREEN_HEIGHT + 2 * G; ++y)
                        for (int32_t x = 0; x < pitch; ++x) {
                            int32_t sx = x - G, sy = y - G;
                            bool inside = sx >= t.clip.x0 && sx < t.clip.x1 && sy >= t.clip.y0 && sy < t.clip.y1;
                            if (!inside && surface[size_t(y) * size_t(pitch) + size_t(x)] != GUARD) ++written_outside;
                        }
                    EXPECT_EQ(written_outside, 0u) << MAPPERS[m].name << " texture " << size;
                    EXPECT_GT(stats.polygons, 100u);
                    EXPECT_GT(stats.pixels, uint32_t(SCREEN_PIXELS)) << "the screen-sized triangle at least";
                }
            }
        }
    }
}

TEST(Stability, PlanarTargetsStayInTheirPage) {
    std::vector<uint8_t> texels(64 * 64);
    generate_texture(TextureKind::Grid, 64, 64, texels.data());
    Texture tex{texels.data(), 64, 64, Wrap::Repeat};
    for (int m = 0; m < MAPPER_COUNT; ++m) {
        std::vector<uint8_t> planes(4 * size_t(PLANE_BYTES) + 2 * 64, GUARD);
        Target t = planar_target(planes.data() + 64);
        int selects = 0;
        int last_plane = -1;
        struct Ctx { int* selects; int* last; } ctx{&selects, &last_plane};
        t.ctx = &ctx;
        t.select_plane = [](void* c, int plane) {
            auto* k = static_cast<Ctx*>(c);
            ++*k->selects;
            *k->last = plane;
        };
        RenderStats stats;
        for (const auto& p : extreme_polygons(5)) draw_polygon(p.data(), int(p.size()), tex, MAPPERS[m], Axis::Columns, t, &stats);
        RenderStats before = stats;
        std::vector<Vertex> big = {vertex(0, 0), vertex(300, 0), vertex(0, 200)};
        draw_polygon(big.data(), 3, tex, MAPPERS[m], Axis::Rows, t, &stats);
        EXPECT_EQ(stats.rejected, before.rejected + 1) << "rows on a planar target are refused";
        EXPECT_EQ(stats.pixels, before.pixels);
        for (int i = 0; i < 64; ++i) {
            EXPECT_EQ(planes[size_t(i)], GUARD);
            EXPECT_EQ(planes[planes.size() - 1 - size_t(i)], GUARD);
        }
        EXPECT_EQ(uint32_t(selects), stats.spans) << "one plane selection per column";
    }
}

TEST(Stability, HugeTrianglesCoverTheWholeScreenOnce) {
    const double L = MAX_COORD_PIXELS;
    std::vector<std::vector<Vertex>> halves = {{vertex(-L, -L), vertex(L, -L), vertex(L, L)}, {vertex(-L, -L), vertex(L, L), vertex(-L, L)}};
    for (Axis axis : {Axis::Rows, Axis::Columns}) {
        std::vector<int> counts = walk_counts(halves, axis);
        for (int c : counts) ASSERT_EQ(c, 1);
    }
}

TEST(Stability, TinyTrianglesCoverAtMostTheirPixel) {
    // triangles smaller than a pixel cover one pixel when they hold its centre, none otherwise
    std::mt19937 rng(3);
    for (int trial = 0; trial < 20000; ++trial) {
        int32_t x = int32_t(rng() % (320 * 256)), y = int32_t(rng() % (240 * 256));
        std::vector<Vertex> p = {vertex_raw(x, y), vertex_raw(x + 1 + int32_t(rng() % 200), y + int32_t(rng() % 50)),
                                 vertex_raw(x + int32_t(rng() % 50), y + 1 + int32_t(rng() % 200))};
        PolygonSetup s;
        if (setup_polygon(p.data(), 3, &s) != SetupStatus::Ok) continue;
        int total = 0;
        for (int c : walk_counts({p}, Axis::Rows)) total += c;
        ASSERT_LE(total, 1);
    }
}

}  // namespace
