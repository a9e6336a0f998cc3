// Under test: kernel/core/setup.h, walk.h.
// The fill rule on meshes: fans, strips and grids of triangles sharing edges, at many subpixel
// offsets and rotations. Every pixel of the union is drawn exactly once by both walkers.
#include <gtest/gtest.h>

#include "tests/unit/kernel/core/raster_helpers.h"

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

namespace {

// The walker takes polygons under 64 pixels a side in 32 bits, relative to their box's pixel
// corner, and larger ones in 64 bits: each walks exactly the pixels covers() accepts, by rows and
// by columns, anywhere in the coordinate range (the clip moved to the polygon), with the run loop's
// view of the bounds (run/skip, stepping them) the same as next()'s, and a triangle's runs from
// triangle_runs (where it takes them) the same again; polygons on either side of the 64-pixel
// line, on and off the half-pixel grid.
TEST(FillRule, BothWidthsOfTheWalkerCoverExactlyTheCoveredPixels) {
    TriangleGen gen(20261124u);
    int small = 0, large = 0, runs = 0;
    for (int n = 0; n < 3000 / SANITIZED_SHARE; ++n) {
        const double size = n % 2 ? gen.uniform(0.2, 63.9) : gen.uniform(60, 140);
        const double cx = gen.uniform(-16000, 16000), cy = gen.uniform(-16000, 16000);
        std::vector<Vertex> p;
        for (int i = 0; i < 3 + int(n % 3 == 0); ++i) {
            Vertex v = vertex(cx + gen.uniform(0, size), cy + gen.uniform(0, size));
            if (n % 5 == 0) v = vertex_raw(v.x.raw & ~127, v.y.raw & ~127);
            p.push_back(v);
        }
        PolygonSetup s;
        if (setup_polygon(p.data(), int(p.size()), &s, PLANES_NONE) != SetupStatus::Ok) continue;
        const bool is_small = s.max_x - s.min_x < (64 << SUBPIXEL_BITS) && s.max_y - s.min_y < (64 << SUBPIXEL_BITS);
        (is_small ? small : large) += 1;
        const int32_t x0 = int32_t(floor_div(s.min_x, SUBPIXEL_ONE)) - 1, y0 = int32_t(floor_div(s.min_y, SUBPIXEL_ONE)) - 1;
        const int32_t x1 = int32_t(floor_div(s.max_x, SUBPIXEL_ONE)) + 2, y1 = int32_t(floor_div(s.max_y, SUBPIXEL_ONE)) + 2;
        // a clip cutting a corner off now and then
        const ClipRect clip = n % 7 == 0 ? ClipRect{x0 + (x1 - x0) / 3, y0, x1, y1 - (y1 - y0) / 4} : ClipRect{x0, y0, x1, y1};
        for (Axis axis : {Axis::Rows, Axis::Columns}) {
            std::vector<int> seen(size_t(x1 - x0) * size_t(y1 - y0), 0), stepped(seen.size(), 0);
            auto mark = [&](std::vector<int>& v, int32_t x, int32_t y) { v[size_t(y - y0) * size_t(x1 - x0) + size_t(x - x0)] += 1; };
            EdgeWalker w(s, axis, clip);
            Span span;
            while (w.next(&span))
                for (int32_t k = 0; k < span.count; ++k) mark(seen, span.x + (axis == Axis::Rows ? k : 0), span.y + (axis == Axis::Rows ? 0 : k));
            // the run loop's way: runs of lines between two bounds, stepped in place
            EdgeWalker r(s, axis, clip);
            for (;;) {
                int32_t line;
                EdgeBound *lo, *hi;
                const int32_t lines = r.run(&line, &lo, &hi);
                if (lines == 0) {
                    if (!r.next(&span)) break;
                    for (int32_t k = 0; k < span.count; ++k) mark(stepped, span.x + (axis == Axis::Rows ? k : 0), span.y + (axis == Axis::Rows ? 0 : k));
                    continue;
                }
                for (int32_t l = 0; l < lines; ++l, lo->step(), hi->step()) {
                    const int32_t a = std::max(lo->q, r.minor_lo()), b = std::min(hi->q, r.minor_hi());
                    for (int32_t m = a; m <= b; ++m) mark(stepped, axis == Axis::Rows ? m : line + l, axis == Axis::Rows ? line + l : m);
                }
                r.skip(lines);
            }
            // a triangle's rows from triangle_runs (the fast drivers'), where it takes them
            std::vector<int> fused(seen.size(), 0);
            EdgeBound lower[3], upper[3];
            TriangleRunsArgs t{&s, clip.y0, clip.y1 - 1, lower, upper, 0, 0, nullptr, nullptr, 0, nullptr, nullptr};
            const bool taken = axis == Axis::Rows && s.edge_count == 3 && triangle_runs(&t);
            if (taken) {
                ++runs;
                const int32_t lines[2] = {t.lines, t.lines > 0 ? t.next_lines : 0};
                EdgeBound* bounds[2][2] = {{t.run_lower, t.run_upper}, {t.next_lower, t.next_upper}};
                for (int32_t run = 0, line = t.line; run < 2; ++run)
                    for (int32_t l = 0; l < lines[run]; ++l, ++line, bounds[run][0]->step(), bounds[run][1]->step()) {
                        const int32_t a = std::max(bounds[run][0]->q, clip.x0), b = std::min(bounds[run][1]->q, clip.x1 - 1);
                        for (int32_t m = a; m <= b; ++m) mark(fused, m, line);
                    }
            }
            for (int32_t y = y0; y < y1; ++y)
                for (int32_t x = x0; x < x1; ++x) {
                    const bool inside = covers(s, x, y) && x >= clip.x0 && x < clip.x1 && y >= clip.y0 && y < clip.y1;
                    const size_t k = size_t(y - y0) * size_t(x1 - x0) + size_t(x - x0);
                    ASSERT_EQ(seen[k], inside ? 1 : 0) << "polygon " << n << (axis == Axis::Rows ? " rows" : " columns") << " at " << x << "," << y;
                    ASSERT_EQ(stepped[k], seen[k]) << "polygon " << n << " run loop at " << x << "," << y;
                    ASSERT_EQ(fused[k], taken ? seen[k] : 0) << "polygon " << n << " triangle_runs at " << x << "," << y;
                }
        }
    }
    EXPECT_GT(small, 500 / SANITIZED_SHARE);
    EXPECT_GT(large, 500 / SANITIZED_SHARE);
    EXPECT_GT(runs, 300 / SANITIZED_SHARE) << "small triangles walked by triangle_runs";
}

}  // namespace
