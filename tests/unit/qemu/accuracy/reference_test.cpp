// Under test: qemu/accuracy/reference.h.
// The reference against an independent brute-force evaluation, the exact mapper against the
// reference, and the affine mapper's error against what the maths predicts.
#include <gtest/gtest.h>

#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

// ---- an independent per-pixel evaluation -------------------------------------------------------
// Coverage from the top-left rule stated geometrically (the third vertex tells the inside, a top
// edge is horizontal with the third vertex below it, a left edge has the third vertex to its
// right); texture coordinates by barycentric weights in long double. Nothing from setup.cpp.

using i128 = __int128;

struct Brute {
    int64_t x[3], y[3];
    long double u[3], v[3], w[3];
};

Brute brute_of(const std::vector<Vertex>& p) {
    Brute b;
    for (int i = 0; i < 3; ++i) b.x[i] = p[size_t(i)].x.raw, b.y[i] = p[size_t(i)].y.raw, b.u[i] = p[size_t(i)].u,
                                    b.v[i] = p[size_t(i)].v, b.w[i] = p[size_t(i)].w;
    return b;
}

// u and v from the barycentric weights l (unnormalised), perspective-correct.
void barycentric_uv(const Brute& t, const long double* l, long double* u, long double* v) {
    long double num_u = 0, num_v = 0, den = 0;
    for (int i = 0; i < 3; ++i) {
        num_u += l[i] * t.u[i] / t.w[i];
        num_v += l[i] * t.v[i] / t.w[i];
        den += l[i] / t.w[i];
    }
    *u = num_u / den;
    *v = num_v / den;
}

i128 side(const Brute& t, int a, int b, i128 px, i128 py) {
    return i128(t.x[b] - t.x[a]) * (py - t.y[a]) - i128(t.y[b] - t.y[a]) * (px - t.x[a]);
}

bool top_or_left(const Brute& t, int a, int b, int c) {
    if (t.y[a] == t.y[b]) return t.y[c] > t.y[a];  // top: the third vertex lies below (y grows down)
    // left: the third vertex lies to the right of the edge, measured along its own row
    // c.x > a.x + (b.x - a.x) * (c.y - a.y) / (b.y - a.y), compared without dividing
    i128 lhs = i128(t.x[c] - t.x[a]) * (t.y[b] - t.y[a]);
    i128 rhs = i128(t.x[b] - t.x[a]) * (t.y[c] - t.y[a]);
    return t.y[b] > t.y[a] ? lhs > rhs : lhs < rhs;
}

bool brute_inside(const Brute& t, int32_t px, int32_t py) {
    i128 cx = i128(px) * 256 + 128, cy = i128(py) * 256 + 128;
    for (int e = 0; e < 3; ++e) {
        int a = e, b = (e + 1) % 3, c = (e + 2) % 3;
        i128 s = side(t, a, b, cx, cy), sc = side(t, a, b, t.x[c], t.y[c]);
        if (sc == 0) return false;
        if (s == 0) {
            if (!top_or_left(t, a, b, c)) return false;
        } else if ((s > 0) != (sc > 0)) {
            return false;
        }
    }
    return true;
}

// u and v at the pixel centre, perspective-correct, in long double.
void brute_uv(const Brute& t, int32_t px, int32_t py, long double* u, long double* v) {
    i128 cx = i128(px) * 256 + 128, cy = i128(py) * 256 + 128;
    long double l[3];
    for (int i = 0; i < 3; ++i) l[i] = (long double)side(t, (i + 1) % 3, (i + 2) % 3, cx, cy);
    barycentric_uv(t, l, u, v);
}

long double distance_to_integer(long double x) { return std::fabs(x - std::round(x)); }

TEST(Reference, AgreesWithAnIndependentBruteForceEvaluation) {
    TriangleGen gen(1234);
    const int32_t tex = 64;
    std::vector<uint8_t> texels(size_t(tex) * tex);
    generate_texture(TextureKind::Xor, tex, tex, texels.data());
    Texture texture{texels.data(), tex, tex, Wrap::Repeat};
    Picture pic(SCREEN_WIDTH, SCREEN_HEIGHT);
    long pixels = 0, near_ties = 0, worst_tie = 0;
    for (int trial = 0; trial < 1500 / SANITIZED_SHARE; ++trial) {
        std::vector<Vertex> p = gen.triangle();
        Brute b = brute_of(p);
        clear_pixel_image(pic.view, 0);
        SetupStatus st = reference_polygon(p.data(), 3, texture, pic.view);
        ASSERT_TRUE(st == SetupStatus::Ok || st == SetupStatus::Degenerate);
        for (int32_t y = 0; y < SCREEN_HEIGHT; ++y)
            for (int32_t x = 0; x < SCREEN_WIDTH; ++x) {
                size_t i = size_t(y) * SCREEN_WIDTH + size_t(x);
                bool in = brute_inside(b, x, y);
                ASSERT_EQ(pic.coverage[i] != 0, in) << "trial " << trial << " pixel " << x << "," << y;
                if (!in) continue;
                ++pixels;
                long double u, v;
                brute_uv(b, x, y, &u, &v);
                int32_t bu = wrap_coord(int32_t(std::floor(u)), tex, Wrap::Repeat), bv = wrap_coord(int32_t(std::floor(v)), tex, Wrap::Repeat);
                if (bu == pic.tu[i] && bv == pic.tv[i]) continue;
                // a texel boundary within rounding of the pixel centre: a tie double precision cannot settle
                ++near_ties;
                long double d = std::min(bu != pic.tu[i] ? distance_to_integer(u) : 1.0L, bv != pic.tv[i] ? distance_to_integer(v) : 1.0L);
                ASSERT_LT(d, 1e-9L) << "trial " << trial << " pixel " << x << "," << y << ": u " << double(u) << " v " << double(v);
                worst_tie = std::max<long>(worst_tie, long(d * 1e15L));
            }
    }
    RecordProperty("pixels", std::to_string(pixels));
    RecordProperty("near_ties", std::to_string(near_ties));
    std::printf("reference vs brute force: %ld pixels, %ld differ (all within 1e-9 texel of a texel boundary)\n", pixels, near_ties);
    EXPECT_GT(pixels, 2000000 / SANITIZED_SHARE);
    EXPECT_LT(near_ties, pixels / 100000 + 1) << "ties are rare";
}

// The reference's footprint (texel_footprint) against central differences of the brute-force
// mapping in long double: the larger of the texel steps across and down, each the larger of its
// u and v parts.
void brute_uv_at(const Brute& t, long double cx, long double cy, long double* u, long double* v) {
    long double l[3];
    for (int i = 0; i < 3; ++i) {
        int a = (i + 1) % 3, b = (i + 2) % 3;
        l[i] = (long double)(t.x[b] - t.x[a]) * (cy - t.y[a]) - (long double)(t.y[b] - t.y[a]) * (cx - t.x[a]);
    }
    barycentric_uv(t, l, u, v);
}

TEST(Reference, FootprintAgreesWithFiniteDifferences) {
    TriangleGen gen(4321);
    std::vector<uint8_t> texels(64 * 64, 1);
    Texture texture{texels.data(), 64, 64, Wrap::Repeat};
    Picture pic(SCREEN_WIDTH, SCREEN_HEIGHT);
    long checked = 0;
    long double worst = 0;
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<Vertex> p = gen.triangle();
        Brute b = brute_of(p);
        clear_pixel_image(pic.view, 0);
        if (reference_polygon(p.data(), 3, texture, pic.view) != SetupStatus::Ok) continue;
        for (size_t i = 0; i < pic.coverage.size(); i += 13) {
            if (!pic.coverage[i]) continue;
            long double cx = (long double)(i % SCREEN_WIDTH) * 256 + 128, cy = (long double)(i / SCREEN_WIDTH) * 256 + 128;
            const long double h = 0.0625L;  // subpixels: 1/4096 pixel either side
            long double u0, v0, u1, v1, steps[2];
            for (int axis = 0; axis < 2; ++axis) {
                brute_uv_at(b, cx - (axis == 0 ? h : 0), cy - (axis == 1 ? h : 0), &u0, &v0);
                brute_uv_at(b, cx + (axis == 0 ? h : 0), cy + (axis == 1 ? h : 0), &u1, &v1);
                long double scale = 256 / (2 * h);  // per pixel
                steps[axis] = std::max(std::fabs(u1 - u0), std::fabs(v1 - v0)) * scale;
            }
            long double want = std::max(steps[0], steps[1]), got = pic.footprint[i];
            long double error = std::fabs(got - want) / std::max(want, 1e-6L);
            worst = std::max(worst, error);
            ASSERT_LT(error, 1e-5L) << "trial " << trial << " pixel " << i << ": footprint " << double(got) << ", by differences " << double(want);
            ++checked;
        }
    }
    std::printf("footprint vs finite differences: %ld pixels, worst relative difference %.2g\n", checked, double(worst));
    EXPECT_GT(checked, 10000);
}

// ---- the exact mapper equals the reference ---------------------------------------------------

void expect_equal_pictures(const Picture& a, const Picture& b, const std::string& what) {
    for (size_t i = 0; i < a.index.size(); ++i) {
        ASSERT_EQ(a.coverage[i], b.coverage[i]) << what << " pixel " << i % SCREEN_WIDTH << "," << i / SCREEN_WIDTH;
        ASSERT_EQ(a.tu[i], b.tu[i]) << what << " pixel " << i % SCREEN_WIDTH << "," << i / SCREEN_WIDTH;
        ASSERT_EQ(a.tv[i], b.tv[i]) << what << " pixel " << i % SCREEN_WIDTH << "," << i / SCREEN_WIDTH;
        ASSERT_EQ(a.index[i], b.index[i]) << what << " pixel " << i % SCREEN_WIDTH << "," << i / SCREEN_WIDTH;
    }
}

TEST(ExactMapper, EqualsTheReferenceOnThousandsOfRandomTriangles) {
    TriangleGen gen(77);
    const struct {
        TextureKind kind;
        int32_t w, h;
        Wrap wrap;
    } textures[] = {{TextureKind::Grid, 64, 64, Wrap::Repeat}, {TextureKind::Xor, 256, 256, Wrap::Repeat},
                    {TextureKind::Gradient, 37, 300, Wrap::Repeat}, {TextureKind::Checker, 1024, 1, Wrap::Clamp},
                    {TextureKind::Grid, 100, 60, Wrap::Clamp}};
    int triangles = 0;
    for (int batch = 0; batch < 40; ++batch) {
        const auto& t = textures[batch % 5];
        auto scene = empty_scene(t.kind, t.w, t.h, t.wrap);
        for (int k = 0; k < 60; ++k, ++triangles) add_polygon(*scene, gen.triangle());
        LoadedScene s = make_loaded_scene(std::move(scene), "random");
        auto ref = render_reference(s);
        for (Axis axis : {Axis::Rows, Axis::Columns})
            expect_equal_pictures(*measure_mapper(s, *find_mapper({"exact", 5}), axis), *ref,
                                  "batch " + std::to_string(batch) + (axis == Axis::Rows ? " rows" : " columns"));
    }
    EXPECT_EQ(triangles, 2400);
}

// ---- the affine mapper's error follows the perspective it ignores ----------------------------

// A floor strip seen in perspective: w runs from 1 at the bottom edge to `ratio` at the top edge,
// v from 0 to 256 texels. Along a column, the exact v at screen fraction s (0 at the near edge)
// is V * s / (s + ratio * (1 - s)) ... the affine v is V * s; the largest gap between them is
// V * (sqrt(ratio) - 1) / (sqrt(ratio) + 1), at s = sqrt(ratio) / (sqrt(ratio) + 1).
double predicted_affine_error(double ratio, double span_texels) {
    double r = std::sqrt(ratio);
    return span_texels * (r - 1) / (r + 1);
}

TEST(AffineMapper, ErrorGrowsWithTheDepthRatioAsPredicted) {
    const double V = 256;
    double last = -1;
    for (double ratio : {1.0, 1.25, 1.5, 2.0, 3.0, 4.0, 8.0}) {
        auto scene = empty_scene(TextureKind::Grid, 1024, 1024, Wrap::Clamp);
        // near edge at y = 230 (w = 1), far edge at y = 10 (w = ratio); v runs 0 (near) .. 256 (far)
        add_polygon(*scene, {vertex(20, 230, 1, 0, 0), vertex(300, 230, 1, 256, 0), vertex(300, 10, ratio, 256, V)});
        add_polygon(*scene, {vertex(20, 230, 1, 0, 0), vertex(300, 10, ratio, 256, V), vertex(20, 10, ratio, 0, V)});
        LoadedScene s = make_loaded_scene(std::move(scene), "floor");
        auto ref = render_reference(s);
        AccuracyMetrics affine = compare_to_reference(ref->view, measure_mapper(s, *find_mapper({"affine", 6}), Axis::Columns)->view, 1024, 1024, Wrap::Clamp);
        AccuracyMetrics exact = compare_to_reference(ref->view, measure_mapper(s, *find_mapper({"exact", 5}), Axis::Columns)->view, 1024, 1024, Wrap::Clamp);
        double want = predicted_affine_error(ratio, V);
        EXPECT_NEAR(double(affine.max_texel_error), want, 1.5) << "ratio " << ratio;
        EXPECT_EQ(exact.max_texel_error, 0u) << "ratio " << ratio;
        EXPECT_EQ(affine.gaps + affine.overdraw + affine.overlaps, 0u);
        EXPECT_GE(double(affine.max_texel_error), last) << "error grows with the ratio";
        last = double(affine.max_texel_error);
        std::printf("affine vs reference, depth ratio %.2f: max texel error %u (predicted %.1f), mean %.2f\n", ratio,
                    affine.max_texel_error, want, affine.mean_texel_error);
    }
}

}  // namespace
