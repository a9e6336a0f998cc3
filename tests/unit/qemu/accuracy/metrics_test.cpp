// Under test: qemu/accuracy/metrics.h.
// The comparator on hand-made pictures: each metric counts what it says.
#include <gtest/gtest.h>

#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

TEST(Metrics, CountsCoverageAndTexelErrors) {
    Picture ref(4, 2), drawn(4, 2);
    // pixel:       0        1        2        3        4        5        6        7
    // reference:   (5,5)    (0,0)    (63,1)   -        (2,2)    (9,9)    -        (1,1)
    // drawn:       (5,5)    (63,0)   (1,1)    (7,7)    -        (9,12)x2 -        (1,1)
    auto set = [](Picture& p, int i, int u, int v, uint8_t idx, uint8_t cov) {
        p.tu[size_t(i)] = u, p.tv[size_t(i)] = v, p.index[size_t(i)] = idx, p.coverage[size_t(i)] = cov;
    };
    set(ref, 0, 5, 5, 10, 1);
    set(ref, 1, 0, 0, 11, 1);
    set(ref, 2, 63, 1, 12, 1);
    set(ref, 4, 2, 2, 14, 1);
    set(ref, 5, 9, 9, 15, 1);
    set(ref, 7, 1, 1, 17, 1);
    set(drawn, 0, 5, 5, 10, 1);
    set(drawn, 1, 63, 0, 99, 1);  // one texel off across the wrap
    set(drawn, 2, 1, 1, 12, 1);   // two texels off across the wrap (same index by chance)
    set(drawn, 3, 7, 7, 13, 1);   // overdraw
    set(drawn, 5, 9, 12, 15, 2);  // three off, drawn twice
    set(drawn, 7, 1, 1, 17, 1);
    AccuracyMetrics m = compare_to_reference(ref.view, drawn.view, 64, 64, Wrap::Repeat);
    EXPECT_EQ(m.reference_pixels, 6u);
    EXPECT_EQ(m.drawn_pixels, 6u);
    EXPECT_EQ(m.overdraw, 1u);
    EXPECT_EQ(m.gaps, 1u);
    EXPECT_EQ(m.overlaps, 1u);
    EXPECT_EQ(m.compared, 5u);
    EXPECT_EQ(m.max_texel_error, 3u);
    EXPECT_DOUBLE_EQ(m.mean_texel_error, (0 + 1 + 2 + 3 + 0) / 5.0);
    EXPECT_EQ(m.exact, 2u);
    EXPECT_EQ(m.within_one, 3u);
    EXPECT_EQ(m.union_pixels, 7u);
    EXPECT_EQ(m.index_differs, 3u);  // pixel 1 (99 vs 11), 3 (13 vs background), 4 (background vs 14)

    AccuracyMetrics clamp = compare_to_reference(ref.view, drawn.view, 64, 64, Wrap::Clamp);
    EXPECT_EQ(clamp.max_texel_error, 63u) << "without wrap, 0 and 63 are 63 texels apart";
}

// The footprint error: the texel error over max(1, the reference's footprint), folded errors counted.
TEST(Metrics, FootprintErrorDividesByTheFootprintAtLeastOne) {
    Picture ref(4, 1), drawn(4, 1);
    auto set = [](Picture& p, int i, int u, float footprint) {
        p.tu[size_t(i)] = u, p.tv[size_t(i)] = 0, p.coverage[size_t(i)] = 1, p.footprint[size_t(i)] = footprint;
    };
    set(ref, 0, 10, 4.0f);   // 8 texels off where a pixel spans 4: 2 pixels on screen
    set(ref, 1, 10, 0.5f);   // 3 texels off, magnified: 3 (texels)
    set(ref, 2, 10, 10.0f);  // exact
    set(ref, 3, 0, 16.0f);   // 32 off in a 64-texel period: half a period, folded; 2
    set(drawn, 0, 18, 0), set(drawn, 1, 13, 0), set(drawn, 2, 10, 0), set(drawn, 3, 32, 0);
    AccuracyMetrics m = compare_to_reference(ref.view, drawn.view, 64, 64, Wrap::Repeat);
    EXPECT_EQ(m.max_texel_error, 32u);
    EXPECT_DOUBLE_EQ(m.max_footprint_error, 3.0);
    EXPECT_DOUBLE_EQ(m.mean_footprint_error, (2.0 + 3.0 + 0.0 + 2.0) / 4);
    EXPECT_EQ(m.folded, 1u);
    AccuracyMetrics clamp = compare_to_reference(ref.view, drawn.view, 64, 64, Wrap::Clamp);
    EXPECT_EQ(clamp.folded, 0u) << "clamped coordinates do not fold";
}

// The 99.9th percentile is the nearest rank: of 1000 compared pixels, the 999th smallest error, so
// one outlier alone does not move it and two do.
TEST(Metrics, The999thPercentileIsTheNearestRank) {
    for (int outliers : {1, 2}) {
        Picture ref(1000, 1), drawn(1000, 1);
        for (size_t i = 0; i < 1000; ++i) {
            ref.tu[i] = ref.tv[i] = drawn.tv[i] = 0, ref.coverage[i] = drawn.coverage[i] = 1, ref.footprint[i] = 2.0f;
            drawn.tu[i] = i < 3 ? 5 : 0;  // three pixels 5 texels off
        }
        for (int k = 0; k < outliers; ++k) drawn.tu[size_t(999 - k)] = 40;
        AccuracyMetrics m = compare_to_reference(ref.view, drawn.view, 256, 256, Wrap::Repeat);
        EXPECT_EQ(m.max_texel_error, 40u);
        EXPECT_EQ(m.p999_texel_error, outliers == 1 ? 5u : 40u);
        EXPECT_DOUBLE_EQ(m.p999_footprint_error, outliers == 1 ? 2.5 : 20.0);
    }
}

// Accumulating frames joins their samples: the percentile is over every pixel of every frame.
TEST(Metrics, AccumulateJoinsTheSamples) {
    AccuracyMetrics a, b, total;
    for (int i = 0; i < 600; ++i) add_texel_error(a, 0, 1.0, false);
    for (int i = 0; i < 400; ++i) add_texel_error(b, i < 2 ? 6u : 0u, 3.0, false);
    finish_metrics(a), finish_metrics(b);
    accumulate(total, a);
    accumulate(total, b);
    EXPECT_EQ(total.compared, 1000u);
    EXPECT_EQ(total.p999_texel_error, 6u);
    EXPECT_DOUBLE_EQ(total.max_footprint_error, 2.0);
    EXPECT_DOUBLE_EQ(total.mean_texel_error, 12.0 / 1000);
}

}  // namespace
