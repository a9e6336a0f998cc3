// The cost model's fit (qemu/tools/cost_model.h): each target's rows from its own columns, the
// cycles an instruction of auto's choosing, and a target the run did not measure kept as it was.
#include "qemu/tools/cost_model.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kernel/core/mapper.h"

namespace {

using harness::FittedModel;
using raster::CostTarget;

const std::vector<std::string> HEADER = {"mapper",
                                         "polygons[count]",
                                         "spans[count]",
                                         "pixels[count]",
                                         "ticks_setup[instructions]",
                                         "ticks_walk[instructions]",
                                         "ticks_inner[instructions]",
                                         "ticks_choose[instructions]",
                                         "cycles_pentium_setup[cycles]",
                                         "cycles_pentium_walk[cycles]",
                                         "cycles_pentium_inner[cycles]",
                                         "cycles_pentium_choose[cycles]"};

// A row drawn by a mapper costing (polygon, span, pixel) on icount and (3x, 2x, 0.5x) on the
// Pentium; auto's choosing: `choose` instructions, 4 cycles each.
std::vector<std::string> row(const std::string& mapper, double polygons, double spans, double pixels, double polygon, double span,
                             double pixel, double choose, bool on_pentium) {
    auto n = [](double v) { return std::to_string(int64_t(v)); };
    return {mapper,
            n(polygons),
            n(spans),
            n(pixels),
            n(polygons * polygon),
            n(spans * span),
            n(pixels * pixel),
            n(choose),
            on_pentium ? n(3 * polygons * polygon) : "",
            on_pentium ? n(2 * spans * span) : "",
            on_pentium ? n(0.5 * pixels * pixel) : "",
            on_pentium && choose ? n(4 * choose) : ""};  // (the bench writes a cycle column's 0 as nothing)
}

TEST(CostModel, EachTargetIsFittedFromItsOwnColumns) {
    // fast-affine: 1000 a polygon, 100 a span, 5 a pixel, on three scenes of different shapes;
    // auto's row adds the choosing
    const std::vector<std::vector<std::string>> csv = {HEADER,
                                                        row("fast-affine", 100, 2000, 40000, 1000, 100, 5, 0, true),
                                                        row("fast-affine", 50, 3000, 90000, 1000, 100, 5, 0, true),
                                                        row("fast-affine", 10, 500, 50000, 1000, 100, 5, 0, true),
                                                        row("exact", 100, 2000, 40000, 1010, 300, 60, 0, false),
                                                        row("exact", 50, 3000, 90000, 1010, 300, 60, 0, false),
                                                        row("auto", 100, 2000, 40000, 1500, 200, 20, 70000, true)};
    const FittedModel icount = harness::fit_costs(csv, CostTarget::Icount);
    ASSERT_EQ(icount.rows.count("fast-affine"), 1u);
    EXPECT_NEAR(icount.rows.at("fast-affine").polygon, 1000, 1e-6);
    EXPECT_NEAR(icount.rows.at("fast-affine").span, 100, 1e-6);
    EXPECT_NEAR(icount.rows.at("fast-affine").pixel, 5, 1e-6);
    EXPECT_NEAR(icount.rows.at("exact").pixel, 60, 1e-6);
    EXPECT_EQ(icount.proof_scale, 1);

    const FittedModel pentium = harness::fit_costs(csv, CostTarget::Pentium);
    EXPECT_EQ(pentium.rows.count("exact"), 0u) << "not run on the Pentium";
    ASSERT_EQ(pentium.rows.count("fast-affine"), 1u);
    EXPECT_NEAR(pentium.rows.at("fast-affine").polygon, 3000, 1e-6);
    EXPECT_NEAR(pentium.rows.at("fast-affine").span, 200, 1e-6);
    EXPECT_NEAR(pentium.rows.at("fast-affine").pixel, 2.5, 1e-6);
    EXPECT_NEAR(pentium.proof_scale, 4, 1e-9) << "auto's choosing: 4 cycles an instruction";

    EXPECT_TRUE(harness::fit_costs(csv, CostTarget::I486).rows.empty()) << "no 486 columns: not measured";

    // the source: the Pentium's table holds its fit; the 486's, not measured, the model built in
    FittedModel models[int(CostTarget::Count)] = {icount, harness::fit_costs(csv, CostTarget::I486), pentium};
    const std::string source = harness::cost_model_source(models, "a test");
    const size_t p = source.find("const MapperCost MAPPER_COSTS_PENTIUM[] = {"), i = source.find("const MapperCost MAPPER_COSTS_486[] = {");
    ASSERT_NE(p, std::string::npos) << source;
    ASSERT_NE(i, std::string::npos) << source;
    EXPECT_NE(source.find("{\"fast-affine\", 3000.0f, 200.00f, 2.500f}, // 3 scenes", p), std::string::npos) << source;
    EXPECT_NE(source.find("{\"exact\", -1.0f, -1.00f, -1.000f},", p), std::string::npos) << source;
    EXPECT_NE(source.find("{\"pentium\", MAPPER_COSTS_PENTIUM, 4.000}"), std::string::npos) << source;
    const raster::CostModel& built_in = raster::cost_model(CostTarget::I486);
    char kept[160];
    std::snprintf(kept, sizeof kept, "{\"%s\", %.1ff, %.2ff, %.3ff},", built_in.rows[0].mapper, double(built_in.rows[0].polygon),
                  double(built_in.rows[0].span), double(built_in.rows[0].pixel));
    EXPECT_NE(source.find(std::string("// (not measured by this run: as the cost model before it)\nconst MapperCost MAPPER_COSTS_486[] = {\n    ") + kept),
              std::string::npos)
        << source;
    std::snprintf(kept, sizeof kept, "{\"486\", MAPPER_COSTS_486, %.3f}", built_in.proof_scale);
    EXPECT_NE(source.find(kept), std::string::npos) << source;
}

}  // namespace
