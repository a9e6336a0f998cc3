// Under test: kernel/mappers/subdiv.h, fast.h, fastsubdiv.h.
// Our mappers' own properties beside the textbook ones: persp-subdiv's segments, fast-affine as
// accurate as affine, the fast mappers on every power-of-two texture (the tiled block, the doubled
// copy above 256 a side, by masks), fast-table's texels within half a texel of fast-affine's line.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "kernel/core/policy.h"
#include "kernel/mappers/fast.h"
#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

TEST(PerspSubdiv, ErrorShrinksWithTheSegmentAndVanishesWhereDepthIsConstantAlongTheSpan) {
    LoadedScene wall = load_scene_file("scenes/screen/wall-tiles.scene"), floor = load_scene_file("scenes/screen/floor-tiles.scene");
    auto ref_wall = render_reference(wall), ref_floor = render_reference(floor);
    double last = -1;
    for (const char* name : {"persp-subdiv-4", "persp-subdiv-8", "persp-subdiv-16", "persp-subdiv-32"}) {
        // rows across the wall change depth: the error grows with the segment
        AccuracyMetrics rows = compare_to_reference(ref_wall->view, measure_mapper(wall, mapper(name), Axis::Rows)->view, 64, 64, Wrap::Repeat);
        EXPECT_GE(rows.mean_texel_error, last) << name;
        last = rows.mean_texel_error;
        EXPECT_EQ(rows.gaps + rows.overdraw + rows.overlaps, 0u) << name;
        // columns down the wall, rows across the floor: constant depth, exact
        AccuracyMetrics columns = compare_to_reference(ref_wall->view, measure_mapper(wall, mapper(name), Axis::Columns)->view, 64, 64, Wrap::Repeat);
        AccuracyMetrics floor_rows = compare_to_reference(ref_floor->view, measure_mapper(floor, mapper(name), Axis::Rows)->view, 64, 64, Wrap::Repeat);
        EXPECT_LE(columns.max_texel_error, 1u) << name;
        EXPECT_LE(floor_rows.max_texel_error, 1u) << name;
    }
    EXPECT_GT(last, 0.5) << "32-pixel segments across a receding wall are visibly off";
}

TEST(FastAffine, AsAccurateAsTheTextbookAffineMapper) {
    // the fixed-point planes and the unrolled loop choose the same texels as affine's per-span
    // doubles, but for the odd pixel where 16.16 rounding meets a texel boundary
    LoadedScene s = load_scene_file("scenes/screen/big-quad-256.scene");
    AccuracyMetrics fast_rows = accuracy(s, "fast-affine"), affine = accuracy(s, "affine");
    auto ref = render_reference(s);
    AccuracyMetrics fast_columns =
        compare_to_reference(ref->view, measure_mapper(s, mapper("fast-columns"), Axis::Columns)->view, 256, 256, Wrap::Repeat);
    for (const AccuracyMetrics& m : {fast_rows, fast_columns}) {
        EXPECT_EQ(m.gaps + m.overdraw + m.overlaps, 0u);
        EXPECT_LE(m.max_texel_error, 1u);
        EXPECT_NEAR(m.mean_texel_error, affine.mean_texel_error, 0.005);
    }
    AccuracyMetrics fatmap16 = accuracy(s, "fatmap-256-16");
    EXPECT_LT(fast_rows.mean_texel_error, fatmap16.mean_texel_error) << "subpixel-correct starts beat fatmap's truncated edges";
}

// fast-affine, fast-columns and the fast-table pair take any repeating texture with power-of-two
// sides up to 256 by reading its tiling of the 64 KiB block (fast-table also its guard rows after it): on random triangles over many periods, each draws with a
// w x h texture exactly the pixels it draws with the 256 x 256 texture that tiles it (built here,
// independently), with both loops, and no texel further than one from affine's.
TEST(FastAffine, TakesEveryPowerOfTwoTextureAsItsTiling) {
    const int32_t sides[][2] = {{1, 1}, {2, 256}, {32, 32}, {64, 128}, {256, 16}, {128, 64}, {256, 256}};
    TriangleGen gen(20261124u);
    gen.uv_range = 2000;
    for (const auto& side : sides) {
        const int32_t w = side[0], h = side[1];
        std::vector<uint8_t> texels(size_t(w) * size_t(h)), tiling(65536);
        for (size_t i = 0; i < texels.size(); ++i) texels[i] = uint8_t(gen.rng() % 250 + 1);
        for (int32_t i = 0; i < 65536; ++i) tiling[size_t(i)] = texels[size_t(((i >> 8) % h) * w + (i & 255) % w)];
        Texture tex{texels.data(), w, h, Wrap::Repeat}, whole{tiling.data(), 256, 256, Wrap::Repeat};
        TextureCopies copies(&tex), whole_copies(&whole);
        for (const char* name : {"fast-affine", "fast-columns", "fast-table", "fast-table-columns"}) {
            const Mapper& m = mapper(name);
            ASSERT_TRUE(mapper_accepts(m, tex)) << name << " " << w << "x" << h;
            const Axis axis = home_axis(m);
            for (Variant variant : {Variant::Twin, Variant::Asm}) {
                int drawn = 0;
                for (int n = 0; n < 60; ++n) {
                    const std::vector<Vertex> t = gen.triangle();
                    std::vector<uint8_t> a(SCREEN_PIXELS, 0), b(SCREEN_PIXELS, 0);
                    Target ta = ram_target(a.data(), ram_planar(m, axis)), tb = ram_target(b.data(), ram_planar(m, axis));
                    RenderStats sa, sb;
                    draw_polygon(t.data(), 3, tex, m, axis, ta, &sa, variant);
                    draw_polygon(t.data(), 3, whole, m, axis, tb, &sb, variant);
                    ASSERT_EQ(sa.pixels, sb.pixels);
                    ASSERT_TRUE(a == b) << name << " " << w << "x" << h << " triangle " << n;
                    drawn += sa.pixels > 0;
                }
                EXPECT_GT(drawn, 20) << name << ": triangles on the screen";
            }
        }
    }
    // and against affine on the w x h texture itself
    auto s = empty_scene(TextureKind::Xor, 64, 128, Wrap::Repeat);
    for (int n = 0; n < 30; ++n) add_polygon(*s, gen.triangle());
    LoadedScene loaded = make_loaded_scene(std::move(s), "tiled");
    AccuracyMetrics fast = accuracy(loaded, "fast-affine"), affine = accuracy(loaded, "affine");
    EXPECT_LE(fast.max_texel_error, affine.max_texel_error + 1);
    EXPECT_EQ(fast.gaps + fast.overdraw + fast.overlaps, 0u);
}

// fast-table draws the pixels fast-affine draws, each texel within one on each axis of fast-affine's,
// and both ways somewhere; and each texel's centre within one texel of fast-affine's 16.16 line at
// the pixel (the line moved by at most half a texel, then floored: docs/bounds.md, "The offset
// table"; a table without the half on v, or on the tiled block whose u carries into the next row,
// reads a texel whose centre is 1.5 away). fast-table-columns likewise against fast-columns (a
// planar target): on random triangles with texel coordinates over many periods, steps to several
// texels a pixel, a 16 x 8 texture whose texels name themselves (v * 16 + u), NASM loop and twin.
TEST(FastTable, EachTexelWithinHalfATexelOfFastAffinesLine) {
    std::vector<uint8_t> texels(16 * 8);
    for (int32_t i = 0; i < 16 * 8; ++i) texels[size_t(i)] = uint8_t(i);
    Texture tex{texels.data(), 16, 8, Wrap::Repeat};
    TextureCopies copies(&tex);
    for (const auto& pair : {std::pair{"fast-table", "fast-affine"}, std::pair{"fast-table-columns", "fast-columns"}}) {
        const Mapper &table = mapper(pair.first), &affine = mapper(pair.second);
        const Axis axis = home_axis(table);
        TriangleGen gen(3031u);
        gen.uv_range = 3000;
        int pixels = 0, moved[2][3] = {};  // [axis][e + 1]
        constexpr uint8_t EMPTY = 255;
        double farthest = 0;  // the largest distance from a texel's centre to the line, either axis
        for (int n = 0; n < 400; ++n) {
            const std::vector<Vertex> t = gen.triangle();
            PolygonSetup s;
            const bool set = setup_polygon(t.data(), 3, &s, PLANES_AFFINE) == SetupStatus::Ok;  // (else nothing drawn)
            // the line at pixel (x, y) in texels, modulo 2^16 (16.16 wrapping as the mappers' does)
            auto line = [](const FixedPlane& f, int32_t x, int32_t y) {
                return double(uint32_t(f.value(0, 0)) + uint32_t(x) * uint32_t(f.dx) + uint32_t(y) * uint32_t(f.dy)) / 65536.0;
            };
            // from a texel's centre to the line, the shorter way round a period
            auto apart = [](int texel, double at, int period) {
                const double d = std::fmod(texel + 0.5 - at, double(period));
                return std::fabs(d > period / 2.0 ? d - period : d < -period / 2.0 ? d + period : d);
            };
            for (Variant variant : {Variant::Twin, Variant::Asm}) {
                std::vector<uint8_t> a(SCREEN_PIXELS, EMPTY), b(SCREEN_PIXELS, EMPTY);
                Target ta = ram_target(a.data(), ram_planar(table, axis)), tb = ram_target(b.data(), ram_planar(affine, axis));
                RenderStats sa, sb;
                ASSERT_EQ(draw_polygon(t.data(), 3, tex, table, axis, ta, &sa, variant),
                          draw_polygon(t.data(), 3, tex, affine, axis, tb, &sb, variant));
                ASSERT_EQ(sa.pixels, sb.pixels);
                for (size_t i = 0; i < a.size(); ++i) {
                    ASSERT_EQ(a[i] == EMPTY, b[i] == EMPTY) << "triangle " << n << " pixel " << i;
                    if (a[i] == EMPTY) continue;
                    ++pixels;
                    const int du = ((a[i] & 15) - (b[i] & 15) + 16 + 1) % 16 - 1, dv = ((a[i] >> 4) - (b[i] >> 4) + 8 + 1) % 8 - 1;
                    ASSERT_TRUE(du >= -1 && du <= 1 && dv >= -1 && dv <= 1)
                        << pair.first << " triangle " << n << " pixel " << i << ": " << int(a[i]) << " against " << int(b[i]);
                    ++moved[0][du + 1], ++moved[1][dv + 1];
                    ASSERT_TRUE(set) << "triangle " << n;
                    const bool planar = ram_planar(table, axis);
                    const int32_t at = int32_t(i) % PLANE_BYTES;
                    const int32_t x = planar ? (at % PLANE_ROW_BYTES) * 4 + int32_t(i) / PLANE_BYTES : int32_t(i) % SCREEN_WIDTH;
                    const int32_t y = planar ? at / PLANE_ROW_BYTES : int32_t(i) / SCREEN_WIDTH;
                    const double off_u = apart(a[i] & 15, line(s.u_fx, x, y), 16), off_v = apart(a[i] >> 4, line(s.v_fx, x, y), 8);
                    ASSERT_LE(off_u, 1.0) << pair.first << " triangle " << n << " pixel (" << x << ", " << y << ")";
                    ASSERT_LE(off_v, 1.0) << pair.first << " triangle " << n << " pixel (" << x << ", " << y << ")";
                    farthest = std::max({farthest, off_u, off_v});
                }
            }
        }
        EXPECT_GT(pixels, 100000) << pair.first;
        EXPECT_GT(farthest, 0.99) << pair.first << ": the half texel's room used";
        for (int t = 0; t < 2; ++t)
            for (int e = 0; e < 3; ++e) EXPECT_GT(moved[t][e], 0) << pair.first << ": " << (t ? "v" : "u") << " never moved by " << e - 1;
    }
}

// A repeating texture of random texels (none 255, the tests' empty pixel) with a side above 256,
// prepared with its doubled copy (tex) and without (alone).
struct RandomBigTexture {
    std::vector<uint8_t> texels, bordered, aligned, doubled;
    Texture tex, alone;
    RandomBigTexture(int32_t w, int32_t h, std::mt19937& rng)
        : texels(size_t(w) * size_t(h)), bordered(size_t(bordered_bytes(w, h))), aligned(ALIGNED256_BYTES), doubled(size_t(doubled_bytes(w, h))) {
        for (uint8_t& t : texels) t = uint8_t(rng() % 255);
        tex = alone = Texture{texels.data(), w, h, Wrap::Repeat};
        prepare_texture(&alone, bordered.data(), aligned.data());
        prepare_texture(&tex, bordered.data(), aligned.data(), doubled.data());
    }
};

// fast-table and fast-table-columns take textures with a side above 256 (powers of two up to
// 1024) through their doubled copy: every pixel fast-affine's arithmetic would draw, its texel
// within one on each axis of fast-affine's (the 16.16 planes' floors at the pixel, modulo the sides:
// one of the nine around it), on random triangles over many periods, a texture of random texels
// (a wrong row, stride or mask reads some other texel), NASM loop and twin; and with the doubled
// copy left out (prepare_texture's null) they refuse such a texture.
TEST(FastTable, TakesTexturesAbove256ByTheDoubledCopy) {
    const int32_t sides[][2] = {{512, 512}, {1024, 64}, {64, 1024}, {1024, 1024}, {512, 2}, {256, 512}};
    TriangleGen gen(20261127u);
    gen.uv_range = 3000;
    for (const auto& side : sides) {
        const int32_t w = side[0], h = side[1];
        const RandomBigTexture big(w, h, gen.rng);
        const std::vector<uint8_t>& texels = big.texels;
        const Texture &tex = big.tex, &alone = big.alone;
        for (const char* name : {"fast-table", "fast-table-columns"}) {
            const Mapper& m = mapper(name);
            EXPECT_FALSE(mapper_accepts(m, alone)) << name << ": no doubled copy";
            ASSERT_TRUE(mapper_accepts(m, tex)) << name << " " << w << "x" << h;
            const Axis axis = home_axis(m);
            for (Variant variant : {Variant::Twin, Variant::Asm}) {
                int pixels = 0;
                for (int n = 0; n < 120; ++n) {
                    const std::vector<Vertex> t = gen.triangle();
                    std::vector<uint8_t> a(SCREEN_PIXELS, 255), planar(SCREEN_PIXELS);
                    const bool is_planar = ram_planar(m, axis);
                    Target target = ram_target(a.data(), is_planar);
                    RenderStats stats;
                    if (draw_polygon(t.data(), 3, tex, m, axis, target, &stats, variant) != SetupStatus::Ok) continue;
                    PolygonSetup s;
                    ASSERT_EQ(setup_polygon(t.data(), 3, &s, PLANES_AFFINE), SetupStatus::Ok);
                    if (is_planar) linear_from_planar(a.data(), planar.data()), a.swap(planar);
                    for (int32_t y = 0; y < SCREEN_HEIGHT; ++y)
                        for (int32_t x = 0; x < SCREEN_WIDTH; ++x) {
                            const uint8_t got = a[size_t(y) * SCREEN_WIDTH + size_t(x)];
                            ASSERT_EQ(got != 255, covers(s, x, y)) << name << " triangle " << n << " at " << x << "," << y;
                            if (got == 255) continue;
                            ++pixels;
                            const int32_t fu = int32_t(uint32_t(s.u_fx.value(x, y)) >> 16), fv = int32_t(uint32_t(s.v_fx.value(x, y)) >> 16);
                            bool near = false;
                            for (int32_t ev = -1; ev <= 1; ++ev)
                                for (int32_t eu = -1; eu <= 1; ++eu)
                                    near = near || texels[size_t((fv + ev) & (h - 1)) * size_t(w) + size_t((fu + eu) & (w - 1))] == got;
                            ASSERT_TRUE(near) << name << " " << w << "x" << h << " triangle " << n << " at " << x << "," << y;
                        }
                }
                EXPECT_GT(pixels, 20000) << name << " " << w << "x" << h;
            }
        }
    }
}

// fast-affine and fast-columns take textures with a side above 256 (powers of two up to 1024): on
// every polygon each draws exactly the texel of its 16.16 planes' floors at each pixel, modulo the
// sides (a texture of random texels: a wrong row, column, step or carry reads some other texel),
// NASM loop and twin, through the doubled copy's window where the polygon's coordinates fit one
// (doubled_window), from the texture by masks where they do not; a face that maps the texture once
// ([0, W] x [0, H], a cube's, shifted by whole periods) always fits. Without the copy each refuses
// the texture.
TEST(FastAffine, TakesTexturesAbove256ByTheDoubledCopy) {
    const int32_t sides[][2] = {{512, 512}, {1024, 64}, {64, 1024}, {1024, 1024}, {512, 2}, {256, 512}};
    TriangleGen gen(20261128u);
    for (int k = 0; k < 2 * int(sizeof sides / sizeof sides[0]); ++k) {
        const auto& side = sides[k / 2];
        const char* name = k % 2 ? "fast-columns" : "fast-affine";
        const Mapper& m = mapper(name);
        const Axis axis = home_axis(m);
        const bool is_planar = ram_planar(m, axis);
        const int32_t w = side[0], h = side[1];
        // spans up to 2.4 times the smaller side and 32: in a window up to the side and 16 more, never
        // from twice the side and 16 more, between as the window falls
        gen.uv_range = 1.2 * (w < h ? w : h) + 16;
        const RandomBigTexture big(w, h, gen.rng);
        const std::vector<uint8_t>& texels = big.texels;
        const Texture &tex = big.tex, &alone = big.alone;
        EXPECT_FALSE(mapper_accepts(m, alone)) << name << ": no doubled copy";
        ASSERT_TRUE(mapper_accepts(m, tex)) << name << " " << name << " " << w << "x" << h;
        auto face = [&](double shift_u, double shift_v) {  // the texture once, shifted by whole periods
            return std::vector<Vertex>{vertex(20.5, 12.25, 1, shift_u, shift_v), vertex(300.75, 20, 1, shift_u + w, shift_v),
                                       vertex(290, 228.5, 1, shift_u + w, shift_v + h)};
        };
        for (Variant variant : {Variant::Twin, Variant::Asm}) {
            int pixels = 0, windowed = 0, wrapped = 0;
            for (int n = 0; n < 160; ++n) {
                const std::vector<Vertex> t = n < 2 ? face(n * 3.0 * w, -n * 5.0 * h) : gen.triangle();
                std::vector<uint8_t> a(SCREEN_PIXELS, 255), planar(SCREEN_PIXELS);
                Target target = ram_target(a.data(), is_planar);
                RenderStats stats;
                PolygonSetup s;
                if (setup_polygon(t.data(), 3, &s, PLANES_AFFINE) != SetupStatus::Ok) continue;
                ASSERT_EQ(draw_polygon(t.data(), 3, tex, m, axis, target, &stats, variant), SetupStatus::Ok);
                if (is_planar) linear_from_planar(a.data(), planar.data()), a.swap(planar);
                uint32_t u_base, v_base;
                const bool window = fast::doubled_window(s, tex, target.clip, &u_base, &v_base);
                ASSERT_TRUE(window || n >= 2) << name << " " << w << "x" << h << ": the face outside a window";
                ++(window ? windowed : wrapped);
                for (int32_t y = 0; y < SCREEN_HEIGHT; ++y)
                    for (int32_t x = 0; x < SCREEN_WIDTH; ++x) {
                        const uint8_t got = a[size_t(y) * SCREEN_WIDTH + size_t(x)];
                        ASSERT_EQ(got != 255, covers(s, x, y)) << name << " " << w << "x" << h << " triangle " << n << " at " << x << "," << y;
                        if (got == 255) continue;
                        ++pixels;
                        const int32_t fu = int32_t(uint32_t(s.u_fx.value(x, y)) >> 16), fv = int32_t(uint32_t(s.v_fx.value(x, y)) >> 16);
                        ASSERT_EQ(got, texels[size_t(fv & (h - 1)) * size_t(w) + size_t(fu & (w - 1))])
                            << name << " " << w << "x" << h << " triangle " << n << " at " << x << "," << y;
                    }
            }
            EXPECT_GT(pixels, 20000) << name << " " << w << "x" << h;
            EXPECT_GT(windowed, 20) << name << " " << w << "x" << h;
            EXPECT_GT(wrapped, 5) << name << " " << w << "x" << h;
        }
    }
}

// The subdivided fast mappers take repeating textures with a side above 256 (powers of two up to
// 1024) through their doubled copy: on a texture that repeats a tile of at most 256 a side, each
// draws, rows and columns, NASM loop and twin, exactly what it draws with the tile on the tiled
// block (texel (u mod W, v mod H) of the big texture is the tile's (u mod w, v mod h)), on random
// triangles in perspective over many periods, some segments beyond the copy (read by masks), most
// not (the texel pointer); a wrong origin, pitch, start or step reads another texel of the random
// tile. Without the copy each refuses the texture, and a clamped one. (Texels beyond the tile's
// period: the loop's random cases on hashed texels, and the bound tests on 1024 x 1024 textures.)
TEST(FastSubdiv, TakesTexturesAbove256ByTheDoubledCopy) {
    const int32_t shapes[][4] = {{512, 512, 256, 256}, {1024, 64, 256, 64}, {64, 1024, 64, 128}, {1024, 1024, 32, 256}};
    const char* names[] = {"fast-subdiv-8", "fast-subdiv-16", "fast-subdiv-32", "fast-constant-depth", "fast-adaptive-1", "fast-adaptive-2", "fast-oriented-1"};
    TriangleGen gen(20261129u);
    gen.uv_range = 3000;
    gen.depth_ratio = 30;
    for (const auto& shape : shapes) {
        const int32_t w = shape[0], h = shape[1], tw = shape[2], th = shape[3];
        std::vector<uint8_t> tile(size_t(tw) * size_t(th)), big(size_t(w) * size_t(h));
        for (uint8_t& t : tile) t = uint8_t(gen.rng() % 255);
        for (int32_t v = 0; v < h; ++v)
            for (int32_t u = 0; u < w; ++u) big[size_t(v) * size_t(w) + size_t(u)] = tile[size_t(v % th) * size_t(tw) + size_t(u % tw)];
        std::vector<uint8_t> bordered(size_t(bordered_bytes(w, h))), aligned(ALIGNED256_BYTES), doubled(size_t(doubled_bytes(w, h)));
        Texture tex{big.data(), w, h, Wrap::Repeat}, alone = tex, clamped{big.data(), w, h, Wrap::Clamp}, small{tile.data(), tw, th, Wrap::Repeat};
        prepare_texture(&tex, bordered.data(), aligned.data(), doubled.data());
        prepare_texture(&alone, bordered.data(), aligned.data());
        prepare_texture(&clamped, bordered.data(), aligned.data(), doubled.data());
        TextureCopies small_copies(&small);
        for (const char* name : names) {
            const Mapper& m = mapper(name);
            EXPECT_FALSE(mapper_accepts(m, alone)) << name << ": no doubled copy";
            EXPECT_FALSE(mapper_accepts(m, clamped)) << name << ": clamped";
            ASSERT_TRUE(mapper_accepts(m, tex)) << name << " " << w << "x" << h;
            int pixels = 0;
            for (int n = 0; n < 24; ++n) {
                const std::vector<Vertex> t = gen.triangle();
                for (Axis axis : {Axis::Rows, Axis::Columns})
                    for (Variant variant : {Variant::Twin, Variant::Asm}) {
                        std::vector<uint8_t> a(SCREEN_PIXELS, 255), b(SCREEN_PIXELS, 255);
                        Target ta = ram_target(a.data(), ram_planar(m, axis)), tb = ram_target(b.data(), ram_planar(m, axis));
                        RenderStats sa, sb;
                        const SetupStatus status = draw_polygon(t.data(), 3, tex, m, axis, ta, &sa, variant);
                        ASSERT_EQ(status, draw_polygon(t.data(), 3, small, m, axis, tb, &sb, variant));
                        ASSERT_EQ(sa.pixels, sb.pixels);
                        for (size_t i = 0; i < a.size(); ++i)
                            ASSERT_EQ(a[i], b[i]) << name << " " << w << "x" << h << " triangle " << n << " pixel " << i << (variant == Variant::Asm ? " NASM" : " twin")
                                                  << (axis == Axis::Rows ? " rows" : " columns");
                        pixels += int(sa.pixels);
                    }
            }
            EXPECT_GT(pixels, 20000) << name << " " << w << "x" << h;
        }
    }
}

// The four affine fast mappers take a clamped texture (power-of-two sides up to 256) polygon by
// polygon: where the polygon's coordinates lie inside it, with their rounding (and fast-table's
// texel more), each draws exactly what it draws with the same texture repeating; where they reach
// an edge it refuses the polygon, and its bound says it does not draw it.
TEST(FastAffine, TakesAClampedTextureWhereThePolygonLiesInsideIt) {
    std::vector<uint8_t> texels(64 * 32);
    for (size_t i = 0; i < texels.size(); ++i) texels[i] = uint8_t(i * 7 + 1);
    Texture clamped{texels.data(), 64, 32, Wrap::Clamp};
    TextureCopies copies(&clamped);
    Texture repeating = clamped;
    repeating.wrap = Wrap::Repeat;
    auto quad = [](double u0, double v0, double u1, double v1) {
        return std::vector<Vertex>{vertex(30, 20, 1, u0, v0), vertex(290, 30, 1.5, u1, v0), vertex(280, 220, 1.2, u1, v1), vertex(40, 210, 1, u0, v1)};
    };
    const std::vector<Vertex> inside = quad(1.5, 1.5, 62.25, 30.25), edge = quad(0.25, 0.25, 63.75, 31.75), outside = quad(-8, 2, 40, 20);
    for (const char* name : {"fast-affine", "fast-table", "fast-columns", "fast-table-columns"}) {
        const Mapper& m = mapper(name);
        const bool table = std::string(name).find("table") != std::string::npos;
        const Axis axis = home_axis(m);
        ASSERT_TRUE(mapper_accepts(m, clamped)) << name;
        for (const auto* p : {&inside, &edge, &outside}) {
            std::vector<uint8_t> a(SCREEN_PIXELS, 0), b(SCREEN_PIXELS, 0);
            Target ta = ram_target(a.data(), ram_planar(m, axis)), tb = ram_target(b.data(), ram_planar(m, axis));
            RenderStats sa, sb;
            const SetupStatus status = draw_polygon(p->data(), 4, clamped, m, axis, ta, &sa, Variant::Asm);
            draw_polygon(p->data(), 4, repeating, m, axis, tb, &sb, Variant::Asm);
            const bool draws = p == &inside || (p == &edge && !table);
            const ErrorBound bound = m.bound(BoundContext{m, clamped, axis, ta.clip}, p->data(), 4);
            EXPECT_EQ(bound.draws, draws) << name;
            if (draws) {
                EXPECT_EQ(status, SetupStatus::Ok) << name;
                EXPECT_GT(sa.pixels, 40000u) << name;
                EXPECT_TRUE(a == b) << name << ": the clamped texture read as the repeating one";
            } else {
                EXPECT_EQ(status, SetupStatus::Unsupported) << name;
                EXPECT_EQ(sa.pixels, 0u) << name;
                EXPECT_EQ(sa.rejected, 1u) << name;
            }
        }
    }
}

}  // namespace
