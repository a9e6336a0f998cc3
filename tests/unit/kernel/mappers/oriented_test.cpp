// Under test: kernel/mappers/auto/choice.h (the oriented candidate and path), draw.cpp.
// auto's oriented path is planned and gated as choose_mapper's oriented candidate would be, and a
// polygon at one depth is left to the mappers that step affinely.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kernel/mappers/auto/choice.h"
#include "kernel/mappers/fastsubdiv.h"
#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

const Budget BUDGETS[] = {{true, 0, true}, {true, 0.5, true}, {true, 1, true}, {true, 2, true}, {true, 4, true}, {true, ANY_ERROR, false}};

// auto's oriented path is planned from a budget of 1 on, on a repeating texture whose texels the
// guard's object check takes, with fast-oriented-1 (from 2: fast-adaptive-2) and fast-constant-
// depth; and its test from the corners (oriented_gate_may_hold) never refuses a polygon whose
// pick's estimate, from its setup, is within the gate (random triangles, some the clip cuts, both
// picks and walkers).
TEST(Auto, TheOrientedPathIsPlannedAndGatedAsTheChoiceWouldBe) {
    Texture256 blank;
    Texture& tex = blank.tex;
    Texture clamped = tex;
    clamped.wrap = Wrap::Clamp;
    Target target = screen_target(Surface::Linear);
    TriangleGen gen(1130u);
    int gated = 0, cut = 0;
    for (const Budget& b : BUDGETS) {
        const OrientedPlan plan = plan_oriented(b, tex, target, 4096);
        const bool wanted = b.max_error >= 1;
        EXPECT_EQ(plan.oriented != nullptr, wanted) << b.max_error;
        EXPECT_EQ(plan_oriented(b, tex, target, NO_BOUND).oriented, nullptr);
        EXPECT_EQ(plan_oriented(b, clamped, target, 4096).oriented, nullptr);
        if (!wanted) continue;
        EXPECT_EQ(plan.oriented->auto_role, b.max_error < 2 ? AutoRole::Oriented : AutoRole::Adaptive2) << "choose_mapper's oriented candidate";
        ASSERT_NE(plan.constant, nullptr);
        EXPECT_EQ(plan.constant->auto_role, AutoRole::ConstantDepth);
        for (int n = 0; n < 3000; ++n) {
            std::vector<Vertex> p = gen.triangle();
            PolygonSetup s;
            if (setup_polygon(p.data(), int(p.size()), &s, PLANES_PERSPECTIVE) != SetupStatus::Ok) continue;
            cut += !box_in_clip(s, target.clip);
            PolygonSize size[2];
            polygon_sizes(s, target.clip, size);
            const double rows = size[int(Axis::Rows)].spans, columns = size[int(Axis::Columns)].spans;
            const double least = estimate_cost(plan.least, PolygonSize{(plan.least.span < 0) == (rows < columns) ? columns : rows, size[0].pixels});
            for (Axis axis : {Axis::Rows, Axis::Columns})
                for (const CostRow* pick : {&plan.oriented_row, &plan.constant_row}) {
                    if (!(estimate_cost(*pick, size[int(axis)]) <= least + plan.gate)) continue;
                    ++gated;
                    EXPECT_TRUE(oriented_gate_may_hold(plan, corner_box(p.data(), int(p.size())), target.clip, p.data(), int(p.size()))) << "polygon " << n;
                }
            if (HasFailure()) return;
        }
    }
    EXPECT_GT(gated, 1000);
    EXPECT_GT(cut, 100) << "polygons the clip cuts among them";
}

// A quad at one depth (its corners' w the same: Q constant, the affine planes its mapping) larger
// than the oriented candidate's gate: from a budget of 1 the choice is a mapper that steps it
// affinely, the oriented candidate never asked; at another depth at one corner it is not.
TEST(Auto, APolygonAtOneDepthIsLeftToTheAffineSteppingMappers) {
    Texture256 blank;
    Texture& tex = blank.tex;
    Target target = screen_target(Surface::Planar);
    for (double far : {2.0, 8.0})
        for (const Budget& b : BUDGETS) {
            if (b.max_error < 1) continue;
            const std::vector<Vertex> quad = {vertex(-40, -30, 2, 0, 0), vertex(360, -20, 2, 900, 0), vertex(350, 270, far, 900, 700), vertex(-30, 260, 2, 0, 700)};
            PreparedPolygon prepared;
            const Choice c = choose_mapper(b, quad.data(), 4, tex, target, &prepared);
            ASSERT_NE(c.mapper, nullptr);
            const bool affine = c.mapper->span_planes == PLANES_AFFINE || c.mapper->enveloped || std::string(c.mapper->name).rfind("fast-table", 0) == 0;
            EXPECT_EQ(affine, far == 2.0) << c.mapper->name << " at " << b.max_error << (far == 2.0 ? ", one depth" : ", a far corner");
        }
}

}  // namespace
