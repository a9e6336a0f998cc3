// The font and the text routine (kernel/scene/text.h): the same pixels into every kind of target.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "kernel/core/random.h"
#include "kernel/scene/text.h"

namespace {

TEST(Text, EveryPrintableCharacterHasItsOwnGlyphInsideItsCell) {
    std::set<std::vector<uint8_t>> seen;
    for (int c = 32; c < 127; ++c) {
        const uint8_t* g = raster::glyph(char(c));
        std::vector<uint8_t> rows(g, g + raster::GLYPH_SIZE);
        EXPECT_TRUE(seen.insert(rows).second) << "'" << char(c) << "' looks like another character";
        for (uint8_t r : rows) EXPECT_EQ(r & 0x83, 0) << "'" << char(c) << "': a column of space left and two right";
        int lit = 0;
        for (uint8_t r : rows) lit += __builtin_popcount(r);
        EXPECT_EQ(lit == 0, c == ' ') << "'" << char(c) << "'";
    }
    EXPECT_EQ(raster::glyph('\n'), raster::glyph('?'));
    EXPECT_EQ(raster::glyph(char(200)), raster::glyph('?'));
}

TEST(Text, ColoursAreThePalettesLightestAndDarkest) {
    raster::Palette p{};
    for (int i = 0; i < 256; ++i) p.entry[i] = raster::Rgb6{20, 20, 20};
    p.entry[7] = raster::Rgb6{63, 63, 63};
    p.entry[9] = raster::Rgb6{0, 0, 1};
    p.entry[10] = raster::Rgb6{0, 0, 1};
    raster::TextColours c = raster::text_colours(p);
    EXPECT_EQ(c.ink, 7);
    EXPECT_EQ(c.paper, 9) << "ties to the lower index";
}

// Text drawn into a linear surface and into a planar one (plane by plane) gives the same picture,
// clipped alike, and nothing outside the clip changes.
TEST(Text, PlanarAndLinearTargetsGetTheSamePixels) {
    raster::Random r(7);
    for (int round = 0; round < 200; ++round) {
        std::vector<uint8_t> linear(raster::SCREEN_PIXELS, 3), planes(raster::SCREEN_PIXELS, 3), expected(raster::SCREEN_PIXELS);
        raster::Target a = raster::linear_target(linear.data(), raster::SCREEN_WIDTH, raster::SCREEN_HEIGHT, raster::SCREEN_WIDTH);
        raster::Target b = raster::planar_target(planes.data());
        const raster::ClipRect clip{r.range(0, 100), r.range(0, 100), r.range(150, 320), r.range(150, 240)};
        a.clip = b.clip = clip;
        std::string s[3];
        for (std::string& line : s)
            for (int n = r.range(0, 30); n > 0; --n) line += char(r.range(20, 130));
        lib::StrView lines[3] = {{s[0].data(), s[0].size()}, {s[1].data(), s[1].size()}, {s[2].data(), s[2].size()}};
        const int32_t x = r.range(-40, 330), y = r.range(-30, 250);
        const raster::TextColours c{uint8_t(r.range(0, 255)), uint8_t(r.range(0, 255))};
        if (round % 2) {
            raster::draw_text(a, x, y, lines[0], c);
            raster::draw_text(b, x, y, lines[0], c);
        } else {
            EXPECT_EQ(raster::draw_text_box(a, x, y, lines, 3, c), 3 * raster::GLYPH_SIZE + 2);
            raster::draw_text_box(b, x, y, lines, 3, c);
        }
        raster::planar_from_linear(linear.data(), expected.data());
        ASSERT_EQ(planes, expected) << "round " << round;
        for (int32_t py = 0; py < raster::SCREEN_HEIGHT; ++py)
            for (int32_t px = 0; px < raster::SCREEN_WIDTH; ++px) {
                if (px < clip.x0 || px >= clip.x1 || py < clip.y0 || py >= clip.y1) {
                    ASSERT_EQ(linear[py * raster::SCREEN_WIDTH + px], 3) << px << "," << py << " outside the clip";
                }
            }
    }
}

TEST(Text, AGlyphLandsWhereItsArtSays) {
    std::vector<uint8_t> px(raster::SCREEN_PIXELS, 0);
    raster::Target t = raster::linear_target(px.data(), raster::SCREEN_WIDTH, raster::SCREEN_HEIGHT, raster::SCREEN_WIDTH);
    raster::draw_text(t, 10, 20, lib::StrView{"T", 1}, raster::TextColours{9, 1});
    // T: its top row five wide from the cell's second column, then its stem in the middle
    for (int x = 10; x < 18; ++x) EXPECT_EQ(px[20 * 320 + x], x >= 11 && x <= 15 ? 9 : 1) << x;
    for (int y = 21; y < 27; ++y) EXPECT_EQ(px[y * 320 + 13], 9) << y;
    EXPECT_EQ(px[27 * 320 + 13], 1) << "the cell's last row is paper";
    EXPECT_EQ(px[19 * 320 + 13], 0) << "nothing above the cell";
}

}  // namespace
