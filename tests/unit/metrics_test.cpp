// The comparator on hand-made pictures: each metric counts what it says.
#include <gtest/gtest.h>

#include "tests/unit/raster_helpers.h"

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

}  // namespace
