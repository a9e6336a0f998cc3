// Under test: kernel/core/envelope.h.
// The object's envelope (docs/auto.md, "The object's envelope"): its bound on a triangle is
// never below what the triangle's own spread gives (spread_planes_deviation, the fast mappers'
// whole-polygon bound) nor below the error fast-affine measures on it: on random triangles fitted
// tightly by their envelope (tiny to the reach guard's limit, slivers up to the conditioning
// guard's, texels up to MAX_UV, perspective up to rho = 0.99) and on every uncut triangle of every
// demo scene at the bench's frames, whose envelopes build_frame measures. And auto draws an
// object so proven as the proven mapper does, pixel for pixel. MODEXLAB_BOUND_POLYGONS sets the
// random triangles (make bounds: 100000).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <string>

#include "kernel/core/envelope.h"
#include "kernel/mappers/auto/choice.h"
#include "kernel/mappers/auto/draw.h"
#include "kernel/core/footprint.h"
#include "kernel/core/policy.h"
#include "kernel/core/spread.h"
#include "qemu/tools/demo_scenes.h"
#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

int random_triangles() {
    const char* env = std::getenv("MODEXLAB_BOUND_POLYGONS");
    return env ? std::max(1, std::atoi(env)) : 20000 / SANITIZED_SHARE;
}

// The triangle's own bound of the fast mappers' planes (its spread, set up with every plane), where
// it passes the guards.
bool spread_deviation(const Vertex* t, double d[2]) {
    PolygonSetup s;
    if (setup_polygon(t, 3, &s, PLANES_ALL) != SetupStatus::Ok || !envelope_guards(s)) return false;
    EXPECT_TRUE(planes_fit_16_16(s)) << "the guards hold the steps in 16.16";
    PolygonSpread p;
    constexpr ClipRect EVERYWHERE{-(1 << 24), -(1 << 24), 1 << 24, 1 << 24};  // the whole triangle, uncut
    polygon_spread(s, EVERYWHERE, &p);
    EXPECT_GT(p.q_min, 0);
    spread_planes_deviation(p, (1 + p.reach) * HALF_ULP_16_16, d);
    return true;
}

// The envelope that fits the triangle as tightly as it may: its own largest |t|, ranges and depth
// ratio (rounded up).
TriangleEnvelope fitted(const Vertex* t) {
    TriangleEnvelope e{};
    double w_lo = t[0].w, w_hi = t[0].w;
    for (int k = 0; k < 2; ++k) {
        double lo = k ? t[0].v : t[0].u, hi = lo;
        for (int i = 0; i < 3; ++i) {
            const double x = k ? t[i].v : t[i].u;
            lo = std::min(lo, x), hi = std::max(hi, x);
            e.texel_abs[k] = std::max(e.texel_abs[k], std::abs(x));
        }
        e.texel_range[k] = hi - lo;
    }
    for (int i = 0; i < 3; ++i) w_lo = std::min(w_lo, t[i].w), w_hi = std::max(w_hi, t[i].w);
    e.depth_ratio = std::nextafter((w_hi - w_lo) / w_lo, 1.0) * (1 + 1e-15);
    return e;
}

const Texture& aligned_texture() {
    static std::vector<uint8_t> texels(256 * 256);
    static Texture tex{texels.data(), 256, 256, Wrap::Repeat};
    static bool made = false;
    if (!made) {
        generate_texture(TextureKind::Xor, 256, 256, texels.data());
        static TextureCopies copies(&tex);
        made = true;
    }
    return tex;
}

// The worst and median of spread / envelope deviation, and of measured / envelope footprint.
struct Ratios {
    std::vector<double> deviation;
    double worst_measured = 0;
    std::string text() {
        if (deviation.empty()) return "none";
        std::sort(deviation.begin(), deviation.end());
        char buf[128];
        std::snprintf(buf, sizeof buf, "spread / envelope: median %.3f, worst %.3f; measured / envelope worst %.3f",
                      deviation[deviation.size() / 2], deviation.back(), worst_measured);
        return buf;
    }
};

// Checks the envelope's bound against the triangle's spread and, with `meter`, against the error
// fast-affine measures on it; returns whether the triangle passed the guards.
bool check_triangle(const Vertex* t, const EnvelopeBound& e, PolygonMeter* meter, const Texture& tex, Ratios* r, const std::string& what) {
    double d[2];
    if (!spread_deviation(t, d)) return false;
    for (int k = 0; k < 2; ++k) {
        EXPECT_LE(d[k], e.deviation[k]) << what << (k ? ": v" : ": u") << " deviation, rho " << e.envelope.depth_ratio;
        if (e.deviation[k] > 0) r->deviation.push_back(d[k] / e.deviation[k]);
    }
    if (meter) {
        bool drawn = false;
        AccuracyMetrics m = meter->measure(t, 3, tex, &drawn);
        EXPECT_LE(m.max_footprint_error, e.footprint) << what << ": measured";
        if (drawn && e.footprint > 0) r->worst_measured = std::max(r->worst_measured, m.max_footprint_error / e.footprint);
    }
    return true;
}

TEST(Envelope, BoundsTheSpreadOfRandomTrianglesItFits) {
    const int count = random_triangles();
    std::mt19937 rng(20261124u);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    auto log_uniform = [&](double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); };
    PolygonMeter meter(*find_mapper("fast-affine"), Axis::Rows);
    Ratios r;
    int guarded = 0, slivers = 0;
    for (int n = 0; n < count; ++n) {
        // the corners: around a point of the screen, of a size from a fraction of a pixel to beyond
        // the reach guard; a third of them slivers (the third corner near the line of the others)
        const double size = log_uniform(0.2, 700), cx = uniform(-100, 420), cy = uniform(-100, 340);
        Vertex t[3];
        for (Vertex& v : t) v = vertex(cx + uniform(-size, size), cy + uniform(-size, size));
        if (n % 3 == 0) {
            const double s = uniform(0, 1), off = log_uniform(1e-3, 1);
            t[2] = Vertex{snap(t[0].x.to_double() + s * (t[1].x.to_double() - t[0].x.to_double()) + off),
                          snap(t[0].y.to_double() + s * (t[1].y.to_double() - t[0].y.to_double()) - off), 0, 0, 0};
        }
        // depth within rho, texels within a range about a centre of any magnitude MAX_UV allows
        const double rho = n % 7 == 0 ? uniform(0.5, 0.99) : log_uniform(1e-7, 0.5), w0 = log_uniform(0.01, 1e4);
        const double range = log_uniform(1e-3, 3e4), centre = n % 5 == 0 ? uniform(-1.6e7, 1.6e7) : uniform(-600, 600);
        for (Vertex& v : t) {
            v.w = w0 * (1 + uniform(0, rho));
            v.u = std::clamp(centre + uniform(-range, range) / 2, -MAX_UV, MAX_UV);
            v.v = std::clamp(-centre + uniform(-range, range) / 2, -MAX_UV, MAX_UV);
        }
        const EnvelopeBound e = envelope_bound(fitted(t));
        if (e.footprint >= NO_BOUND) continue;
        const bool sliver = n % 3 == 0;
        const bool measured = n % 8 == 0 && e.footprint < 1e6;
        const bool passed = check_triangle(t, e, measured ? &meter : nullptr, aligned_texture(), &r, "random triangle " + std::to_string(n));
        guarded += passed;
        slivers += passed && sliver;
        if (HasFailure()) return;
    }
    std::printf("  %d of %d random triangles within the guards (%d slivers); %s\n", guarded, count, slivers, r.text().c_str());
    EXPECT_GT(guarded, count / 3) << "most triangles pass the guards";
    EXPECT_GT(slivers, count / 20) << "slivers among them";
}

TEST(Envelope, HoldsOnEveryUncutTriangleOfTheDemoScenes) {
    PolygonMeter meter(*find_mapper("fast-affine"), Axis::Rows);
    for (const DemoScene& d : demo_scenes()) {
        LoadedWorld w = load_world_file(std::string("scenes/") + d.name + ".scene");
        Ratios r;
        int triangles = 0, bounded = 0, guarded = 0;
        for (int f = 0; f < 8; f += SANITIZED_SHARE) {  // the bench's frames
            auto frame = world_frame(w, int32_t(int64_t(f) * w.world->frames / 8));
            const Vertex* v = frame->vertices;
            for (int32_t k = 0; k < frame->polygon_count; v += frame->polygon_size[k], ++k) {
                if (!frame->polygon_whole[k] || frame->polygon_size[k] != 3) continue;
                ++triangles;
                const int o = frame->polygon_object[k];
                const EnvelopeBound& e = frame->envelope[o];
                const std::string what = std::string(d.name) + " frame " + std::to_string(f) + " polygon " + std::to_string(k);
                if (e.footprint >= NO_BOUND) continue;
                ++bounded;
                // what the envelope says of every uncut triangle of its object
                double w_lo = v[0].w, w_hi = v[0].w;
                for (int i = 0; i < 3; ++i) {
                    w_lo = std::min(w_lo, v[i].w), w_hi = std::max(w_hi, v[i].w);
                    EXPECT_LE(std::abs(v[i].u), e.envelope.texel_abs[0]) << what;
                    EXPECT_LE(std::abs(v[i].v), e.envelope.texel_abs[1]) << what;
                    for (int j = 0; j < 3; ++j) {
                        EXPECT_LE(std::abs(v[i].u - v[j].u), e.envelope.texel_range[0]) << what;
                        EXPECT_LE(std::abs(v[i].v - v[j].v), e.envelope.texel_range[1]) << what;
                    }
                }
                EXPECT_LE(w_hi / w_lo - 1, e.envelope.depth_ratio) << what;
                const Texture& tex = w.textures->objects[o];
                guarded += check_triangle(v, e, mapper_accepts(*find_mapper("fast-affine"), tex) ? &meter : nullptr, tex, &r, what);
                if (HasFailure()) return;
            }
        }
        std::printf("  %-9s %5d uncut triangles, %5d with an envelope, %5d within the guards; %s\n", d.name, triangles, bounded, guarded,
                    r.text().c_str());
        if (std::string(d.name) == "mesh") {
            EXPECT_GT(guarded, 1000) << "the mesh's triangles are proven by their envelope";
        }
    }
}

// The guards (envelope_guards) take exactly the triangles of the derivation's conditions, W + H <=
// the reach, 4 W H <= 65536 D and the 16.16 steps within 32766 texels, taken here in long double:
// boxes at and around each limit and up to setup's range (2^22 subpixels a coordinate), areas at
// and around 4 W H / 65536, steps at and around +-32766 texels.
TEST(Envelope, GuardsAreTheDerivationsConditions) {
    std::mt19937 rng(20261129u);
    auto any = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
    constexpr int64_t REACH = int64_t(ENVELOPE_REACH) * SUBPIXEL_ONE, STEP = int64_t(32766) << 16;
    int taken = 0, refused = 0;
    for (int n = 0; n < 200000; ++n) {
        PolygonSetup s{};
        s.edge_count = 3;
        const int64_t w = n % 50 == 0 ? any(0, int64_t(1) << 23) : any(0, REACH), left = std::max<int64_t>(REACH - w, 0), h = n % 3 == 0 ? std::max<int64_t>(left + any(-2, 2), 0) : any(0, left + 2);
        s.min_x = any(-100000, 100000), s.max_x = s.min_x + w;
        s.min_y = any(-100000, 100000), s.max_y = s.min_y + h;
        const int64_t edge = (4 * w * h) / 65536;
        s.area2 = std::max<int64_t>(1, n % 2 ? edge + any(-2, 2) : any(1, std::max<int64_t>(2, 2 * edge)));
        int32_t* steps[4] = {&s.u_fx.dx, &s.u_fx.dy, &s.v_fx.dx, &s.v_fx.dy};
        for (int32_t* t : steps) *t = int32_t(n % 5 == 0 ? (any(0, 1) ? 1 : -1) * (STEP + any(-2, 2)) : any(-STEP, STEP));
        const long double lw = (long double)(s.max_x - s.min_x), lh = (long double)(s.max_y - s.min_y);
        bool want = lw + lh <= (long double)REACH && 4 * lw * lh <= 65536.0L * (long double)s.area2;
        for (int32_t* t : steps) want = want && *t >= -STEP && *t <= STEP;
        ASSERT_EQ(envelope_guards(s), want) << "W " << w << " H " << h << " D " << s.area2 << " case " << n;
        ++(want ? taken : refused);
    }
    EXPECT_GT(taken, 20000);
    EXPECT_GT(refused, 20000);
}

// A mesh the parser did not measure (built some other way) has no envelope: nothing is proven.
TEST(Envelope, NoneForAMeshNotMeasured) {
    LoadedWorld w = load_world_file("scenes/mesh.scene");
    EXPECT_LT(world_frame(w, 0)->envelope[0].footprint, NO_BOUND);
    w.world->meshes[w.world->objects[0].mesh].measured = false;
    EXPECT_GE(world_frame(w, 0)->envelope[0].footprint, NO_BOUND);
}

// On the mesh at a budget its envelope meets, auto draws every triangle that passes the guards with
// the mapper the envelope proves, as that mapper draws alone; at a budget below the envelope's
// bound, none so.
TEST(Envelope, AutoDrawsAnEnvelopedObjectAsTheProvenMapperDoes) {
    LoadedWorld w = load_world_file("scenes/mesh.scene");
    const Mapper& a = *find_mapper("auto");
    const Mapper& fast = *find_mapper("fast-affine");
    for (int f = 0; f < 8; f += 2 * SANITIZED_SHARE) {
        auto frame = world_frame(w, int32_t(int64_t(f) * w.world->frames / 8));
        ASSERT_LE(frame->envelope[0].footprint, 1.0) << "the mesh's envelope within one footprint";
        frame->budget = Budget{true, 1, true};
        RenderStats by_auto, alone;
        IndexImage chosen = render_world_frame(w, *frame, a, Axis::Rows, &by_auto);
        IndexImage proven = render_world_frame(w, *frame, fast, Axis::Rows, &alone);
        EXPECT_TRUE(chosen.index == proven.index) << "frame " << f;
        EXPECT_EQ(by_auto.polygons, alone.polygons);
        EXPECT_EQ(by_auto.mapper_polygons[&fast - MAPPERS], by_auto.polygons) << "frame " << f;
        EXPECT_GT(by_auto.enveloped, by_auto.polygons * 9 / 10) << "frame " << f << ": proven by the envelope";
        frame->budget = Budget{true, 0.5, true};
        RenderStats tighter;
        render_world_frame(w, *frame, a, Axis::Rows, &tighter);
        EXPECT_EQ(tighter.enveloped, 0u) << "frame " << f << ": the envelope's bound is above 0.5";
    }
}

// The plan weighs the enveloped mapper against every other candidate over the triangles the guards
// let through: where one costs less a pixel (fast-table against fast-affine), the envelope takes
// triangles only up to the area where that one, proven, would not yet be the cheaper on one line,
// and where one costs less a line, only up to as many lines as take half of what its setup costs
// more; a larger or taller triangle goes to the choice, a smaller one is drawn by the envelope.
TEST(Envelope, TakesTrianglesOnlyUpToTheSizeWhereNoOtherCandidateUndercutsIt) {
    std::vector<uint8_t> texels(64 * 64, 3);
    Texture tex{texels.data(), 64, 64, Wrap::Repeat};
    TextureCopies copies(&tex);
    Target target = surface_kind(Surface::Linear);
    target.clip = ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
    const Budget budget{true, 2, true};
    const AutoPlan plan = plan_auto(budget, tex, target, 1.0);
    const Mapper &fast = *find_mapper("fast-affine"), &table = *find_mapper("fast-table");
    ASSERT_EQ(plan.enveloped, &fast);
    ASSERT_LT(plan.enveloped_area2, INT64_MAX) << "fast-table costs less a pixel: a limit";
    // up to the limit, fast-table with its proof costs no less on one line than fast-affine without
    // (fast-table's line costs about as much: the limit may come from it or a dearer candidate)
    const double one = double(SUBPIXEL_ONE), pixels = double(plan.enveloped_area2) / (2 * one * one);
    const CostRow own = cost_row(MAPPER_COSTS[&fast - MAPPERS]), other = proven_cost(table, cost_row(MAPPER_COSTS[&table - MAPPERS]), 1);
    // (where fast-table's line costs less, at the most lines the envelope takes)
    ASSERT_LE(plan.enveloped_extent, (ENVELOPE_REACH + 1) * SUBPIXEL_ONE);
    const double lines = other.span < own.span ? double(plan.enveloped_extent) / one : 1;
    EXPECT_GE(estimate_cost(other, PolygonSize{lines, pixels}), estimate_cost(own, PolygonSize{lines, pixels}) - 1);
    EXPECT_GT(pixels, 50);
    EXPECT_GT(lines, 50);
    // drawn through the envelope below it, chosen above it
    std::vector<uint8_t> surface(SCREEN_PIXELS);
    Target t = ram_target(surface.data(), false);
    const double side = std::sqrt(2 * pixels);  // a right triangle of side s has s^2 / 2 pixels
    for (double scale : {0.8, 1.25}) {
        const double s = side * scale;
        const std::vector<Vertex> tri{vertex(20, 20, 1, 0, 0), vertex(20 + s, 20, 1, 40, 0), vertex(20, 20 + s, 1, 0, 40)};
        RenderStats stats;
        Drawer d = Drawer::of(fast, tex, Axis::Rows, t, &stats, Variant::Twin, true);
        d.limits.area2 = plan.enveloped_area2;
        d.limits.extent_y = plan.enveloped_extent;
        EXPECT_EQ(draw_enveloped(d, tri.data(), Variant::Twin, budget), SetupStatus::Ok);
        EXPECT_EQ(stats.enveloped, scale < 1 ? 1u : 0u) << "a triangle of " << s * s / 2 << " pixels against a limit of " << pixels;
        EXPECT_EQ(stats.polygons, 1u);
    }
    // a sliver a pixel wide (h / 2 pixels), below the area limit, about the line limit
    if (plan.enveloped_extent < (ENVELOPE_REACH + 1) * SUBPIXEL_ONE) {
        for (double scale : {0.8, 1.25}) {
            const double h = lines * scale;
            ASSERT_LT(h / 2, pixels);
            const std::vector<Vertex> tri{vertex(20, 10, 1, 0, 0), vertex(21, 10, 1, 2, 0), vertex(20, 10 + h, 1, 0, 40)};
            RenderStats stats;
            Drawer d = Drawer::of(fast, tex, Axis::Rows, t, &stats, Variant::Twin, true);
            d.limits.area2 = plan.enveloped_area2;
            d.limits.extent_y = plan.enveloped_extent;
            EXPECT_EQ(draw_enveloped(d, tri.data(), Variant::Twin, budget), SetupStatus::Ok);
            EXPECT_EQ(stats.enveloped, scale < 1 ? 1u : 0u) << "a sliver of " << h << " lines against a limit of " << lines;
        }
    }
}

}  // namespace
