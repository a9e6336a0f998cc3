// persp-adaptive-B: its runs follow from the bound and the budget. Every run whose chord bound is
// not within the budget is a single pixel (the chooser could not do better there); a span of
// constant depth is one run; a looser budget never takes more runs; under strong perspective the
// runs differ in length along a span (long where 1/w barely changes). The drawn error against its
// bound is in bound_test.cpp (every mapper of the registry).
#include <gtest/gtest.h>

#include "kernel/core/bound.h"
#include "kernel/mappers/subdiv.h"
#include "tests/unit/raster_helpers.h"

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

}  // namespace
