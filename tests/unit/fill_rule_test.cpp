// The fill rule on meshes: fans, strips and grids of triangles sharing edges, at many subpixel
// offsets and rotations. Every pixel of the union is drawn exactly once by both walkers.
#include <gtest/gtest.h>

#include "tests/unit/raster_helpers.h"

namespace {

using namespace rastertest;

struct MeshCase {
    std::vector<std::vector<Vertex>> triangles;
    std::vector<Vertex> outline;  // the union: a convex polygon
};

// Checks every screen pixel: drawn exactly once inside the outline, never outside.
void expect_watertight(const MeshCase& m, const char* what, int trial) {
    PolygonSetup outline;
    ASSERT_EQ(setup_polygon(m.outline.data(), int(m.outline.size()), &outline), SetupStatus::Ok) << what << " " << trial;
    for (Axis axis : {Axis::Rows, Axis::Columns}) {
        std::vector<int> counts = walk_counts(m.triangles, axis);
        int holes = 0, overlaps = 0, outside = 0;
        for (int32_t y = 0; y < SCREEN_HEIGHT; ++y)
            for (int32_t x = 0; x < SCREEN_WIDTH; ++x) {
                int c = counts[size_t(y) * SCREEN_WIDTH + size_t(x)];
                bool in = covers(outline, x, y);
                holes += in && c == 0;
                overlaps += c > 1;
                outside += !in && c > 0;
            }
        ASSERT_EQ(holes, 0) << what << " trial " << trial << (axis == Axis::Rows ? " rows" : " columns");
        ASSERT_EQ(overlaps, 0) << what << " trial " << trial << (axis == Axis::Rows ? " rows" : " columns");
        ASSERT_EQ(outside, 0) << what << " trial " << trial << (axis == Axis::Rows ? " rows" : " columns");
    }
}

// A lattice origin + i*a + j*b in exact subpixel integers: the outline's sides are exactly straight
// at any rotation. Interior points are jittered; each cell is split along a random diagonal.
MeshCase grid(std::mt19937& rng, int cols, int rows) {
    auto r = [&](int lo, int hi) { return lo + int(rng() % unsigned(hi - lo + 1)); };
    double angle = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
    double cell = std::uniform_real_distribution<double>(3, 40)(rng) * 256;
    int32_t ax = int32_t(std::lround(cell * std::cos(angle))), ay = int32_t(std::lround(cell * std::sin(angle)));
    int32_t bx = -ay + r(-200, 200), by = ax + r(-200, 200);  // roughly perpendicular, not exactly
    int32_t ox = r(0, 320 * 256) - (cols * ax + rows * bx) / 2, oy = r(0, 240 * 256) - (cols * ay + rows * by) / 2;
    int32_t jitter = int32_t(cell / 6);
    std::vector<std::vector<Vertex>> p(size_t(cols + 1), std::vector<Vertex>(size_t(rows + 1)));
    for (int i = 0; i <= cols; ++i)
        for (int j = 0; j <= rows; ++j) {
            bool inner = i > 0 && i < cols && j > 0 && j < rows;
            int32_t jx = inner ? r(-jitter, jitter) : 0, jy = inner ? r(-jitter, jitter) : 0;
            p[size_t(i)][size_t(j)] = vertex_raw(ox + i * ax + j * bx + jx, oy + i * ay + j * by + jy);
        }
    MeshCase m;
    for (int i = 0; i < cols; ++i)
        for (int j = 0; j < rows; ++j) {
            const Vertex &a = p[size_t(i)][size_t(j)], &b = p[size_t(i + 1)][size_t(j)], &c = p[size_t(i + 1)][size_t(j + 1)], &d = p[size_t(i)][size_t(j + 1)];
            if (rng() % 2) {
                m.triangles.push_back({a, b, c});
                m.triangles.push_back({a, c, d});
            } else {
                m.triangles.push_back({a, b, d});
                m.triangles.push_back({b, c, d});
            }
        }
    m.outline = {p[0][0], p[size_t(cols)][0], p[size_t(cols)][size_t(rows)], p[0][size_t(rows)]};
    return m;
}

TEST(FillRule, GridsAtEveryRotationAreWatertight) {
    std::mt19937 rng(2024);
    for (int trial = 0; trial < 150; ++trial) expect_watertight(grid(rng, 1 + int(rng() % 8), 1 + int(rng() % 8)), "grid", trial);
}

TEST(FillRule, StripsAreWatertight) {
    std::mt19937 rng(99);
    for (int trial = 0; trial < 150; ++trial) expect_watertight(grid(rng, 2 + int(rng() % 20), 1), "strip", trial);
}

TEST(FillRule, FansAreWatertight) {
    std::mt19937 rng(7);
    int tested = 0;
    for (int trial = 0; tested < 200 && trial < 1000; ++trial) {
        int n = 3 + int(rng() % 14);
        double cx = std::uniform_real_distribution<double>(40, 280)(rng), cy = std::uniform_real_distribution<double>(40, 200)(rng);
        double radius = std::uniform_real_distribution<double>(2, 150)(rng), turn = std::uniform_real_distribution<double>(0, 1)(rng);
        MeshCase m;
        for (int k = 0; k < n; ++k) {
            double a = (k + turn + std::uniform_real_distribution<double>(-0.3, 0.3)(rng)) * 2 * M_PI / n;
            m.outline.push_back(vertex(cx + radius * std::cos(a), cy + radius * std::sin(a)));
        }
        PolygonSetup o;
        if (setup_polygon(m.outline.data(), n, &o) != SetupStatus::Ok) continue;  // snapping made it concave
        Vertex centre = vertex(cx + std::uniform_real_distribution<double>(-radius / 4, radius / 4)(rng), cy);
        if (!covers(o, int32_t(centre.x.floor_int()), int32_t(centre.y.floor_int()))) continue;
        for (int k = 0; k < n; ++k) m.triangles.push_back({centre, m.outline[size_t(k)], m.outline[size_t((k + 1) % n)]});
        expect_watertight(m, "fan", trial);
        ++tested;
    }
    EXPECT_EQ(tested, 200);
}

TEST(FillRule, PixelCentresExactlyOnSharedEdgesAndVertices) {
    // vertices on pixel centres: many centres lie exactly on the edges and at the vertices
    MeshCase m;
    auto c = [](int x, int y) { return vertex_raw(x * 256 + 128, y * 256 + 128); };
    std::vector<Vertex> pts = {c(10, 10), c(60, 10), c(110, 10), c(10, 60), c(60, 60), c(110, 60), c(10, 110), c(60, 110), c(110, 110)};
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            const Vertex &a = pts[size_t(3 * j + i)], &b = pts[size_t(3 * j + i + 1)], &d = pts[size_t(3 * j + i + 3)], &e = pts[size_t(3 * j + i + 4)];
            m.triangles.push_back({a, b, e});
            m.triangles.push_back({a, e, d});
        }
    m.outline = {pts[0], pts[2], pts[8], pts[6]};
    expect_watertight(m, "centred", 0);
    // the top-left rule: the outline's top and left sides are in, the bottom and right sides are out
    std::vector<int> counts = walk_counts(m.triangles, Axis::Rows);
    EXPECT_EQ(counts[10 * SCREEN_WIDTH + 10], 1);
    EXPECT_EQ(counts[10 * SCREEN_WIDTH + 110], 0);
    EXPECT_EQ(counts[110 * SCREEN_WIDTH + 10], 0);
    EXPECT_EQ(counts[60 * SCREEN_WIDTH + 60], 1);
}

}  // namespace
