// Under test: kernel/core/fuzz.h and every mapper of the registry.
// Stability at the extremes: huge and tiny polygons, slivers, coordinates and w at their limits,
// every mapper, both walkers, linear and planar targets: nothing is written outside the clip
// rectangle (guard bytes), the texture is never read outside (AddressSanitizer build), coverage
// stays the definition's.
#include <gtest/gtest.h>

#include "kernel/core/fuzz.h"
#include "kernel/core/policy.h"
#include "kernel/mappers/classic.h"
#include "kernel/mappers/hecker.h"
#include "qemu/accuracy/guarded_surface.h"
#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

double classic_limit() { return classic::MAX_COORD; }

constexpr uint8_t GUARD = FUZZ_FILL;

// Polygons at the limits. With `inside` set (mappers that cannot wrap), texture coordinates stay
// within a texture of that size, so those mappers draw them rather than refuse them.
std::vector<std::vector<Vertex>> extreme_polygons(uint32_t seed, int32_t inside = 0) {
    std::mt19937 rng(seed);
    auto pick = [&](std::initializer_list<double> values) { return *(values.begin() + rng() % values.size()); };
    auto any = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    const double L = inside ? classic_limit() : MAX_COORD_PIXELS;
    std::vector<std::vector<Vertex>> out;
    // 150 a call (under the sanitizers a quarter): every mapper, walker, wrap and texture size
    // below; the random classes of kernel/core/fuzz.h go further in PolygonFuzz
    for (int k = 0; k < 150 / SANITIZED_SHARE; ++k) {
        std::vector<Vertex> p;
        int n = k % 5 == 0 ? 3 + int(rng() % 6) : 3;
        for (int i = 0; i < n; ++i) {
            double x = pick({any(-L, L), any(-2, 322), pick({-L, L, 0.0, 319.999, 160.5}), any(150, 151)});
            double y = pick({any(-L, L), any(-2, 242), pick({-L, L, 0.0, 239.999, 120.5}), any(100, 100.01)});
            double w = pick({MIN_W, MAX_W, 1.0, any(MIN_W, 1), any(1, MAX_W)});
            double u = inside ? pick({0.0, double(inside), any(0, inside)}) : pick({MAX_UV, -MAX_UV, any(-MAX_UV, MAX_UV), any(-2, 2), 32767.9, -32768.1});
            double v = inside ? pick({0.0, double(inside), any(0, inside)}) : pick({MAX_UV, -MAX_UV, any(-MAX_UV, MAX_UV), any(-2, 2), 65535.5});
            p.push_back(vertex(x, y, w, u, v));
        }
        out.push_back(p);
    }
    // the whole screen, under a triangle a hundred screens wide
    double t = inside ? double(inside) : MAX_UV;
    out.push_back({vertex(-L, -L, MIN_W, inside ? 0 : -t, inside ? 0 : -t), vertex(L, -L, MAX_W, t, 0), vertex(0, L, 1, 0, t)});
    return out;
}

TEST(Stability, NothingIsWrittenOutsideTheClipAndCoverageHolds) {
    // every size's texture, repeating and clamped, prepared once for every mapper: its texels and
    // copies in buffers of exactly their size, so that ASan sees any stray read
    struct Prepared {
        std::vector<uint8_t> texels, bordered, aligned, doubled;
        Texture tex;
    };
    std::vector<std::unique_ptr<Prepared>> textures;
    for (Wrap wrap : {Wrap::Repeat, Wrap::Clamp})
        for (int32_t size : {1, 3, 64, 256, 1024}) {
            auto t = std::make_unique<Prepared>();
            t->texels.resize(size_t(size) * size_t(size));
            t->bordered.resize(size_t(bordered_bytes(size, size)));
            t->aligned.resize(ALIGNED256_BYTES);
            t->doubled.resize(gets_doubled(size, size) ? size_t(doubled_bytes(size, size)) : 0);
            generate_texture(TextureKind::Xor, size, size, t->texels.data());
            t->tex = Texture{t->texels.data(), size, size, wrap};
            prepare_texture(&t->tex, t->bordered.data(), t->aligned.data(), t->doubled.data());
            textures.push_back(std::move(t));
        }
    for (int m = 0; m < MAPPER_COUNT; ++m) {
        const Mapper& mapper = MAPPERS[m];
        // the classics take vertices within +-8192 pixels and texture coordinates that fit (or
        // wrap inside 16.16): give them polygons at those limits
        bool inside_only = std::string(mapper.family) == "classic";
        for (Axis axis : {Axis::Rows, Axis::Columns}) {
            if (!mapper_walks(mapper, axis)) continue;
            for (const auto& t : textures) {
                const Texture& tex = t->tex;
                if (!mapper_accepts(mapper, tex)) continue;
                harness::GuardedSurface surface(ram_planar(mapper, axis));
                RenderStats stats;
                for (const auto& p : extreme_polygons(uint32_t(tex.width), inside_only ? tex.width : 0))
                    draw_polygon(p.data(), int(p.size()), tex, mapper, axis, surface.target(), &stats);
                EXPECT_EQ(surface.scan(GUARD).written_outside, 0u) << mapper.name << " texture " << tex.width;
                // (a mapper that takes a clamped texture only where the polygon lies inside it
                // refuses these, whose coordinates reach its edges and beyond)
                if (tex.wrap == Wrap::Clamp && (mapper.needs & (NEED_TILED256_OR_INSIDE | NEED_POW2_OR_INSIDE))) continue;
                EXPECT_GT(stats.polygons, uint32_t(40 / SANITIZED_SHARE)) << mapper.name;
                EXPECT_GT(stats.pixels, uint32_t(SCREEN_PIXELS)) << mapper.name << ": the screen-sized triangle at least";
            }
        }
    }
}

// The plane selection on planar targets: once per column for column walkers (the map mask set
// outside the inner loop), once per pixel for row loops on Mode X (X-Sharp's OUT per pixel);
// generic row walkers refuse planar targets (auto, asked for rows, draws by columns there).
TEST(Stability, PlaneSelectionOnPlanarTargets) {
    std::vector<uint8_t> texels(256 * 256);
    generate_texture(TextureKind::Grid, 256, 256, texels.data());
    Texture tex{texels.data(), 256, 256, Wrap::Repeat};  // 256 x 256: every mapper takes it
    TextureCopies copies(&tex);
    for (int m = 0; m < MAPPER_COUNT; ++m) {
        const Mapper& mapper = MAPPERS[m];
        std::vector<uint8_t> planes(4 * size_t(PLANE_BYTES) + 2 * 64, GUARD);
        Target t = planar_target(planes.data() + 64);
        int selects = 0;
        t.ctx = &selects;
        t.select_plane = [](void* c, int) { ++*static_cast<int*>(c); };
        auto polygons = extreme_polygons(5, std::string(mapper.family) == "classic" ? 64 : 0);
        for (Axis axis : {Axis::Rows, Axis::Columns}) {
            if (!mapper_walks(mapper, axis)) continue;
            selects = 0;
            RenderStats stats;
            for (const auto& p : polygons) draw_polygon(p.data(), int(p.size()), tex, mapper, axis, t, &stats);
            if (axis == Axis::Columns || mapper.is_auto) {
                EXPECT_EQ(uint32_t(selects), stats.spans) << mapper.name << ": one plane selection per column";
                EXPECT_GT(stats.pixels, 0u) << mapper.name;
            } else if (mapper.needs & NEED_PLANAR_TARGET) {
                EXPECT_EQ(uint32_t(selects), stats.pixels) << mapper.name << ": one OUT per pixel";
                EXPECT_GT(stats.pixels, 0u) << mapper.name;
            } else {
                EXPECT_EQ(stats.pixels, 0u) << mapper.name << ": rows on a planar target are refused";
                EXPECT_EQ(stats.rejected, uint32_t(polygons.size()));
            }
        }
        for (int i = 0; i < 64; ++i) {
            EXPECT_EQ(planes[size_t(i)], GUARD) << mapper.name;
            EXPECT_EQ(planes[planes.size() - 1 - size_t(i)], GUARD) << mapper.name;
        }
    }
}

// Our mappers promise exact coverage: each draws exactly the pixels covers() accepts inside the
// clip, whichever way it walks (fast-affine's run loop walks the rows itself, with rows where a
// vertex lies on the centre drawn apart: a third of the triangles here have their vertices on the
// half-pixel grid).
TEST(Stability, OurMappersDrawExactlyTheCoveredPixels) {
    std::vector<uint8_t> texels(256 * 256, 7);
    Texture tex{texels.data(), 256, 256, Wrap::Repeat};  // every texel 7: drawn pixels show
    TextureCopies copies(&tex);
    for (int m = 0; m < MAPPER_COUNT; ++m) {
        const Mapper& mapper = MAPPERS[m];
        if (std::string(mapper.family) != "ours") continue;
        for (Axis axis : {Axis::Rows, Axis::Columns}) {
            if (!mapper_walks(mapper, axis)) continue;
            TriangleGen gen(uint32_t(100 + m));
            std::vector<uint8_t> pixels(SCREEN_PIXELS), planes(4 * size_t(PLANE_BYTES));
            int checked = 0;
            // coverage arithmetic, not memory: a quarter of the trials under the sanitizers
            const int trials = 300 / SANITIZED_SHARE;
            for (int trial = 0; trial < trials; ++trial) {
                std::vector<Vertex> p = gen.triangle();
                if (trial % 4 == 0) {  // a convex polygon: points on an ellipse, some on the grid
                    p.clear();
                    int n = 3 + int(gen.rng() % 8);
                    double cx = gen.uniform(0, 320), cy = gen.uniform(0, 240), rx = gen.uniform(1, 150), ry = gen.uniform(1, 150);
                    for (int k = 0; k < n; ++k) {
                        double x = cx + rx * std::cos(k * 2 * M_PI / n), y = cy + ry * std::sin(k * 2 * M_PI / n);
                        if (trial % 8 == 0) x = std::floor(x) + 0.5, y = std::floor(y) + 0.5;
                        p.push_back(vertex(x, y));
                    }
                }
                PolygonSetup s;
                if (setup_polygon(p.data(), int(p.size()), &s) != SetupStatus::Ok) continue;
                ClipRect clip{int32_t(gen.rng() % 40), int32_t(gen.rng() % 40), 280 + int32_t(gen.rng() % 41), 200 + int32_t(gen.rng() % 41)};
                std::fill(pixels.begin(), pixels.end(), 0);
                std::fill(planes.begin(), planes.end(), 0);
                bool planar = ram_planar(mapper, axis);
                Target t = ram_target(planar ? planes.data() : pixels.data(), planar);
                t.clip = clip;
                RenderStats stats;
                ASSERT_EQ(draw_polygon(p.data(), int(p.size()), tex, mapper, axis, t, &stats), SetupStatus::Ok) << mapper.name;
                if (t.planar) linear_from_planar(planes.data(), pixels.data());
                uint32_t drawn = 0;
                for (int32_t y = 0; y < SCREEN_HEIGHT; ++y)
                    for (int32_t x = 0; x < SCREEN_WIDTH; ++x) {
                        bool want = x >= clip.x0 && x < clip.x1 && y >= clip.y0 && y < clip.y1 && covers(s, x, y);
                        ASSERT_EQ(pixels[size_t(y) * SCREEN_WIDTH + size_t(x)] != 0, want)
                            << mapper.name << (axis == Axis::Rows ? " rows" : " columns") << " trial " << trial << " pixel " << x << "," << y;
                        drawn += want;
                    }
                EXPECT_EQ(stats.pixels, drawn) << mapper.name << " trial " << trial;
                ++checked;
            }
            EXPECT_GT(checked, trials * 5 / 6) << mapper.name;
        }
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
    for (int trial = 0; trial < 20000 / SANITIZED_SHARE; ++trial) {
        int32_t x = int32_t(rng() % (320 * 256)), y = int32_t(rng() % (240 * 256));
        std::vector<Vertex> p = {vertex_raw(x, y), vertex_raw(x + 1 + int32_t(rng() % 200), y + int32_t(rng() % 50)),
                                 vertex_raw(x + int32_t(rng() % 50), y + 1 + int32_t(rng() % 200))};
        PolygonSetup s;
        if (setup_polygon(p.data(), 3, &s) != SetupStatus::Ok) continue;
        EdgeWalker w(s, Axis::Rows, ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT});
        int total = 0;
        for (Span span; w.next(&span);) total += span.count;
        ASSERT_LE(total, 1);
    }
}

}  // namespace

namespace {

// A watched drawing is asked before every 16th polygon and stops there when told to: the polygons
// before are drawn, none after.
TEST(Stability, AWatchStopsTheDrawingBetweenPolygons) {
    auto scene = rastertest::empty_scene(TextureKind::Checker, 64, 64, Wrap::Repeat);
    rastertest::TriangleGen gen(5u);
    for (int i = 0; i < 100; ++i) rastertest::add_polygon(*scene, gen.triangle());
    std::vector<uint8_t> texels(64 * 64, 7), pixels(SCREEN_PIXELS);
    Texture tex{texels.data(), 64, 64, Wrap::Repeat};
    struct Seen {
        std::vector<uint32_t> done;
        uint32_t stop_at;
    };
    raster::Watch watch;
    watch.keep_going = [](void* ctx, uint32_t done, uint32_t total) {
        auto* s = static_cast<Seen*>(ctx);
        EXPECT_EQ(total, 100u);
        s->done.push_back(done);
        return done < s->stop_at;
    };
    for (uint32_t stop_at : {48u, 1000u}) {
        Seen seen{{}, stop_at};
        watch.ctx = &seen;
        Target t = rastertest::ram_target(pixels.data(), false);
        RenderStats stats = render_scene(*scene, tex, *find_mapper("exact"), Axis::Rows, t, Variant::Twin, nullptr, &watch);
        const uint32_t handled = stats.polygons + stats.skipped + stats.rejected;
        if (stop_at == 48) {
            EXPECT_TRUE(stats.interrupted);
            EXPECT_EQ(handled, 48u);
            EXPECT_EQ(seen.done, (std::vector<uint32_t>{16, 32, 48}));
        } else {
            EXPECT_FALSE(stats.interrupted);
            EXPECT_EQ(handled, 100u);
            EXPECT_EQ(seen.done.size(), 6u);  // 16 .. 96
        }
    }
}

}  // namespace

namespace {

using namespace rastertest;

// `make fuzz`: every mapper over MODEXLAB_FUZZ_POLYGONS random polygons (make fuzz: 10^6; make test
// a fixed-seed share) from every class of extreme (kernel/core/fuzz.h, docs/fuzzing.md), built under
// AddressSanitizer and UBSan there; every texture size from 1 x 1 to 1024 x 1024, odd and
// non-square, repeat and clamp, each texel array and its copies exactly its size (ASan sees a stray
// read), and the surface too (a stray write), with a clip rectangle inside it whose border must
// keep its fill. The kernel's `fuzz` command runs the same polygons between guard pages.
// Textures of every size class, each in arrays of exactly its size.
struct FuzzTexture {
    std::vector<uint8_t> texels, bordered, aligned, doubled;
    Texture tex;
    FuzzTexture(int32_t width, int32_t height, Wrap wrap)
        : texels(size_t(width) * size_t(height)), bordered(size_t(bordered_bytes(width, height))), aligned(ALIGNED256_BYTES),
          doubled(gets_doubled(width, height) ? size_t(doubled_bytes(width, height)) : 0) {
        generate_texture(TextureKind::Xor, width, height, texels.data());
        tex = Texture{texels.data(), width, height, wrap};
        prepare_texture(&tex, bordered.data(), aligned.data(), doubled.data());
    }
};
// The fuzzer's bank: texture i as fuzz_texture_size(i) and fuzz_texture_wrap(i) say.
struct FuzzBank {
    std::vector<std::unique_ptr<FuzzTexture>> textures;
    Texture bank[FUZZ_TEXTURE_COUNT];
    FuzzBank() {
        for (int i = 0; i < FUZZ_TEXTURE_COUNT; ++i) {
            textures.push_back(std::make_unique<FuzzTexture>(fuzz_texture_size(i).width, fuzz_texture_size(i).height, fuzz_texture_wrap(i)));
            bank[i] = textures.back()->tex;
        }
    }
};

uint64_t env_count(const char* name, uint64_t fallback) {
    const char* s = std::getenv(name);
    return s && *s ? std::strtoull(s, nullptr, 10) : fallback;
}

TEST(PolygonFuzz, EveryMapperKeepsToItsTextureAndItsClip) {
    // make test: 5000 polygons a mapper, all of them under the sanitizers too (these are the memory
    // checks; ~4 s there); make fuzz: MODEXLAB_FUZZ_POLYGONS
    const uint64_t per_mapper = env_count("MODEXLAB_FUZZ_POLYGONS", 5000);
    const uint32_t seed = uint32_t(env_count("MODEXLAB_FUZZ_SEED", 2026));
    const FuzzBank textures;
    const Texture* bank = textures.bank;
    std::vector<uint8_t> surface(SCREEN_PIXELS);  // exactly the surface: ASan sees a write past it
    auto give_surface = [](void* ctx, bool) { return static_cast<std::vector<uint8_t>*>(ctx)->data(); };
    std::printf("%-20s %10s %10s %10s %12s %s\n", "mapper", "polygons", "drawn", "refused", "pixels", "refusals by reason");
    for (int m = 0; m < MAPPER_COUNT; ++m) {
        const Mapper& mapper = MAPPERS[m];
        // the seed's low bits: the mapper, so that each gets polygons of its own
        const FuzzStats f = fuzz_mapper(mapper, seed * 64 + uint32_t(m), uint32_t(per_mapper), bank, give_surface, &surface);
        std::string reasons;
        for (int s = 1; s < 7; ++s)
            if (f.by_status[s]) reasons += std::string(" ") + setup_status_name(SetupStatus(s)) + " " + std::to_string(f.by_status[s]);
        std::printf("%-20s %10u %10u %10u %12llu%s\n", mapper.name, f.tried, f.by_status[0], f.tried - f.by_status[0],
                    (unsigned long long)f.pixels, reasons.c_str());
        std::fflush(stdout);  // a line a mapper as it comes (make fuzz: minutes a mapper)
        EXPECT_EQ(f.tried, uint32_t(per_mapper)) << mapper.name;
        EXPECT_EQ(f.written_outside, 0u) << mapper.name << ": bytes outside the clip rectangle written, first in batch " << f.first_bad_batch
                                         << " (seed " << seed << ")";
        EXPECT_GT(f.by_status[0], f.tried / 2) << mapper.name << ": most polygons should be drawn, not refused";
    }
}

// Hecker's loop reads wherever a piece points; his driver must keep it inside the bordered copy.
// Here the fuzzer's polygons and textures (every class, every texture of its bank) go through his
// driver with a loop that walks each piece's texel pointer as his does and counts the reads that
// fall outside every copy of the bank (reading nothing), on the seeds of make test's fuzz run for
// registry rows 14, 22, 30 and 38 (without the guard, each reads outside a copy). The pixels the
// driver draws itself (the nearest texel) must occur, or the test would not reach the case. (The
// batches are fuzz_mapper's, written out here to call his driver with this loop; were they to drift
// apart, the last check fails.)
struct HeckerReads {
    const Texture* bank;
    uint64_t outside, pixels;
};
HeckerReads g_hecker_reads;
void counting_hecker_loop(const void* raw) {
    const auto& a = *static_cast<const HeckerArgs*>(raw);
    const uint8_t* texel = a.texel;
    uint32_t u = a.u_frac, v = a.v_frac;
    for (int32_t n = 0; n < a.count; ++n) {
        bool inside = false;
        for (int i = 0; i < FUZZ_TEXTURE_COUNT && !inside; ++i) {
            const Texture& t = g_hecker_reads.bank[i];
            inside = texel >= t.bordered && texel < t.bordered + bordered_bytes(t.width, t.height);
        }
        g_hecker_reads.outside += !inside;
        const uint32_t v_next = v + a.dv_frac, u_next = u + a.du_frac;
        texel += (v_next < v ? a.step_carry : a.step_no_carry) + int32_t(u_next < u);
        u = u_next, v = v_next;
    }
    g_hecker_reads.pixels += uint64_t(a.count > 0 ? a.count : 0);
}

TEST(PolygonFuzz, HeckersPiecesStayInsideTheBorderedCopy) {
    const Mapper& hecker = *find_mapper("hecker-steptable");
    const FuzzBank textures;
    const Texture* bank = textures.bank;
    int usable[FUZZ_TEXTURE_COUNT], usable_count = 0;
    for (int i = 0; i < FUZZ_TEXTURE_COUNT; ++i)
        if (mapper_accepts(hecker, bank[i])) usable[usable_count++] = i;
    ASSERT_GT(usable_count, 0);
    std::vector<uint8_t> surface(SCREEN_PIXELS);
    uint64_t drawn = 0, looped = 0;
    for (uint32_t m : {14u, 22u, 30u, 38u}) {  // (of the first 40 rows' seeds, those that reached it)
        g_hecker_reads = HeckerReads{bank, 0, 0};
        const uint32_t seed = 2026 * 64 + m;
        // fuzz_mapper's batches (kernel/core/fuzz.cpp), his driver called with the counting loop
        Random pick(seed);
        for (uint32_t tried = 0; tried < 5000; tried += FUZZ_BATCH) {
            const Texture& tex = bank[usable[pick.below(uint32_t(usable_count))]];
            (void)pick.below(1);  // the walker: rows, his only
            Target target = ram_target(surface.data(), false);
            target.clip = FUZZ_CLIP;
            RandomPolygons polygons(pick.next(), 8192, tex.width < tex.height ? tex.width : tex.height);
            RenderStats stats;
            for (uint32_t i = 0; i < FUZZ_BATCH && tried + i < 5000; ++i) {
                Vertex corners[MAX_FUZZ_CORNERS];
                const int n = polygons.next(corners);
                hecker::draw(DrawContext{tex, Axis::Rows, target, &stats, counting_hecker_loop}, corners, n);
            }
            drawn += stats.pixels;
        }
        EXPECT_EQ(g_hecker_reads.outside, 0u) << "seed " << seed << ": reads outside the bordered copy";
        looped += g_hecker_reads.pixels;
    }
    EXPECT_GT(drawn, looped) << "no piece needed the guard: the test does not reach what it tests";
}

}  // namespace
