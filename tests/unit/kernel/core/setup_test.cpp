// Under test: kernel/core/setup.h, walk.h.
// Polygon setup and the edge walkers: orientation, degenerate and bad input, planes, and the
// walkers against the per-pixel definition covers().
#include <gtest/gtest.h>

#include <cstring>

#include "kernel/core/random.h"
#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

SetupStatus setup(const std::vector<Vertex>& p, PolygonSetup* s = nullptr) {
    PolygonSetup tmp;
    return setup_polygon(p.data(), int(p.size()), s ? s : &tmp);
}

TEST(Setup, BothWindingsCoverTheSamePixelsWithTheSamePlanes) {
    std::vector<Vertex> cw = {vertex(10.3, 10.7, 1, 0, 0), vertex(200.1, 30.2, 2, 64, 0), vertex(60.6, 180.4, 4, 0, 64)};
    std::vector<Vertex> ccw = {cw[0], cw[2], cw[1]};
    PolygonSetup a, b;
    ASSERT_EQ(setup(cw, &a), SetupStatus::Ok);
    ASSERT_EQ(setup(ccw, &b), SetupStatus::Ok);
    for (int32_t y = 0; y < 200; ++y)
        for (int32_t x = 0; x < 220; ++x) {
            ASSERT_EQ(covers(a, x, y), covers(b, x, y)) << x << "," << y;
            int32_t au, av, bu, bv;
            perspective_texel(a, centre_x(a, x), centre_y(a, y), &au, &av);
            perspective_texel(b, centre_x(b, x), centre_y(b, y), &bu, &bv);
            if (covers(a, x, y)) {
                EXPECT_NEAR(au, bu, 1);
                EXPECT_NEAR(av, bv, 1);
            }
        }
}

TEST(Setup, PlanesReproduceTheVertexAttributes) {
    std::vector<Vertex> p = {vertex(5, 7, 0.5, 3, -9), vertex(300, 20, 8, 1000, 5), vertex(150, 230, 2, -40, 700)};
    PolygonSetup s;
    ASSERT_EQ(setup(p, &s), SetupStatus::Ok);
    for (const Vertex& v : p) {
        double x = double(v.x.raw - s.ref_x), y = double(v.y.raw - s.ref_y);
        EXPECT_NEAR(s.q.at(x, y), 1 / v.w, 1e-12);
        EXPECT_NEAR(s.pu.at(x, y) / s.q.at(x, y), v.u, 1e-9);
        EXPECT_NEAR(s.pv.at(x, y) / s.q.at(x, y), v.v, 1e-9);
        EXPECT_NEAR(s.u.at(x, y), v.u, 1e-9);
        EXPECT_NEAR(s.v.at(x, y), v.v, 1e-9);
    }
}

// auto's oriented path sets the perspective planes up first and the affine ones after, where it
// hands the polygon to the choice: the same setup as every plane at once, field by field (random
// triangles, InRange or not, and quads of two of them).
TEST(Setup, PlanesInTurnEqualEveryPlaneAtOnce) {
    TriangleGen gen(20261129u);
    int compared = 0;
    for (int n = 0; n < 3000; ++n) {
        std::vector<Vertex> p = gen.triangle();
        if (n % 3 == 0) p.insert(p.begin() + 2, gen.random_vertex());  // (often not convex: refused by both)
        const Input input = n % 2 && p.size() == 3 ? Input::InRange : Input::Any;
        PolygonSetup all, turn;
        std::memset(&all, 0, sizeof all), std::memset(&turn, 0, sizeof turn);
        const SetupStatus status = setup_polygon(p.data(), int(p.size()), &all, PLANES_ALL, input);
        ASSERT_EQ(setup_polygon(p.data(), int(p.size()), &turn, PLANES_PERSPECTIVE, input), status) << n;
        if (status != SetupStatus::Ok) continue;
        ASSERT_EQ(setup_polygon(p.data(), int(p.size()), &turn, PLANES_AFFINE, input), status) << n;
        ++compared;
        ASSERT_EQ(std::memcmp(&all, &turn, sizeof all), 0) << "polygon " << n;
    }
    EXPECT_GT(compared, 1500);
}

// The convexity test runs in 32 bits within a box under 128 pixels a side, in 64 beyond, and a
// triangle skips the outline loops: scaling an outline by a power of two changes no sign of any
// edge function, so its verdict must not change from one path to the other; and a triangle
// given with a repeated corner (four corners: the generic path) must get the triangle's own.
TEST(Setup, EveryPathGivesTheSameVerdict) {
    raster::Random r(20261125);
    int verdicts[8] = {};
    for (int trial = 0; trial < 20000; ++trial) {
        const int n = r.range(3, 7);
        std::vector<Vertex> small(n);
        for (Vertex& v : small) v = vertex_raw(r.range(-40, 40) * 256 / 8, r.range(-40, 40) * 256 / 8);  // within 10 pixels of 0
        if (r.below(4) == 0 && n > 3) small[r.below(uint32_t(n))] = small[0];                             // a repeated corner
        if (r.below(8) == 0) {                                                                             // all on one line
            const int32_t dx = r.range(-64, 64), dy = r.range(-64, 64);
            for (Vertex& v : small) {
                const int32_t k = r.range(-40, 40);
                v = vertex_raw(dx * k, dy * k);
            }
        }
        const SetupStatus verdict = setup(small);
        ++verdicts[int(verdict)];
        for (int shift = 1; shift <= 10; ++shift) {  // boxes up to 40 pixels a side at 2, 20000 at 1024: both paths
            std::vector<Vertex> big = small;
            for (Vertex& v : big) v = vertex_raw(v.x.raw * (1 << shift), v.y.raw * (1 << shift));
            ASSERT_EQ(setup(big), verdict) << "trial " << trial << ", scaled by 2^" << shift;
        }
        if (n == 3) {
            std::vector<Vertex> four = {small[0], small[1], small[1], small[2]};
            ASSERT_EQ(setup(four), verdict) << "trial " << trial;
        }
    }
    // the outlines drew every verdict the test means to compare
    EXPECT_GT(verdicts[int(SetupStatus::Ok)], 1000);
    EXPECT_GT(verdicts[int(SetupStatus::NotConvex)], 1000);
    EXPECT_GT(verdicts[int(SetupStatus::Degenerate)], 100);
}

TEST(Setup, DegenerateInputDrawsNothing) {
    EXPECT_EQ(setup({vertex(0, 0), vertex(10, 10), vertex(20, 20)}), SetupStatus::Degenerate);      // collinear
    EXPECT_EQ(setup({vertex(5, 5), vertex(5, 5), vertex(5, 5)}), SetupStatus::Degenerate);          // a point
    EXPECT_EQ(setup({vertex(5, 5), vertex(9, 5), vertex(5, 5)}), SetupStatus::Degenerate);          // repeated
    EXPECT_EQ(setup({vertex(0, 0), vertex(1, 0)}), SetupStatus::Degenerate);                        // two vertices
    // a repeated vertex inside a quad is dropped, leaving a good triangle
    EXPECT_EQ(setup({vertex(0, 0), vertex(50, 0), vertex(50, 0), vertex(0, 50)}), SetupStatus::Ok);
    EXPECT_EQ(setup({vertex(0, 0), vertex(50, 0), vertex(0, 50), vertex(0, 0)}), SetupStatus::Ok);
}

TEST(Setup, RejectsWhatItCannotDraw) {
    EXPECT_EQ(setup({vertex(0, 0), vertex(50, 50), vertex(50, 0), vertex(0, 50)}), SetupStatus::NotConvex);  // bow tie
    EXPECT_EQ(setup({vertex(0, 0), vertex(50, 0), vertex(10, 10), vertex(0, 50)}), SetupStatus::NotConvex);  // concave
    std::vector<Vertex> star;  // a pentagram: every turn the same way, but it winds twice
    for (int k = 0; k < 5; ++k) star.push_back(vertex(100 + 50 * std::cos(k * 4 * M_PI / 5), 100 + 50 * std::sin(k * 4 * M_PI / 5)));
    EXPECT_EQ(setup(star), SetupStatus::NotConvex);
    // a triangle traced twice: every vertex on the inner side of every edge, but it winds twice
    EXPECT_EQ(setup({vertex(0, 0), vertex(50, 0), vertex(0, 50), vertex(0, 0.004), vertex(50, 0), vertex(0, 50)}), SetupStatus::NotConvex);
    EXPECT_EQ(setup({vertex(0, 0), vertex(50, 0), vertex(0, 50), vertex(0, 0), vertex(50, 0), vertex(0, 50)}), SetupStatus::NotConvex);
    std::vector<Vertex> many;
    for (int k = 0; k < 17; ++k) many.push_back(vertex(100 + 50 * std::cos(k * 2 * M_PI / 17), 100 + 50 * std::sin(k * 2 * M_PI / 17)));
    EXPECT_EQ(setup(many), SetupStatus::TooManyVertices);
    many.pop_back();
    EXPECT_EQ(setup(many), SetupStatus::Ok);
    auto with = [](double w, double u, double x) { return std::vector<Vertex>{vertex(0, 0, 1), vertex(x, 0, w, u), vertex(0, 10, 1)}; };
    EXPECT_EQ(setup(with(0, 0, 10)), SetupStatus::OutOfRange);
    EXPECT_EQ(setup(with(-1, 0, 10)), SetupStatus::OutOfRange);
    EXPECT_EQ(setup(with(std::nan(""), 0, 10)), SetupStatus::OutOfRange);
    EXPECT_EQ(setup(with(1, std::nan(""), 10)), SetupStatus::OutOfRange);
    EXPECT_EQ(setup(with(1, std::numeric_limits<double>::infinity(), 10)), SetupStatus::OutOfRange);
    EXPECT_EQ(setup(with(1, -std::numeric_limits<double>::infinity(), 10)), SetupStatus::OutOfRange);
    EXPECT_EQ(setup(with(std::numeric_limits<double>::infinity(), 0, 10)), SetupStatus::OutOfRange);
    EXPECT_EQ(setup(with(-std::numeric_limits<double>::infinity(), 0, 10)), SetupStatus::OutOfRange);
    for (double bad_v : {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
        std::vector<Vertex> p = with(1, 0, 10);
        p[1].v = bad_v;
        EXPECT_EQ(setup(p), SetupStatus::OutOfRange) << bad_v;
    }
    EXPECT_EQ(setup(with(1, 2 * MAX_UV, 10)), SetupStatus::OutOfRange);
    EXPECT_EQ(setup(with(1, 0, MAX_COORD_PIXELS + 1)), SetupStatus::OutOfRange);
    EXPECT_EQ(setup(with(MIN_W, MAX_UV, MAX_COORD_PIXELS)), SetupStatus::Ok);
    EXPECT_STREQ(setup_status_name(SetupStatus::NotConvex), "not convex");
}

ClipRect random_clip(TriangleGen& gen) {
    return ClipRect{int32_t(gen.rng() % 160), int32_t(gen.rng() % 120), 160 + int32_t(gen.rng() % 161), 120 + int32_t(gen.rng() % 121)};
}

// Both walkers yield each pixel covers() accepts inside the clip once, and no other (nothing for a
// polygon setup refuses); adds the covered pixels to *drawn.
void expect_walks_cover(const std::vector<Vertex>& p, const ClipRect& clip, int trial, int* drawn) {
    PolygonSetup s;
    if (setup(p, &s) != SetupStatus::Ok) return;
    for (Axis axis : {Axis::Rows, Axis::Columns}) {
        std::vector<int> counts = walk_counts({p}, axis, clip);
        for (int32_t y = 0; y < SCREEN_HEIGHT; ++y)
            for (int32_t x = 0; x < SCREEN_WIDTH; ++x) {
                bool inside_clip = x >= clip.x0 && x < clip.x1 && y >= clip.y0 && y < clip.y1;
                int want = inside_clip && covers(s, x, y) ? 1 : 0;
                ASSERT_EQ(counts[size_t(y) * SCREEN_WIDTH + size_t(x)], want)
                    << "trial " << trial << (axis == Axis::Rows ? " rows" : " columns") << " pixel " << x << "," << y;
                *drawn += want;
            }
    }
}

// Every pixel the walker yields is covered, every covered pixel inside the clip is yielded once,
// for both axes, random triangles and polygons and clip rectangles.
TEST(Walker, YieldsExactlyTheCoveredPixels) {
    TriangleGen gen(42);
    int drawn = 0;
    for (int trial = 0; trial < 3000 / SANITIZED_SHARE; ++trial) {
        std::vector<Vertex> p = gen.triangle();
        if (trial % 3 == 0) {  // a convex polygon: points on an ellipse
            p.clear();
            int n = 3 + int(gen.rng() % 14);
            double cx = gen.uniform(0, 320), cy = gen.uniform(0, 240), rx = gen.uniform(0.3, 150), ry = gen.uniform(0.3, 150);
            for (int k = 0; k < n; ++k) p.push_back(vertex(cx + rx * std::cos(k * 2 * M_PI / n), cy + ry * std::sin(k * 2 * M_PI / n)));
        }
        ClipRect clip{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
        if (trial % 2) clip = random_clip(gen);
        ASSERT_NO_FATAL_FAILURE(expect_walks_cover(p, clip, trial, &drawn));
    }
    EXPECT_GT(drawn, 1000000 / SANITIZED_SHARE) << "the trials drew something worth checking";
}

// The walker steps each edge only on the lines its extent spans (the polygon is convex): check that
// where it is easiest to get wrong. Vertices out to the coordinate limit with edges nearly along
// the lines, extra vertices in the middle of edges (collinear neighbours), edges and vertices
// exactly on pixel centres (the top-left rule decides), and one-line polygons.
TEST(Walker, ExtremesCollinearVerticesAndCentres) {
    TriangleGen gen(1234);
    const double far = MAX_COORD_PIXELS;
    int drawn = 0;
    for (int trial = 0; trial < 1500; ++trial) {
        std::vector<Vertex> p;
        switch (trial % 5) {
        case 0:  // huge: one vertex near the screen, two far out
            p = {vertex(gen.uniform(-50, 370), gen.uniform(-50, 290)), vertex(gen.uniform(-far, far), gen.uniform(-far, far)),
                 vertex(gen.uniform(-far, far), gen.uniform(-far, far))};
            break;
        case 1: {  // a needle across the screen, nearly along the rows or the columns
            double y = gen.uniform(0, 240), x = gen.uniform(0, 320), tilt = gen.uniform(-1, 1) / 256;
            if (gen.rng() % 2)
                p = {vertex(-far, y), vertex(far, y + tilt * 2 * far), vertex(gen.uniform(-far, far), y + gen.uniform(0.001, 3))};
            else
                p = {vertex(x, -far), vertex(x + tilt * 2 * far, far), vertex(x + gen.uniform(0.001, 3), gen.uniform(-far, far))};
            break;
        }
        case 2: {  // a triangle with a vertex added in the middle of each edge (on the grid)
            std::vector<Vertex> t = gen.triangle();
            for (int i = 0; i < 3; ++i) {
                const Vertex &a = t[size_t(i)], &b = t[size_t(i + 1) % 3];
                p.push_back(a);
                if ((a.x.raw + b.x.raw) % 2 == 0 && (a.y.raw + b.y.raw) % 2 == 0)
                    p.push_back(vertex_raw((a.x.raw + b.x.raw) / 2, (a.y.raw + b.y.raw) / 2));
            }
            break;
        }
        case 3: {  // an axis-aligned rectangle or a diamond, corners on pixel centres or pixel edges
            double half = gen.rng() % 2 ? 0.5 : 0.0;
            double x0 = double(gen.rng() % 300) + half, y0 = double(gen.rng() % 220) + half;
            double w = double(gen.rng() % 40), h = double(gen.rng() % 40);
            if (gen.rng() % 2) p = {vertex(x0, y0), vertex(x0 + w + 1, y0), vertex(x0 + w + 1, y0 + h + 1), vertex(x0, y0 + h + 1)};
            else p = {vertex(x0, y0 - h), vertex(x0 + w, y0), vertex(x0, y0 + h), vertex(x0 - w, y0)};
            break;
        }
        default:  // thin in the major direction: a few lines at most
            p = {vertex(gen.uniform(0, 320), gen.uniform(0, 240)), vertex(gen.uniform(0, 320), gen.uniform(0, 240)), vertex(0, 0)};
            p[2] = vertex_raw(p[0].x.raw + int32_t(gen.rng() % 2000) - 1000, p[1].y.raw + int32_t(gen.rng() % 512) - 256);
            break;
        }
        ClipRect clip{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
        if (trial % 4 == 1) clip = random_clip(gen);
        ASSERT_NO_FATAL_FAILURE(expect_walks_cover(p, clip, trial, &drawn));
    }
    EXPECT_GT(drawn, 1000000 / SANITIZED_SHARE) << "the trials drew something worth checking";
}

TEST(Walker, SpansComeInOrderInsideTheClip) {
    PolygonSetup s;
    ASSERT_EQ(setup({vertex(-500, -300), vertex(900, -100), vertex(100, 800)}, &s), SetupStatus::Ok);
    for (Axis axis : {Axis::Rows, Axis::Columns}) {
        ClipRect clip{3, 5, 300, 200};
        EdgeWalker w(s, axis, clip);
        Span sp;
        int32_t last = -1, lines = 0;
        while (w.next(&sp)) {
            int32_t line = axis == Axis::Rows ? sp.y : sp.x;
            EXPECT_GT(line, last);
            last = line;
            ++lines;
            EXPECT_GE(sp.x, clip.x0);
            EXPECT_GE(sp.y, clip.y0);
            EXPECT_LE((axis == Axis::Rows ? sp.x : sp.y) + sp.count, axis == Axis::Rows ? clip.x1 : clip.y1);
        }
        EXPECT_EQ(lines, axis == Axis::Rows ? 195 : 297) << "a triangle over the whole clip fills every line";
    }
}

TEST(Walker, SliversThinnerThanAPixel) {
    // long needles at every angle, 1/256 to 1 pixel thick: covered pixels only, never a crash
    TriangleGen gen(7);
    for (int trial = 0; trial < 2000; ++trial) {
        double a = gen.uniform(0, 2 * M_PI), len = gen.uniform(1, 400), thick = gen.uniform(1.0 / 256, 1);
        double x0 = gen.uniform(0, 320), y0 = gen.uniform(0, 240);
        double dx = std::cos(a), dy = std::sin(a);
        std::vector<Vertex> p = {vertex(x0, y0), vertex(x0 + dx * len, y0 + dy * len), vertex(x0 + dx * len - dy * thick, y0 + dy * len + dx * thick)};
        PolygonSetup s;
        if (setup(p, &s) != SetupStatus::Ok) continue;
        for (Axis axis : {Axis::Rows, Axis::Columns}) {
            std::vector<int> counts = walk_counts({p}, axis);
            for (int32_t y = 0; y < SCREEN_HEIGHT; ++y)
                for (int32_t x = 0; x < SCREEN_WIDTH; ++x)
                    ASSERT_EQ(counts[size_t(y) * SCREEN_WIDTH + size_t(x)], covers(s, x, y) ? 1 : 0);
        }
    }
}

}  // namespace
