// Under test: kernel/scene/palette.h, pattern.h.
// Palettes and patterns shared by kernel and host.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "kernel/scene/palette.h"
#include "kernel/scene/pattern.h"
#include "qemu/lib/host_image.h"

namespace {

TEST(Palette, DefaultIsUniqueAfterQemusWidening) {
    const raster::Palette& p = raster::palette(raster::PaletteId::Default);
    std::set<std::tuple<int, int, int>> seen;
    for (const auto& c : p.entry) {
        ASSERT_LE(std::max({c.r, c.g, c.b}), 63);
        seen.insert({harness::qemu_widen(c.r), harness::qemu_widen(c.g), harness::qemu_widen(c.b)});
    }
    EXPECT_EQ(seen.size(), 256u);
    EXPECT_EQ(p.entry[0].r + p.entry[0].g + p.entry[0].b, 0) << "0 is black";
    EXPECT_EQ(p.entry[15].r, 63);
    EXPECT_EQ(p.entry[15].g, 63);
    EXPECT_EQ(p.entry[15].b, 63);
}

TEST(Palette, GrayHasSixtyFourLevels) {
    const raster::Palette& p = raster::palette(raster::PaletteId::Gray);
    for (int i = 0; i < 256; ++i) {
        EXPECT_EQ(p.entry[i].r, i >> 2);
        EXPECT_EQ(p.entry[i].g, i >> 2);
        EXPECT_EQ(p.entry[i].b, i >> 2);
    }
}

TEST(Palette, Names) {
    raster::PaletteId id;
    EXPECT_TRUE(raster::palette_from_name({"gray", 4}, &id));
    EXPECT_EQ(id, raster::PaletteId::Gray);
    EXPECT_STREQ(raster::palette_name(id), "gray");
    EXPECT_FALSE(raster::palette_from_name({"grey", 4}, &id));
}

TEST(Widen, MatchesQemusC6To8) {
    EXPECT_EQ(harness::qemu_widen(0), 0);
    EXPECT_EQ(harness::qemu_widen(1), 7);
    EXPECT_EQ(harness::qemu_widen(2), 8);
    EXPECT_EQ(harness::qemu_widen(42), 168);
    EXPECT_EQ(harness::qemu_widen(63), 255);
}

TEST(Pattern, Definitions) {
    using raster::Pattern;
    using raster::pattern_pixel;
    EXPECT_EQ(pattern_pixel(Pattern::Ramp, 300, 200, 320, 240), uint8_t(500));
    EXPECT_EQ(pattern_pixel(Pattern::Planes, 7, 3, 320, 240), 3);
    EXPECT_EQ(pattern_pixel(Pattern::Grid, 16, 5, 320, 240), raster::GRID_LINE);
    EXPECT_EQ(pattern_pixel(Pattern::Grid, 5, 32, 320, 240), raster::GRID_LINE);
    EXPECT_EQ(pattern_pixel(Pattern::Grid, 5, 33, 320, 240), raster::GRID_FIELD);
    EXPECT_EQ(pattern_pixel(Pattern::Border, 319, 100, 320, 240), raster::BORDER_FRAME);
    EXPECT_EQ(pattern_pixel(Pattern::Border, 318, 238, 320, 240), raster::BORDER_FIELD);
    EXPECT_EQ(pattern_pixel(Pattern::Border, 100, 199, 320, 200), raster::BORDER_FRAME);
    raster::Pattern p;
    for (int i = 0; i < raster::PATTERN_COUNT; ++i) {
        const char* name = raster::pattern_name(Pattern(i));
        ASSERT_TRUE(raster::pattern_from_name({name, strlen(name)}, &p));
        EXPECT_EQ(p, Pattern(i));
    }
    EXPECT_FALSE(raster::pattern_from_name({"ramps", 5}, &p));
}

}  // namespace
