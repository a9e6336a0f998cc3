// Under test: kernel/mappers/xsharp.h, hecker.h, fatmap.h, quake.h.
// The classic mappers' own properties: what each reproduces, checked where the published
// algorithm says what it does (docs/classics.md).
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "kernel/core/bound.h"
#include "kernel/core/policy.h"
#include "kernel/mappers/classic.h"
#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

// How often the mapper drew each pixel, one polygon at a time (planes for the planar mappers).
std::vector<int> draw_counts(const Mapper& m, const std::vector<std::vector<Vertex>>& polygons, int32_t tex_size) {
    std::vector<uint8_t> ones(size_t(tex_size) * size_t(tex_size), 1);
    Texture tex{ones.data(), tex_size, tex_size, Wrap::Repeat};
    TextureCopies copies(&tex);
    std::vector<int> counts(SCREEN_PIXELS, 0);
    for (const auto& p : polygons) {
        std::vector<uint8_t> surface(SCREEN_PIXELS, 0), linear(SCREEN_PIXELS);
        Axis axis = home_axis(m);
        bool planar = ram_planar(m, axis);
        Target t = ram_target(surface.data(), planar);
        RenderStats stats;
        draw_polygon(p.data(), int(p.size()), tex, m, axis, t, &stats);
        if (planar) linear_from_planar(surface.data(), linear.data());
        else linear = surface;
        for (int i = 0; i < SCREEN_PIXELS; ++i) counts[size_t(i)] += linear[size_t(i)];
    }
    return counts;
}

// A jittered grid of triangles on whole pixels (the classics' vertices), texture inside 0..64.
std::vector<std::vector<Vertex>> integer_mesh(uint32_t seed, std::vector<Vertex>* outline) {
    std::mt19937 rng(seed);
    const int cols = 6, rows = 5;
    std::vector<std::vector<Vertex>> grid(cols + 1, std::vector<Vertex>(rows + 1));
    for (int i = 0; i <= cols; ++i)
        for (int j = 0; j <= rows; ++j) {
            bool inner = i > 0 && i < cols && j > 0 && j < rows;
            int x = 20 + i * 45 + (inner ? int(rng() % 21) - 10 : 0), y = 10 + j * 44 + (inner ? int(rng() % 21) - 10 : 0);
            grid[size_t(i)][size_t(j)] = vertex(x, y, 1, i * 64.0 / cols, j * 64.0 / rows);
        }
    std::vector<std::vector<Vertex>> tris;
    for (int i = 0; i < cols; ++i)
        for (int j = 0; j < rows; ++j) {
            const Vertex &a = grid[size_t(i)][size_t(j)], &b = grid[size_t(i + 1)][size_t(j)], &c = grid[size_t(i + 1)][size_t(j + 1)],
                         &d = grid[size_t(i)][size_t(j + 1)];
            tris.push_back({a, b, c});
            tris.push_back({a, c, d});
        }
    *outline = {grid[0][0], grid[cols][0], grid[cols][rows], grid[0][rows]};
    return tris;
}

TEST(XSharp, TheAsmRowLoopDrawsWhatTheCListingDraws) {
    // listing 57.2 is listing 57.1 in assembly: the same pixels, the same texels
    TriangleGen gen(31);
    for (int batch = 0; batch < 10; ++batch) {
        auto scene = empty_scene(TextureKind::Xor, 128, 128, Wrap::Repeat);
        for (int k = 0; k < 40; ++k) {
            std::vector<Vertex> t = gen.triangle();
            for (Vertex& v : t) v.u = std::fmod(std::fabs(v.u), 128.0), v.v = std::fmod(std::fabs(v.v), 128.0);
            add_polygon(*scene, t);
        }
        LoadedScene s = make_loaded_scene(std::move(scene), "random");
        RenderStats a, b;
        IndexImage dda = render_mapper(s, mapper("xsharp-dda"), Axis::Rows, &a);
        IndexImage out = render_mapper(s, mapper("xsharp-row-out"), Axis::Rows, &b);
        EXPECT_TRUE(compare(out, dda).equal()) << "batch " << batch << ": " << compare(out, dda).summary();
        EXPECT_EQ(a.pixels, b.pixels);
        EXPECT_GT(a.pixels, 1000u);
    }
}

TEST(XSharp, MeshesOnWholePixelsAreWatertight) {
    // X-Sharp's fill convention (top and left edges in, bottom and right out) leaves no gaps and no
    // overlaps between polygons sharing edges, by rows (57.x) and by columns (X-Sharp 22)
    for (const char* name : {"xsharp-dda", "xsharp-column"}) {
        for (uint32_t seed = 1; seed <= 20; ++seed) {
            std::vector<Vertex> outline;
            auto tris = integer_mesh(seed, &outline);
            std::vector<int> mesh = draw_counts(mapper(name), tris, 64), whole = draw_counts(mapper(name), {outline}, 64);
            int overlaps = 0, holes = 0, outside = 0;
            for (size_t i = 0; i < mesh.size(); ++i) {
                overlaps += mesh[i] > 1;
                holes += whole[i] == 1 && mesh[i] == 0;
                outside += whole[i] == 0 && mesh[i] > 0;
            }
            EXPECT_EQ(overlaps, 0) << name << " seed " << seed;
            EXPECT_EQ(holes, 0) << name << " seed " << seed;
            EXPECT_EQ(outside, 0) << name << " seed " << seed;
        }
    }
}

TEST(XSharp, AnAxisAlignedSquareMapsTexelForTexel) {
    // 64 x 64 pixels on whole pixels showing a 64 x 64 texture: every texel exactly once, as the
    // reference does; the half-step and the rounding to the nearest texel center the samples
    auto scene = empty_scene(TextureKind::Xor, 64, 64, Wrap::Clamp);
    add_polygon(*scene, {vertex(100, 50, 1, 0, 0), vertex(164, 50, 1, 64, 0), vertex(164, 114, 1, 64, 64), vertex(100, 114, 1, 0, 64)});
    LoadedScene s = make_loaded_scene(std::move(scene), "square");
    auto ref = render_reference(s);
    for (const char* name : {"xsharp-dda", "xsharp-row-out", "xsharp-column"}) {
        const Mapper& m = mapper(name);
        AccuracyMetrics a = compare_to_reference(ref->view, measure_mapper(s, m, home_axis(m))->view, 64, 64, Wrap::Clamp);
        EXPECT_EQ(a.gaps + a.overdraw + a.overlaps, 0u) << name;
        EXPECT_EQ(a.max_texel_error, 0u) << name;
        EXPECT_EQ(a.reference_pixels, 64u * 64u);
    }
}

TEST(XSharp, CoordinatesBeyondTheTextureAreRefusedNotWrapped) {
    // X-Sharp could not wrap: a polygon whose texture coordinates span more than the texture is
    // not drawn (its pointers would walk off the bitmap); one that fits after a whole-period shift is
    auto scene = empty_scene(TextureKind::Xor, 64, 64, Wrap::Repeat);
    add_polygon(*scene, {vertex(10, 10, 1, 0, 0), vertex(100, 10, 1, 100, 0), vertex(10, 100, 1, 0, 20)});    // u spans 100 > 64
    add_polygon(*scene, {vertex(120, 10, 1, 640, 64), vertex(200, 10, 1, 700, 64), vertex(120, 100, 1, 640, 128)});  // fits after -640, -64
    LoadedScene s = make_loaded_scene(std::move(scene), "wrap");
    for (const char* name : {"xsharp-dda", "xsharp-row-out", "xsharp-column"}) {
        RenderStats stats;
        render_mapper(s, mapper(name), home_axis(mapper(name)), &stats);
        EXPECT_EQ(stats.rejected, 1u) << name;
        EXPECT_EQ(stats.polygons, 1u) << name;
    }
    classic::Vertex16 out[3];
    int n;
    std::vector<Vertex> bowtie_free = {vertex(0, 0, 1, 0, 0), vertex(10, 0, 1, 64.5, 0), vertex(0, 10, 1, 0, 0)};
    std::vector<uint8_t> t(64 * 64);
    EXPECT_EQ(classic::convert(bowtie_free.data(), 3, Texture{t.data(), 64, 64, Wrap::Clamp}, 0, out, &n), SetupStatus::OutsideTexture);
}

}  // namespace

namespace {

using namespace rastertest;

TEST(Hecker, CoverageIsTheTopLeftRuleOnIts28_4Grid) {
    // with vertices on his 1/16-pixel grid, Hecker's ceil-based edges cover exactly what the
    // reference covers (his pixel centres at integers are ours at +1/2)
    TriangleGen gen(5);
    const Mapper& m = mapper("hecker-steptable");
    int triangles = 0;
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<Vertex> t = gen.triangle();
        for (Vertex& v : t) {
            v.x = Fixed24_8::from_raw(v.x.raw & ~15);
            v.y = Fixed24_8::from_raw(v.y.raw & ~15);
            v.u = 1 + std::fmod(std::fabs(v.u), 60.0);
            v.v = 1 + std::fmod(std::fabs(v.v), 60.0);
        }
        PolygonSetup s;
        if (setup_polygon(t.data(), 3, &s) != SetupStatus::Ok) continue;
        // his Fixed28_4Mul truncates the gradients' cross product: a triangle of a few 1/256 pixel
        // squares can come out as zero, and then it is not drawn at all (a flaw we keep)
        auto h = [&](int i, bool y) { return ((y ? t[size_t(i)].y.raw : t[size_t(i)].x.raw) - 128) / 16; };
        int64_t x1y0 = (int64_t(h(1, false) - h(2, false)) * (h(0, true) - h(2, true))) / 16;
        int64_t x0y1 = (int64_t(h(0, false) - h(2, false)) * (h(1, true) - h(2, true))) / 16;
        bool dropped = x1y0 == x0y1;
        std::vector<int> counts = draw_counts(m, {t}, 64);
        for (int32_t y = 0; y < SCREEN_HEIGHT; ++y)
            for (int32_t x = 0; x < SCREEN_WIDTH; ++x)
                ASSERT_EQ(counts[size_t(y) * SCREEN_WIDTH + size_t(x)], !dropped && covers(s, x, y) ? 1 : 0)
                    << "trial " << trial << " pixel " << x << "," << y;
        ++triangles;
    }
    EXPECT_GT(triangles, 250);
}

TEST(Hecker, SubdivisionKeepsPerspectiveWithinATexel) {
    // the tilted disc: 8-pixel affine pieces between exact points stay within one texel of the
    // reference, where one affine plane over the polygon is off by dozens
    LoadedScene s = load_scene_file("scenes/screen/polygon-12.scene");
    auto ref = render_reference(s);
    AccuracyMetrics h = compare_to_reference(ref->view, measure_mapper(s, mapper("hecker-steptable"), Axis::Rows)->view, 128, 128, Wrap::Repeat);
    AccuracyMetrics a = compare_to_reference(ref->view, measure_mapper(s, mapper("affine"), Axis::Rows)->view, 128, 128, Wrap::Repeat);
    EXPECT_LE(h.max_texel_error, 1u);
    EXPECT_GT(double(h.exact) / h.compared, 0.9);
    EXPECT_GT(a.max_texel_error, 20u);
}

}  // namespace

namespace {

using namespace rastertest;

// A 256 x 256 texture magnified: one triangle pair showing 40 x 30 texels over most of the screen,
// with start fractions that are not whole (so dropping them shows).
LoadedScene magnified(uint32_t seed) {
    std::mt19937 rng(seed);
    auto any = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    auto scene = empty_scene(TextureKind::Xor, 256, 256, Wrap::Repeat);
    double u0 = any(10, 200), v0 = any(10, 200);
    std::vector<Vertex> q = {vertex(any(5, 20), any(5, 20), 1, u0, v0), vertex(any(300, 315), any(5, 20), 1, u0 + 40.3, v0 + 3.7),
                             vertex(any(300, 315), any(220, 235), 1, u0 + 44.1, v0 + 33.9), vertex(any(5, 20), any(220, 235), 1, u0 + 2.6, v0 + 30.2)};
    add_polygon(*scene, {q[0], q[1], q[2]});
    add_polygon(*scene, {q[0], q[2], q[3]});
    return make_loaded_scene(std::move(scene), "magnified");
}

TEST(Fatmap, TheThreeLoopsShareOneDriverAndItsCoverage) {
    for (uint32_t seed = 1; seed <= 10; ++seed) {
        LoadedScene s = magnified(seed);
        RenderStats a, b, c;
        render_mapper(s, mapper("fatmap-256"), Axis::Rows, &a);
        render_mapper(s, mapper("fatmap-256-16"), Axis::Rows, &b);
        render_mapper(s, mapper("fatmap-lut"), Axis::Rows, &c);
        EXPECT_EQ(a.pixels, b.pixels);
        EXPECT_EQ(a.pixels, c.pixels);
        EXPECT_EQ(a.spans, c.spans);
        EXPECT_GT(a.pixels, 50000u);
    }
}

TEST(Fatmap, SixteenFractionBitsBeatEightAndTheTableDistorts) {
    // fatmap.txt: 8-bit fractions are "shaky"; the lookup table, starting every scanline at its
    // first entry, drops the start fractions ("very bad distortion especially when ... zoomed in")
    double mean8 = 0, mean16 = 0, mean_lut = 0, exact8 = 0, exact_lut = 0;
    for (uint32_t seed = 1; seed <= 10; ++seed) {
        LoadedScene s = magnified(seed);
        AccuracyMetrics m8 = accuracy(s, "fatmap-256"), m16 = accuracy(s, "fatmap-256-16"), lut = accuracy(s, "fatmap-lut");
        mean8 += m8.mean_texel_error, mean16 += m16.mean_texel_error, mean_lut += lut.mean_texel_error;
        exact8 += double(m8.exact) / m8.compared, exact_lut += double(lut.exact) / lut.compared;
        EXPECT_LE(lut.max_texel_error, 3u) << "start fractions cost at most a texel, plus the 8-bit drift";
    }
    EXPECT_LE(mean16, mean8);
    EXPECT_GT(mean_lut, mean8);
    EXPECT_LT(exact_lut, exact8);
}

TEST(Fatmap, MeshesOnWholePixelsAreWatertight) {
    // x truncated on both edges, computed the same way from the same vertices on either side
    for (uint32_t seed = 1; seed <= 10; ++seed) {
        std::vector<Vertex> outline;
        auto tris = integer_mesh(seed, &outline);
        for (auto& t : tris)
            for (Vertex& v : t) v.u *= 4, v.v *= 4;  // a 256 texture
        for (Vertex& v : outline) v.u *= 4, v.v *= 4;
        std::vector<int> mesh = draw_counts(mapper("fatmap-256"), tris, 256);
        int overlaps = 0, drawn = 0;
        for (int c : mesh) overlaps += c > 1, drawn += c > 0;
        EXPECT_EQ(overlaps, 0) << "seed " << seed;
        EXPECT_GT(drawn, 50000);
    }
}

}  // namespace

namespace {

using namespace rastertest;

TEST(Quake, SegmentsAreExactWhereDepthIsConstantAlongRows) {
    // a floor: along each row depth is constant, so affine steps between exact points are exact
    LoadedScene s = load_scene_file("scenes/screen/floor-tiles.scene");
    for (const char* name : {"quake-subdiv16", "quake-subdiv8", "quake-d_draw16"}) {
        AccuracyMetrics m = accuracy(s, name);
        EXPECT_EQ(m.gaps + m.overdraw + m.overlaps, 0u) << name << ": our walker's coverage";
        EXPECT_LE(m.max_texel_error, 1u) << name;
        EXPECT_GT(double(m.exact) / m.compared, 0.999) << name;
    }
}

TEST(Quake, EightPixelSegmentsBeatSixteenWhereDepthChangesAlongRows) {
    // a wall: depth changes along each row; the affine error inside a segment grows with its length
    LoadedScene s = load_scene_file("scenes/screen/wall-tiles.scene");
    AccuracyMetrics m16 = accuracy(s, "quake-subdiv16"), m8 = accuracy(s, "quake-subdiv8"), a = accuracy(s, "affine");
    EXPECT_LT(m8.mean_texel_error, m16.mean_texel_error);
    EXPECT_LT(m16.mean_texel_error, a.mean_texel_error);
    EXPECT_LE(m16.max_texel_error, 8u);
}

}  // namespace
