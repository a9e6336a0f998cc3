// Under test: kernel/mappers/subdiv.h, fastsubdiv.h.
// fast-oriented-B (the end of this file): fast-adaptive-B along the walker it picks, walls by
// columns and floors by rows.
// persp-adaptive-B: its runs follow from the bound and the budget. Every run whose chord bound is
// not within the budget is a single pixel (the chooser could not do better there); a span of
// constant depth is one run; a looser budget never takes more runs; under strong perspective the
// runs differ in length along a span (long where 1/w barely changes). The drawn error against its
// bound is in bound_test.cpp (every mapper of the registry).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "kernel/core/bound.h"
#include "kernel/core/footprint.h"
#include "kernel/core/policy.h"
#include "kernel/core/spanline.h"
#include "kernel/core/spread.h"
#include "kernel/mappers/fastsubdiv.h"
#include "kernel/mappers/subdiv.h"
#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

// The runs along a span, as adaptive_run cuts it.
std::vector<int32_t> runs(const SpanLine& l, double budget) {
    std::vector<int32_t> out;
    const ChordTerms terms = chord_terms(l);
    for (int32_t k = 0; k < l.count;) {
        int32_t len = adaptive_run(l, terms, k, budget);
        EXPECT_GE(len, 1);
        EXPECT_LE(len, ADAPTIVE_LONGEST);
        if (len < 1) break;
        out.push_back(len);
        k += len;
    }
    return out;
}

TEST(Adaptive, RunsFollowTheBoundAndTheBudget) {
    TriangleGen gen(4242u);
    int varied = 0, spans = 0;
    const double budgets[] = {0.5, 1.0, 2.0, 4.0};
    size_t total[4] = {};
    for (int n = 0; n < 300; ++n) {
        gen.depth_ratio = n % 3 == 0 ? 1.001 : n % 3 == 1 ? 10 : 1000;
        std::vector<Vertex> p = gen.triangle();
        PolygonSetup s;
        if (setup_polygon(p.data(), 3, &s) != SetupStatus::Ok) continue;
        for (Axis axis : {Axis::Rows, Axis::Columns}) {
            EdgeWalker walker(s, axis, ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT});
            Span span;
            while (walker.next(&span)) {
                const SpanLine l = span_line(s, axis, span);
                for (int b = 0; b < 4; ++b) {
                    const double budget = budgets[b];
                    std::vector<int32_t> r = runs(l, budget);
                    total[b] += r.size();
                    int32_t k = 0;
                    for (int32_t len : r) {
                        const double end = k + len < l.count ? double(k + len) : double(l.count - 1);
                        if (len > 1) {
                            EXPECT_LE(chords_bound(l, len, k, end, (1 + len) * HALF_ULP_16_16), budget) << "a run of " << len << " at " << k;
                        }
                        k += len;
                    }
                    EXPECT_EQ(k, l.count);
                    if (budget == 1.0 && r.size() > 2) {
                        ++spans;
                        varied += *std::min_element(r.begin(), r.end() - 1) != *std::max_element(r.begin(), r.end() - 1);
                    }
                }
                if (HasFailure()) return;
            }
        }
    }
    for (int b = 1; b < 4; ++b) EXPECT_LT(total[b], total[b - 1]) << "budget " << budgets[b] << " takes no fewer runs than " << budgets[b - 1];
    EXPECT_GT(varied, spans / 10) << "runs of one length only: the chooser does not follow the depth (" << varied << " of " << spans << ")";
}

TEST(Adaptive, ASpanOfConstantDepthIsOneRun) {
    // a floor seen straight on: w constant along each row
    std::vector<Vertex> p = {vertex(40, 20, 2, 0, 0), vertex(280, 20, 2, 900, 0), vertex(280, 200, 5, 900, 500)};
    PolygonSetup s;
    ASSERT_EQ(setup_polygon(p.data(), 3, &s), SetupStatus::Ok);
    EdgeWalker walker(s, Axis::Rows, ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT});
    Span span;
    int checked = 0;
    while (walker.next(&span)) {
        const SpanLine l = span_line(s, Axis::Rows, span);
        ASSERT_EQ(runs(l, 1.0).size(), size_t(1)) << "row " << span.y << " of " << span.count << " pixels";
        ++checked;
    }
    EXPECT_GT(checked, 100);
}

// fast-adaptive-B: the room it allows a chord (X, in each pixel's own steps) keeps the relative
// chords bound within B at its rounding allowance, and no more room would.
TEST(FastAdaptive, TheRoomKeepsTheRelativeChordsBoundWithinTheBudget) {
    for (double budget : {1.0, 1.25, 1.5, 2.0, 3.0, 4.0, 7.75}) {
        const double room = fast_adaptive_room(budget);
        EXPECT_LE(relative_chords_bound(room, FAST_ADAPTIVE_ROUNDING), budget) << budget;
        EXPECT_GT(relative_chords_bound(room * 1.001, FAST_ADAPTIVE_ROUNDING), budget) << budget << ": room left unused";
    }
    EXPECT_EQ(fast_adaptive_room(0.75), 0) << "below one footprint no chord of two pixels is within";
}

// Each span's segments: the longest power of two from 2 to 512 pixels whose relative chords bound
// (h^2 |Q'| / (4 Q_lo)) stays within the room; 2 where none does; 512 where Q is constant.
TEST(FastAdaptive, EachSpanTakesTheLongestSegmentsWithinTheRoom) {
    std::mt19937 rng(909u);
    auto log_uniform = [&](double lo, double hi) { return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng)); };
    int seen[10] = {};
    for (int n = 0; n < 200000; ++n) {
        const double room = fast_adaptive_room(n % 2 ? 1.0 : 2.0);
        const double q_first = log_uniform(1e-6, 10), q_last = q_first * log_uniform(0.1, 10), q_pixel = log_uniform(1e-12, 10);
        const int32_t s = fast_adaptive_shift(q_first, q_last, q_pixel, room);
        ASSERT_GE(s, 1);
        ASSERT_LE(s, 9);
        ++seen[s];
        const double q_lo = std::min(q_first, q_last);
        auto within = [&](int32_t shift) { return std::ldexp(1.0, 2 * shift) * q_pixel / (4 * q_lo) <= room; };
        if (s > 1) {
            EXPECT_TRUE(within(s)) << q_first << " " << q_last << " " << q_pixel << ": 2^" << s << " is not within";
        }
        if (s < 9) {
            EXPECT_FALSE(within(s + 1)) << q_first << " " << q_last << " " << q_pixel << ": 2^" << s + 1 << " is within too";
        }
        if (HasFailure()) return;
    }
    for (int s = 1; s <= 9; ++s) EXPECT_GT(seen[s], 1000) << "shift " << s << " never taken";
    EXPECT_EQ(fast_adaptive_shift(1, 2, 0.0, fast_adaptive_room(1)), 9);
    EXPECT_EQ(fast_adaptive_shift(1, 2, -0.0, fast_adaptive_room(1)), 9) << "a gradient of -0 is constant Q too";
    EXPECT_EQ(fast_adaptive_shift(0, 2, 1e-9, fast_adaptive_room(1)), 1);
    EXPECT_EQ(fast_adaptive_shift(1, 1, 1e-300, fast_adaptive_room(1)), 9);
}

// Under strong perspective the segments follow the depth: over random triangles (depth ratios to
// 1000), the spans of one polygon take segments of different lengths.
TEST(FastAdaptive, SegmentsDifferFromSpanToSpanUnderPerspective) {
    TriangleGen gen(5151u);
    gen.depth_ratio = 1000;
    int polygons = 0, varied = 0;
    for (int n = 0; n < 300; ++n) {
        std::vector<Vertex> p = gen.triangle();
        PolygonSetup s;
        if (setup_polygon(p.data(), 3, &s) != SetupStatus::Ok) continue;
        EdgeWalker walker(s, Axis::Rows, ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT});
        Span span;
        int lo = 10, hi = 0, spans = 0;
        while (walker.next(&span)) {
            const SpanLine l = span_line(s, Axis::Rows, span);
            const int32_t shift = fast_adaptive_shift(l.q0, l.q0 + l.qm * (l.count - 1), std::fabs(l.qm), fast_adaptive_room(1));
            if (span.count > 2) lo = std::min(lo, shift), hi = std::max(hi, shift), ++spans;
        }
        if (spans < 10) continue;
        ++polygons;
        varied += lo < hi;
    }
    EXPECT_GT(polygons, 50);
    EXPECT_GT(varied, polygons / 4) << "segments of one length a polygon: the rule does not follow the depth";
}

// fast-oriented-1 draws, asked for rows on a linear target, exactly what fast-adaptive-1 draws along
// the walker fast_oriented_walker picks (the same pixels, spans and bound), and on a planar target
// what fast-adaptive-1 draws by columns; on random triangles and quads from no perspective to a
// depth ratio of 1000, texture 64 x 32 tiled.
TEST(FastOriented, DrawsFastAdaptiveAlongTheWalkerItPicks) {
    const Mapper& oriented = *find_mapper("fast-oriented-1");
    const Mapper& adaptive = *find_mapper("fast-adaptive-1");
    std::vector<uint8_t> texels(64 * 32);
    generate_texture(TextureKind::Xor, 64, 32, texels.data());
    Texture tex{texels.data(), 64, 32, Wrap::Repeat};
    TextureCopies copies(&tex);
    TriangleGen gen(2611u);
    std::vector<uint8_t> a(SCREEN_PIXELS * 4), b(SCREEN_PIXELS * 4);
    int drawn = 0, picked[2] = {0, 0};
    for (int n = 0; n < 600; ++n) {
        gen.depth_ratio = n % 3 == 0 ? 1 : n % 3 == 1 ? 10 : 1000;
        std::vector<Vertex> p = gen.triangle();
        if (n % 2) {  // a quad: the parallelogram on the triangle, 1/w and u/w, v/w planar across it
            const Vertex &v0 = p[0], &v1 = p[1], &v2 = p[2];
            const double q = 1 / v0.w + 1 / v2.w - 1 / v1.w;
            if (q > 0)
                p.push_back(Vertex{Fixed24_8::from_raw(v0.x.raw + v2.x.raw - v1.x.raw), Fixed24_8::from_raw(v0.y.raw + v2.y.raw - v1.y.raw),
                                   1 / q, (v0.u / v0.w + v2.u / v2.w - v1.u / v1.w) / q, (v0.v / v0.w + v2.v / v2.w - v1.v / v1.w) / q});
        }
        const int count = int(p.size());
        for (bool planar : {false, true}) {
            Target ta = ram_target(a.data(), planar), tb = ram_target(b.data(), planar);
            std::fill(a.begin(), a.end(), 0), std::fill(b.begin(), b.end(), 0);
            PolygonSetup s;
            Axis axis = Axis::Columns;
            if (!planar) {
                if (setup_polygon(p.data(), count, &s, PLANES_PERSPECTIVE) != SetupStatus::Ok) break;
                axis = fast_oriented_walker<4>(s, ta.clip);
                ++picked[int(axis)];
            }
            RenderStats sa, sb;
            const SetupStatus status = draw_polygon(p.data(), count, tex, oriented, planar ? Axis::Columns : Axis::Rows, ta, &sa);
            EXPECT_EQ(status, draw_polygon(p.data(), count, tex, adaptive, axis, tb, &sb));
            ASSERT_EQ(a, b) << "polygon " << n << (planar ? " planar" : " linear");
            EXPECT_EQ(sa.spans, sb.spans);
            EXPECT_EQ(sa.pixels, sb.pixels);
            drawn += sa.pixels > 0;
            const ErrorBound ba = oriented.bound(BoundContext{oriented, tex, planar ? Axis::Columns : Axis::Rows, ta.clip}, p.data(), count);
            const ErrorBound bb = adaptive.bound(BoundContext{adaptive, tex, axis, ta.clip}, p.data(), count);
            EXPECT_EQ(ba.draws, bb.draws);
            EXPECT_EQ(ba.footprint, bb.footprint) << "polygon " << n;
        }
        if (HasFailure()) return;
    }
    EXPECT_GT(drawn, 600);
    EXPECT_GT(picked[int(Axis::Rows)], 50);
    EXPECT_GT(picked[int(Axis::Columns)], 50);
}

// A wall (1/w changes across it, not down it) goes by columns, a floor (down it, not across it) by
// rows, whichever walker has the more lines: one segment a line.
TEST(FastOriented, TakesWallsByColumnsAndFloorsByRows) {
    const ClipRect clip{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
    // a wall from w = 1 at x = 20 to w = 10 at x = 300: its edges' y scale with 1/w
    const std::vector<Vertex> wall{vertex(20, 20, 1, 0, 0), vertex(300, 110, 10, 640, 0), vertex(300, 130, 10, 640, 64),
                                   vertex(20, 220, 1, 0, 64)};
    // a floor from w = 10 at y = 125 to w = 1 at y = 235, narrow: fewer columns than rows
    const std::vector<Vertex> floor{vertex(150, 125, 10, 0, 0), vertex(170, 125, 10, 64, 0), vertex(180, 235, 1, 64, 640),
                                    vertex(140, 235, 1, 0, 640)};
    PolygonSetup s;
    ASSERT_EQ(setup_polygon(wall.data(), 4, &s, PLANES_PERSPECTIVE), SetupStatus::Ok);
    EXPECT_EQ(s.q.gy, 0.0);
    EXPECT_EQ(fast_oriented_walker<4>(s, clip), Axis::Columns) << "the wall has fewer rows than columns, but each row needs many segments";
    ASSERT_EQ(setup_polygon(floor.data(), 4, &s, PLANES_PERSPECTIVE), SetupStatus::Ok);
    EXPECT_EQ(s.q.gx, 0.0);
    EXPECT_EQ(fast_oriented_walker<4>(s, clip), Axis::Rows) << "the floor has fewer columns than rows, but each column needs many segments";
}

}  // namespace
