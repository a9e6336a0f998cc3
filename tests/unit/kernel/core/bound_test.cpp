// Under test: kernel/core/bound.h, spread.h, footprint.h.
// Error bounds against measured errors: on random polygons (perspective from none to extreme,
// slivers, tiny and huge ones, texture sizes from 1 to 1024, repeat and clamp) and on every
// polygon of every demo scene at the bench's frames, no mapper's measured footprint error exceeds
// its bound, a mapper that promises exact coverage draws exactly the reference's pixels, and one
// that says it draws a polygon draws it; bounds asked with a budget (coarse where that is enough)
// hold as well. MODEXLAB_BOUND_POLYGONS sets the random polygons per
// mapper (make bounds: 100000; make test: fewer).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>

#include "kernel/core/bound.h"
#include "kernel/core/footprint.h"
#include "kernel/core/policy.h"
#include "kernel/core/random.h"
#include "kernel/core/spread.h"
#include "kernel/mappers/fastsubdiv.h"
#include "qemu/tools/demo_scenes.h"
#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

constexpr double SLACK = 1e-6;  // the measure divides by the footprint as stored (a float)

int polygons_per_mapper() {
    const char* env = std::getenv("MODEXLAB_BOUND_POLYGONS");
    return env ? std::max(1, std::atoi(env)) : 600 / SANITIZED_SHARE;
}

// Whether the run takes this mapper: every one, or those MODEXLAB_BOUND_MAPPERS names (make bounds
// MAPPERS=a,b: a long run for the mappers a change touched).
bool bound_mapper_taken(const Mapper& m) {
    const char* env = std::getenv("MODEXLAB_BOUND_MAPPERS");
    if (!env || !*env) return true;
    const std::string list = std::string(",") + env + ",";
    return list.find(std::string(",") + m.name + ",") != std::string::npos;
}

// A random polygon of one of the classes the bounds must hold on.
std::vector<Vertex> random_polygon(TriangleGen& gen, int cls) {
    switch (cls) {
    case 0: gen.depth_ratio = 1.0001, gen.uv_range = 300; return gen.triangle();  // next to no perspective
    case 1: gen.depth_ratio = 20, gen.uv_range = 300; return gen.triangle();
    case 2: gen.depth_ratio = 1e4, gen.uv_range = 3000; return gen.triangle();   // strong perspective
    case 3: {  // a sliver: two vertices a fraction of a pixel apart
        gen.depth_ratio = 50, gen.uv_range = 500;
        std::vector<Vertex> t = gen.triangle();
        t[1].x = Fixed24_8::from_raw(t[0].x.raw + int32_t(gen.rng() % 64));
        t[1].y = Fixed24_8::from_raw(t[0].y.raw + int32_t(gen.rng() % 64));
        return t;
    }
    case 4: {  // tiny: below a few pixels
        gen.depth_ratio = 10, gen.uv_range = 100;
        Vertex c = gen.random_vertex();
        std::vector<Vertex> t;
        for (int i = 0; i < 3; ++i) {
            Vertex v = gen.random_vertex();
            v.x = Fixed24_8::from_raw(c.x.raw + int32_t(gen.uniform(-400, 400)));
            v.y = Fixed24_8::from_raw(c.y.raw + int32_t(gen.uniform(-400, 400)));
            t.push_back(v);
        }
        return t;
    }
    default: {  // huge: vertices far outside the screen, a floor or wall receding
        gen.depth_ratio = 200, gen.uv_range = 20000;
        std::vector<Vertex> t;
        for (int i = 0; i < 3; ++i) {
            Vertex v = gen.random_vertex();
            v.x = Fixed24_8::from_raw(int32_t(gen.uniform(-3000, 3300) * 256));
            v.y = Fixed24_8::from_raw(int32_t(gen.uniform(-3000, 3300) * 256));
            t.push_back(v);
        }
        return t;
    }
    }
}

// For mappers that cannot wrap (NEED_INSIDE): most polygons' texture coordinates squeezed into one
// period at a random place (an affine change of texture coordinates: the perspective stays), the
// rest left as they are, which such a mapper refuses.
void place_inside(TriangleGen& gen, std::vector<Vertex>& p, int32_t width, int32_t height) {
    if (gen.rng() % 8 == 0) return;
    auto squeeze = [&](double Vertex::*t, int32_t size) {
        double lo = p[0].*t, hi = lo;
        for (const Vertex& v : p) lo = std::min(lo, v.*t), hi = std::max(hi, v.*t);
        double scale = hi - lo > size ? double(size) / (hi - lo) * gen.uniform(0.5, 1) : 1;
        double offset = gen.uniform(0, double(size) - (hi - lo) * scale);
        for (Vertex& v : p) v.*t = std::clamp(offset + (v.*t - lo) * scale, 0.0, double(size));
    };
    squeeze(&Vertex::u, width);
    squeeze(&Vertex::v, height);
}

// measured / bound over the polygons with a finite bound above 0: the median over all of them, over
// those with an error at all, and the worst.
struct Tightness {
    std::vector<double> ratios, erring;
    double worst = 0;
    void add(double measured, double bound) {
        if (bound <= 0 || bound >= NO_BOUND) return;
        ratios.push_back(measured / bound);
        if (measured > 0) erring.push_back(measured / bound);
        worst = std::max(worst, measured / bound);
    }
    static double median(std::vector<double>& v) {
        if (v.empty()) return 0;
        std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
        return v[v.size() / 2];
    }
    std::string text() {
        char buf[96];
        std::snprintf(buf, sizeof buf, "median %.3f, with an error %.3f, worst %.3f", median(ratios), median(erring), worst);
        return buf;
    }
};

// Measures one polygon and checks it against the mapper's bound; returns whether the bound was finite.
bool check_polygon(PolygonMeter& meter, const Mapper& m, Axis axis, const std::vector<Vertex>& p, const Texture& tex,
                   Tightness* tight, const std::string& what) {
    BoundContext c{m, tex, axis, ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT}};
    ErrorBound b = m.bound(c, p.data(), int(p.size()));
    bool drawn = false;
    uint32_t coverage_differs = 0;
    AccuracyMetrics e = meter.measure(p.data(), int(p.size()), tex, &drawn, [&](int32_t, int32_t, bool rc, bool dc, double) { coverage_differs += rc != dc; });
    if (m.bound != unbounded) {
        EXPECT_EQ(b.draws, drawn) << what;
    } else if (!b.draws) {
        EXPECT_FALSE(drawn) << what << ": said it would not draw";
    }
    if (!drawn) return false;
    if (b.exact_coverage) {
        EXPECT_EQ(coverage_differs, 0u) << what << ": promised exact coverage";
    }
    EXPECT_LE(e.max_footprint_error, b.footprint * (1 + SLACK) + SLACK)
        << what << ": measured " << e.max_footprint_error << " (texel error " << e.max_texel_error << ") over the bound " << b.footprint;
    // asked with a budget (auto's way: coarse where that is enough, stopping above it), a bound
    // within the budget is still a bound
    for (double budget : {0.5, 1.0, 2.0, 4.0, 1e6}) {  // 1e6: the whole-polygon bound wherever it is finite
        BoundContext asked = c;
        asked.budget = budget;
        ErrorBound q = m.bound(asked, p.data(), int(p.size()));
        if (q.draws && q.footprint <= budget) {
            EXPECT_LE(e.max_footprint_error, q.footprint * (1 + SLACK) + SLACK) << what << ": asked with budget " << budget;
        }
    }
    tight->add(e.max_footprint_error, b.footprint);
    return b.footprint < NO_BOUND;
}

TEST(Bounds, NoMapperExceedsItsBoundOnRandomPolygons) {
    const int per_mapper = polygons_per_mapper();
    const int32_t sizes[] = {1, 3, 37, 64, 256, 1024};
    std::vector<std::vector<uint8_t>> texels;
    for (int32_t size : sizes) {
        texels.emplace_back(size_t(size) * size_t(size));
        generate_texture(TextureKind::Xor, size, size, texels.back().data());
    }
    // each size's texture, repeating or clamped, with its copies: prepared once for every mapper
    struct Prepared {
        Texture tex;
        std::unique_ptr<TextureCopies> copies;
    };
    std::map<std::pair<size_t, Wrap>, Prepared> prepared;
    auto texture = [&](size_t t, Wrap wrap) -> const Texture& {
        Prepared& p = prepared[{t, wrap}];
        if (!p.copies) {
            p.tex = Texture{texels[t].data(), sizes[t], sizes[t], wrap};
            p.copies = std::make_unique<TextureCopies>(&p.tex);
        }
        return p.tex;
    };
    std::printf("bounds on %d random polygons per mapper (median and worst of measured / bound):\n", per_mapper);
    for (int i = 0; i < MAPPER_COUNT; ++i) {
        const Mapper& m = MAPPERS[i];
        if (!bound_mapper_taken(m)) continue;
        Axis axis = home_axis(m);
        PolygonMeter meter(m, axis);
        TriangleGen gen(20261123u + uint32_t(i));
        Tightness tight;
        int bounded = 0;
        for (int n = 0; n < per_mapper; ++n) {
            size_t t = size_t(n) % std::size(sizes);
            if ((m.needs & NEED_ALIGNED256) && sizes[t] != 256) t = 4;
            if ((m.needs & NEED_TILED256_OR_INSIDE) && !tiles256(sizes[t], sizes[t])) t = n % 3 == 0 ? 0 : n % 3 == 1 ? 3 : 4;  // 1, 64, 256
            if ((m.needs & (NEED_POW2_OR_INSIDE | NEED_POW2_REPEAT)) && !tiles256(sizes[t], sizes[t]) && !gets_doubled(sizes[t], sizes[t]))
                t = n % 2 ? 5 : 3;  // 1024, 64
            Wrap wrap = (m.needs & (NEED_ALIGNED256 | NEED_POW2_REPEAT)) || n % 3 ? Wrap::Repeat : Wrap::Clamp;
            const Texture& tex = texture(t, wrap);
            std::vector<Vertex> p = random_polygon(gen, n % 6);
            if (m.needs & NEED_INSIDE) place_inside(gen, p, sizes[t], sizes[t]);
            bounded += check_polygon(meter, m, axis, p, tex, &tight, std::string(m.name) + " polygon " + std::to_string(n));
            if (HasFailure()) return;
        }
        std::printf("  %-16s %6d bounded  %s\n", m.name, bounded, tight.text().c_str());
        if (m.bound != unbounded) {
            EXPECT_GT(bounded, per_mapper / 3) << m.name << ": most polygons get a finite bound";
        }
    }
}

// Found in review: Quake's driver put the whole-period shift into 16.16 with a plain conversion,
// which overflows past 32768 texels (u near -32000 in a 999-texel texture: 0x80000000, every texel
// 199 off), while its bound said one texel.
TEST(Bounds, QuakeTakesWholePeriodShiftsBeyondSixteenBits) {
    std::vector<uint8_t> texels(999 * 64);
    generate_texture(TextureKind::Xor, 999, 64, texels.data());
    Texture tex{texels.data(), 999, 64, Wrap::Repeat};
    TextureCopies copies(&tex);
    const std::vector<Vertex> p = {vertex_raw(20 * 256, 20 * 256, 1, -32000, 0), vertex_raw(300 * 256, 20 * 256, 1, -31970, 0),
                                   vertex_raw(20 * 256, 200 * 256, 1, -32000, 60)};
    for (const char* name : {"quake-subdiv16", "quake-subdiv8", "quake-d_draw16"}) {
        const Mapper& m = *find_mapper(name);
        PolygonMeter meter(m, Axis::Rows);
        Tightness tight;
        EXPECT_TRUE(check_polygon(meter, m, Axis::Rows, p, tex, &tight, name)) << name << ": a finite bound";
        bool drawn = false;
        AccuracyMetrics e = meter.measure(p.data(), int(p.size()), tex, &drawn, [](int32_t, int32_t, bool, bool, double) {});
        EXPECT_TRUE(drawn);
        EXPECT_LE(e.max_texel_error, 1u) << name;
    }
}

// Found with extreme depths: a quad whose planes (through three of its vertices) put Q = 1/w at or
// below 0 at the fourth, so Q crosses 0 on some spans. The span bounds assumed Q > 0 (t'' largest
// where Q is least, the footprint least where Q is largest): the coarse chord bound came out below
// a texel where constant-depth erred by 128 footprints. Now no bound where Q is not positive.
TEST(Bounds, NoBoundWhereQIsNotPositive) {
    std::vector<uint8_t> texels(256 * 256);
    generate_texture(TextureKind::Xor, 256, 256, texels.data());
    Texture tex{texels.data(), 256, 256, Wrap::Repeat};
    TextureCopies copies(&tex);
    const std::vector<Vertex> p = {{snap(206.9570), snap(-81.6484), 0.000233777472, -417.951969, -179.658735},
                                   {snap(299.7500), snap(27.8164), 0.000183679473, -264.901175, -289.130108},
                                   {snap(190.2852), snap(120.6094), 2358196.74, -155.429802, -136.079315},
                                   {snap(97.4922), snap(11.1445), 1984981.56, -308.480596, -26.6079415}};
    for (const char* name : {"constant-depth", "persp-subdiv-16", "persp-adaptive-1", "affine", "auto"})
        for (Axis axis : {Axis::Rows, Axis::Columns}) {
            const Mapper& m = *find_mapper(name);
            PolygonMeter meter(m, axis);
            Tightness tight;
            check_polygon(meter, m, axis, p, tex, &tight, std::string(name) + (axis == Axis::Rows ? " rows" : " columns"));
        }
}

TEST(Bounds, NoMapperExceedsItsBoundOnTheDemoScenes) {
    for (const DemoScene& d : demo_scenes()) {
        LoadedWorld w = load_world_file(std::string("scenes/") + d.name + ".scene");
        std::vector<std::unique_ptr<HostFrame>> frames;  // the bench's: 8 spread over the animation
        for (int f = 0; f < 8; f += SANITIZED_SHARE) frames.push_back(world_frame(w, int32_t(int64_t(f) * w.world->frames / 8)));
        for (int i = 0; i < MAPPER_COUNT; ++i) {
            const Mapper& m = MAPPERS[i];
            if (m.bound == unbounded || !bound_mapper_taken(m)) continue;
            Axis axis = home_axis(m);
            PolygonMeter meter(m, axis);
            Tightness tight;
            for (size_t fi = 0; fi < frames.size(); ++fi) {
                const int f = int(fi) * SANITIZED_SHARE;
                const Frame* frame = frames[fi].get();
                const Vertex* v = frame->vertices;
                for (int32_t k = 0; k < frame->polygon_count; ++k) {
                    int n = frame->polygon_size[k];
                    std::vector<Vertex> p(v, v + n);
                    check_polygon(meter, m, axis, p, w.textures->objects[frame->polygon_object[k]], &tight,
                                  std::string(d.name) + " frame " + std::to_string(f) + " polygon " + std::to_string(k) + " " + m.name);
                    v += n;
                    if (HasFailure()) return;
                }
            }
            std::printf("  %-9s %-16s %s\n", d.name, m.name, tight.text().c_str());
        }
    }
}

}  // namespace

// The chords' bound relative to the step (docs/bounds.md, "Chords, relative to the step"): where
// a pixel's deviation is at most X times its step plus r and its step at most its footprint F, its
// footprint error is ceil(X F + r) / max(1, F) at most; the bound must cover that for every F and
// reach it (as F comes down to where a texel more first appears).
// The certificates' n-th random case: an XOR texture of 1, 64 or 256 texels a side, repeating, with
// its copies, and a random polygon of class n % 6 (random_polygon).
struct CertificateCase {
    int32_t size;
    std::vector<uint8_t> texels;
    Texture tex;
    TextureCopies copies;
    std::vector<Vertex> p;
    int count;
    PolygonSetup s;  // every plane
    bool set_up;
    static std::vector<uint8_t> xor_texels(int32_t size) {
        std::vector<uint8_t> texels(size_t(size) * size_t(size));
        generate_texture(TextureKind::Xor, size, size, texels.data());
        return texels;
    }
    CertificateCase(TriangleGen& gen, int n)
        : size(n % 3 == 0 ? 1 : n % 3 == 1 ? 64 : 256), texels(xor_texels(size)), tex{texels.data(), size, size, Wrap::Repeat}, copies(&tex),
          p(random_polygon(gen, n % 6)), count(int(p.size())), set_up(setup_polygon(p.data(), count, &s, PLANES_ALL) == SetupStatus::Ok) {}
    // its texture coordinates k times as far apart (ranges of t beyond 16.16's chords)
    void stretch(double k) {
        for (Vertex& v : p) v.u *= k, v.v *= k;
        set_up = setup_polygon(p.data(), count, &s, PLANES_ALL) == SetupStatus::Ok;
    }
};

// fast-adaptive-1's certificate (auto's oriented candidate): wherever it holds, the mapper's own
// whole-polygon bound is within one footprint along that walker, and so is the measured error; it
// holds on many polygons inside the screen and never on one that reaches outside or on a clamped
// texture. Random polygons of every class, both walkers, textures of 1, 64 and 256 texels (make
// test 1800, make bounds MODEXLAB_BOUND_POLYGONS).
TEST(Bounds, FastAdaptiveCertificateImpliesItsBound) {
    const Mapper& m = *find_mapper("fast-adaptive-1");
    const ClipRect clip{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
    TriangleGen gen(20261126u);
    PolygonMeter meters[2] = {PolygonMeter(m, Axis::Rows), PolygonMeter(m, Axis::Columns)};
    int certified = 0, refused_inside = 0, outside = 0;
    const int polygons = std::max(1800 / SANITIZED_SHARE, polygons_per_mapper());
    for (int n = 0; n < polygons; ++n) {
        const CertificateCase c(gen, n);
        if (!c.set_up) continue;
        const PolygonSetup& s = c.s;
        const bool inside = s.min_x >= 0 && s.min_y >= 0 && s.max_x <= SCREEN_WIDTH * SUBPIXEL_ONE && s.max_y <= SCREEN_HEIGHT * SUBPIXEL_ONE;
        for (Axis axis : {Axis::Rows, Axis::Columns}) {
            const std::string what = "polygon " + std::to_string(n) + (axis == Axis::Rows ? " by rows" : " by columns");
            Texture clamped = c.tex;
            clamped.wrap = Wrap::Clamp;
            EXPECT_FALSE(fast_adaptive_certain<4>(s, clip, clamped, axis)) << what << ": a clamped texture";
            if (!fast_adaptive_certain<4>(s, clip, c.tex, axis)) {
                refused_inside += inside, outside += !inside;
                continue;
            }
            EXPECT_TRUE(inside) << what << ": certified, though it reaches outside the clip";
            ++certified;
            const ErrorBound whole = m.bound(BoundContext{m, c.tex, axis, clip, 1.0, nullptr, true}, c.p.data(), c.count);
            EXPECT_TRUE(whole.draws && whole.exact_coverage) << what;
            EXPECT_LE(whole.footprint, 1.0) << what << ": certified, but its whole-polygon bound is above one footprint";
            const AccuracyMetrics e = meters[int(axis)].measure(c.p.data(), c.count, c.tex);
            EXPECT_LE(e.max_footprint_error, 1 + SLACK) << what << ": measured above the certificate's footprint";
            if (HasFailure()) return;
        }
    }
    std::printf("fast-adaptive-1's certificate: %d of %d polygon-walkers, %d inside the screen refused, %d outside\n", certified,
                2 * polygons, refused_inside, outside);
    EXPECT_GT(certified, polygons / 6) << "the certificate holds on many polygons";
    EXPECT_GT(refused_inside, polygons / 20) << "and not on all of those inside the screen (strong perspective)";
    EXPECT_GT(outside, 0);
}

// Both certificates (fast-adaptive-1's and -2's) inside random clips (the screen less up to a
// quarter of it on each side), which cut many of the polygons: wherever one holds, the polygon lies inside the clip and its mapper's whole-polygon
// bound along that walker is within B.
TEST(Bounds, FastAdaptiveCertificatesHoldInsideAnyClip) {
    const Mapper* adaptive[2] = {find_mapper("fast-adaptive-1"), find_mapper("fast-adaptive-2")};
    TriangleGen gen(20261127u);
    int certified[2] = {0, 0}, cut = 0, chords = 0, n_budget = 0;
    const int polygons = std::max(3000 / SANITIZED_SHARE, polygons_per_mapper());
    for (int n = 0; n < polygons; ++n) {
        const CertificateCase c(gen, n);
        if (!c.set_up) continue;
        const PolygonSetup& s = c.s;
        // (the screen less up to a quarter of it on each side)
        auto in = [&](int32_t side) { return int32_t(gen.uniform(0, side / 4.0)); };
        const ClipRect clip{in(SCREEN_WIDTH), in(SCREEN_HEIGHT), SCREEN_WIDTH - in(SCREEN_WIDTH), SCREEN_HEIGHT - in(SCREEN_HEIGHT)};
        cut += !box_in_clip(s, clip);
        // fast-subdiv-N's chords bound from the same certificate: where within a budget of 1 to 4,
        // at least the mapper's whole bound asked with that budget
        const FastCertificate certificate = fast_certificate(s, clip, c.tex);
        EXPECT_TRUE(!certificate.holds || box_in_clip(s, clip));
        for (const char* name : {"fast-subdiv-8", "fast-subdiv-16", "fast-subdiv-32", "fast-constant-depth"})
            for (Axis axis : {Axis::Rows, Axis::Columns}) {
                const Mapper& m = *find_mapper(name);
                const double pixels = m.span == fast_subdiv_span<8> ? 8 : m.span == fast_subdiv_span<16> ? 16 : m.span == fast_subdiv_span<32> ? 32 : FAST_SPAN_LONG;
                const double bound = fast_chords_bound(certificate, s, axis, pixels), budget = double(1 + n_budget++ % 4);
                if (!(bound <= budget)) continue;
                ++chords;
                const ErrorBound whole = m.bound(BoundContext{m, c.tex, axis, clip, budget, nullptr, true}, c.p.data(), c.count);
                EXPECT_TRUE(whole.draws && whole.exact_coverage) << name << " polygon " << n;
                EXPECT_LE(whole.footprint, bound) << name << " polygon " << n << (axis == Axis::Rows ? " by rows" : " by columns") << ": its chords bound "
                                                  << bound << " within " << budget;
            }
        for (int two = 0; two < 2; ++two)
            for (Axis axis : {Axis::Rows, Axis::Columns}) {
                if (!(two ? fast_adaptive_certain<8>(s, clip, c.tex, axis) : fast_adaptive_certain<4>(s, clip, c.tex, axis))) continue;
                ++certified[two];
                const std::string what = "polygon " + std::to_string(n) + (axis == Axis::Rows ? " by rows" : " by columns") + " in clip " +
                                         std::to_string(clip.x0) + "," + std::to_string(clip.y0) + "-" + std::to_string(clip.x1) + "," + std::to_string(clip.y1);
                EXPECT_TRUE(box_in_clip(s, clip)) << what << ": certified, though the clip cuts it";
                const double within = two ? 2 : 1;
                const Mapper& m = *adaptive[two];
                const ErrorBound whole = m.bound(BoundContext{m, c.tex, axis, clip, within, nullptr, true}, c.p.data(), c.count);
                EXPECT_TRUE(whole.draws && whole.exact_coverage) << what;
                EXPECT_LE(whole.footprint, within) << what << ": certified within " << within;
                if (HasFailure()) return;
            }
    }
    std::printf("certified: fast-adaptive-1 %d, fast-adaptive-2 %d of %d polygon-walkers each (%d polygons cut by their clip); chords: %d\n",
                certified[0], certified[1], 2 * polygons, cut, chords);
    EXPECT_GT(chords, polygons / 10) << "the chords bound within a budget on many";
    EXPECT_GT(certified[0], polygons / 10);
    EXPECT_GT(certified[1], certified[0]) << "a budget of 2 certifies more";
    EXPECT_GT(cut, polygons / 4);
}

// fast-oriented-1's guard (auto's oriented path): on random polygons in random clips (a quarter
// with their texture coordinates stretched 4 to 40 times), wherever the object's check takes the
// polygon's own texels and the guard holds along a walker, fast-adaptive-1's whole bound is within
// one footprint (fast-adaptive-2's within two), the certificate from its spread holds with a Q_min
// at least the guard's; and wherever fast_constant_within says so for a budget, fast-constant-
// depth's whole bound is within it. The guard holds on most polygon-walkers the whole bound is
// within 1 on, cut or not.
TEST(Bounds, FastOrientedGuardImpliesTheCertificate) {
    const Mapper &adaptive = *find_mapper("fast-adaptive-1"), &adaptive2 = *find_mapper("fast-adaptive-2");
    const Mapper& constant = *find_mapper("fast-constant-depth");
    TriangleGen gen(20261129u);
    int guarded[2] = {0, 0}, certified[2] = {0, 0}, constant_within = 0, untaken = 0;  // [uncut, cut]
    const int polygons = std::max(3000 / SANITIZED_SHARE, polygons_per_mapper());
    for (int n = 0; n < polygons; ++n) {
        CertificateCase c(gen, n);
        if (n % 4 == 3) c.stretch(gen.uniform(4, 40));
        if (!c.set_up) continue;
        const PolygonSetup& s = c.s;
        auto in = [&](int32_t side) { return n % 2 ? 0 : int32_t(gen.uniform(0, side / 4.0)); };
        const ClipRect clip{in(SCREEN_WIDTH), in(SCREEN_HEIGHT), SCREEN_WIDTH - in(SCREEN_WIDTH), SCREEN_HEIGHT - in(SCREEN_HEIGHT)};
        const double most = texel_most(c.p);
        if (!fast_oriented_guard_takes(most, clip)) {
            ++untaken;
            continue;
        }
        const bool cut = !box_in_clip(s, clip);
        PolygonSpread spread;
        polygon_spread(s, clip, &spread);
        if (spread.corners == 0) continue;  // (its box meets the clip, the polygon not: nothing drawn)
        const FastCertificate f = fast_certificate(spread);
        for (Axis axis : {Axis::Rows, Axis::Columns}) {
            const std::string what = "polygon " + std::to_string(n) + (axis == Axis::Rows ? " by rows" : " by columns") + (cut ? " (cut)" : "");
            const ErrorBound whole = adaptive.bound(BoundContext{adaptive, c.tex, axis, clip, 1.0, nullptr, true}, c.p.data(), c.count);
            certified[cut] += whole.draws && whole.footprint <= 1.0;
            const double q_min = fast_oriented_guard(s, clip, axis, most);
            if (!(q_min > 0)) continue;
            ++guarded[cut];
            EXPECT_TRUE(f.holds) << what;
            EXPECT_LE(q_min, f.q_min) << what;
            EXPECT_TRUE(whole.draws && whole.footprint <= 1.0) << what << ": fast-adaptive-1's whole bound " << whole.footprint;
            const ErrorBound two = adaptive2.bound(BoundContext{adaptive2, c.tex, axis, clip, 2.0, nullptr, true}, c.p.data(), c.count);
            EXPECT_TRUE(two.draws && two.footprint <= 2.0) << what << ": fast-adaptive-2's whole bound " << two.footprint;
            for (double budget : {1.0, 2.0, 3.75}) {
                if (!fast_constant_within(s, clip, axis, q_min, fast_adaptive_room(budget))) continue;
                ++constant_within;
                const ErrorBound b = constant.bound(BoundContext{constant, c.tex, axis, clip, budget, nullptr, true}, c.p.data(), c.count);
                EXPECT_TRUE(b.draws && b.footprint <= budget) << what << ": fast-constant-depth's whole bound " << b.footprint << " above " << budget;
                EXPECT_LE(fast_chords_bound(f, s, axis, FAST_SPAN_LONG), budget) << what;
            }
            if (HasFailure()) return;
        }
    }
    std::printf("fast-oriented-1's guard: %d of %d polygon-walkers fast-adaptive-1's whole bound is within 1 on, %d of %d cut ones; "
                "fast-constant-depth within %d times; %d polygons' texels beyond the object's check\n",
                guarded[0], certified[0], guarded[1], certified[1], constant_within, untaken);
    // (the whole bound holds on more: where the chords of two pixels fail relative to the step, its
    // bound from the steps may still be within 1)
    EXPECT_GT(guarded[0], certified[0] * 3 / 5) << "the guard holds on most polygons the whole bound does";
    EXPECT_GT(guarded[1], certified[1] / 2) << "and on many the clip cuts";
    EXPECT_GT(constant_within, (guarded[0] + guarded[1]) / 4);
    EXPECT_LT(untaken, polygons / 2);
    // the object's check on the screen: the affine planes' terms within what the range of t leaves
    // for A (1 + 8 * 14 * W H) up to some 1.77e6 texels
    const ClipRect screen{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
    EXPECT_TRUE(fast_oriented_guard_takes(1.7e6, screen));
    EXPECT_FALSE(fast_oriented_guard_takes(1.8e6, screen));
    EXPECT_FALSE(fast_oriented_guard_takes(NO_BOUND, screen));
}

TEST(Bounds, RelativeChordsBoundCoversEveryFootprint) {
    raster::Random rng(4242u);
    auto error_at = [](double x, double r, double f) { return footprint_error(x * f + r, 0, f); };
    for (int n = 0; n < 2000; ++n) {
        const double x = n % 10 == 0 ? 0.0 : rng.unit() * (n % 3 ? 1.0 : 8.0), r = rng.unit() * (n % 2 ? 1e-3 : 0.999);
        const double bound = relative_chords_bound(x, r);
        double worst = std::max(error_at(x, r, 0), error_at(x, r, 1));
        for (double f = 1.0 / 1024; f < 64; f *= 1.01) worst = std::max(worst, error_at(x, r, f));
        for (int k = 0; k < 64 && x > 0; ++k) {  // just past each whole texel more, n0 + k
            const double jump = (std::ceil(x + r) + k - r) / x;
            if (jump > 1) worst = std::max(worst, error_at(x, r, jump * (1 + 1e-12)));
        }
        EXPECT_GE(bound, worst) << "X " << x << " r " << r;
        EXPECT_LE(bound, worst * (1 + 1e-6)) << "X " << x << " r " << r << ": as tight as its derivation says";
    }
    EXPECT_EQ(relative_chords_bound(0, 0), 0);
    EXPECT_GE(relative_chords_bound(-1, 0), NO_BOUND);
}

// A wall drawn by columns (1/w constant down each column): its chords lie on the exact mapping,
// and the relative bound settles it within a budget of 1 without the steps; by rows it does not
// (Q changes along them), and the bound from the steps is asked.
TEST(Bounds, RelativeChordsBoundSettlesConstantDepthLinesAlone) {
    const std::vector<Vertex> wall = {{snap(40), snap(20), 1, 0, 0}, {snap(200), snap(50), 4, 1024, 0},
                                      {snap(200), snap(150), 4, 1024, 256}, {snap(40), snap(180), 1, 0, 256}};
    PolygonSetup s;
    ASSERT_EQ(setup_polygon(wall.data(), int(wall.size()), &s, PLANES_ALL), SetupStatus::Ok);
    const ClipRect clip{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
    PolygonSpread columns, rows;
    polygon_spread(s, clip, &columns);
    polygon_spread(s, clip, &rows);
    EXPECT_EQ(spread_chords_bound(columns, s, Axis::Columns, 160, 3 * HALF_ULP_16_16, 1), 1);
    EXPECT_FALSE(columns.steps_known) << "settled without the steps";
    EXPECT_GT(spread_chords_bound(rows, s, Axis::Rows, 160, 3 * HALF_ULP_16_16, 1), 1);
    EXPECT_TRUE(rows.steps_known);
}

// The affine planes against the exact mapping over a polygon: at any point, with weights l_i of the
// corners, sum l_i t_i - sum l_i Q_i t_i / Q is within (t_max - t_min) times perspective_share. On
// random triangles and quads (points inside and on the edges, Q over ratios up to 10^4), never
// above; on a segment from Q = a to Q = b (t from 0 to 1) the deviation's largest is
// (sqrt(b) - sqrt(a)) / (sqrt(b) + sqrt(a)), at Q = sqrt(ab): the share is at least that and at most
// 4/3 of it (the cruder (b - a) / 2a is twice it or more: docs/bounds.md, "Planes").
TEST(Bounds, PerspectiveShareBoundsThePlanesDeviation) {
    raster::Random rng(2611u);
    for (int n = 0; n < 20000; ++n) {
        const int corners = n % 2 ? 4 : 3;
        const double ratio = std::pow(10.0, rng.unit() * 4);
        double q[4], t[4], q_lo = 1e300, q_hi = 0, t_lo = 1e300, t_hi = -1e300;
        for (int i = 0; i < corners; ++i) {
            q[i] = 0.01 * (1 + rng.unit() * (ratio - 1)), t[i] = (rng.unit() - 0.5) * 2000;
            q_lo = std::min(q_lo, q[i]), q_hi = std::max(q_hi, q[i]), t_lo = std::min(t_lo, t[i]), t_hi = std::max(t_hi, t[i]);
        }
        const double bound = (t_hi - t_lo) * perspective_share(q_lo, q_hi) * (1 + 1e-12) + 1e-9;
        for (int k = 0; k < 50; ++k) {
            double l[4], sum = 0;
            for (int i = 0; i < corners; ++i) sum += l[i] = k % 5 == 0 && i >= 2 ? 0.0 : rng.unit();  // every fifth on an edge
            double affine = 0, p = 0, qq = 0;
            for (int i = 0; i < corners; ++i) l[i] /= sum, affine += l[i] * t[i], p += l[i] * q[i] * t[i], qq += l[i] * q[i];
            ASSERT_LE(std::fabs(affine - p / qq), bound) << "corners " << corners << " ratio " << ratio;
        }
    }
    for (double b : {1.0001, 1.01, 1.5, 4.0, 11.0, 100.0, 1e4}) {
        const double a = 1, s = (std::sqrt(a * b) - a) / (b - a), q = (1 - s) * a + s * b;
        const double worst = std::fabs(s - s * b / q), sup = (std::sqrt(b) - std::sqrt(a)) / (std::sqrt(b) + std::sqrt(a));
        EXPECT_NEAR(worst, sup, 1e-12 * (1 + sup)) << b;
        EXPECT_GE(perspective_share(a, b), sup * (1 - 1e-12)) << b;
        EXPECT_LE(perspective_share(a, b), sup * 4 / 3 * (1 + 1e-12)) << b;
    }
    EXPECT_EQ(perspective_share(2, 2), 0);
}
