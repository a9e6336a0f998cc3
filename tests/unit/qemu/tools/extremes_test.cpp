// The extremes report's measures (qemu/tools/extremes.h): every mapper through every class of
// extreme input, a few polygons each (make extremes runs 300), keeps what it promises; our own
// mappers never read outside the texture and its copies, refuse what is beyond the limits and
// cover the reference's pixels at every angle.
#include <gtest/gtest.h>

#include "qemu/tools/extremes.h"
#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace harness;

TEST(Extremes, EveryMapperKeepsItsPromisesOnEveryClass) {
    ExtremesOptions o;
    o.polygons = 8 / rastertest::SANITIZED_SHARE;
    o.rotation_step = 30 * rastertest::SANITIZED_SHARE;
    for (int m = 0; m < raster::MAPPER_COUNT; ++m) {
        const raster::Mapper& mapper = raster::MAPPERS[m];
        uint32_t drawn = 0;
        for (const std::string& cls : extreme_classes()) {
            const ExtremeRow r = run_extreme_class(mapper, cls, o);
            EXPECT_EQ(r.broken_promise(), "") << mapper.name << " on " << cls;
            EXPECT_EQ(r.tried, r.drawn + r.refused_total()) << mapper.name << " on " << cls;
            // the classics' known flaws are reported, not asserted: X-Sharp ignores w (it draws a
            // polygon whose w is beyond its limits) and the classics' fill conventions move their
            // pixels by up to one against the reference's
            if (std::string(mapper.family) == "ours") {
                EXPECT_EQ(r.reads_outside, 0u) << mapper.name << " on " << cls;
                if (cls == "beyond") {
                    EXPECT_EQ(r.drawn, 0u) << mapper.name << ": a value beyond its limit is refused";
                }
                if (cls == "rotation") {
                    EXPECT_GE(r.centroid_shift, 0) << mapper.name;
                    EXPECT_LT(r.centroid_shift, 0.01) << mapper.name << ": exact coverage, whatever the angle";
                }
            }
            drawn += r.drawn;
        }
        EXPECT_GT(drawn, 0u) << mapper.name;
    }
}

// The children: a row per mapper and class, a fault reported as one.
TEST(Extremes, ChildrenReportEachRow) {
    ExtremesOptions o;
    o.polygons = 2;
    o.rotation_step = 90;
    o.mappers = {"exact", "fatmap-lut"};
    o.classes = {"tiny", "rotation"};
    size_t heard = 0;
    const std::vector<ExtremeRow> rows = run_extremes(o, [&](const ExtremeRow&, size_t done, size_t all) {
        ++heard;
        EXPECT_LE(done, all);
    });
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(heard, 4u);
    for (const ExtremeRow& r : rows) {
        EXPECT_EQ(r.fault, "") << r.mapper << " " << r.cls;
        EXPECT_FALSE(r.hang);
        EXPECT_GT(r.tried, 0u) << r.mapper << " " << r.cls;
    }
}

}  // namespace
