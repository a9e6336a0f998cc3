// Under test: qemu/lib/host_image.h.
// Host image handling: PNG/PPM decoding, the 2x2 and palette mapping of screendumps, comparisons.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "qemu/lib/error.h"
#include "qemu/lib/host_image.h"
#include "qemu/harness/session.h"

namespace {

using namespace harness;

const raster::Palette& default_palette() { return raster::palette(raster::PaletteId::Default); }

std::string temp_dir() {
    std::string d = build_dir() + "/test-tmp/image";
    std::filesystem::create_directories(d);
    return d;
}

void set_pixel(RgbImage& img, int x, int y, uint8_t r, uint8_t g, uint8_t b) {
    uint8_t* p = &img.rgb[3 * (size_t(y) * size_t(img.width) + size_t(x))];
    p[0] = r, p[1] = g, p[2] = b;
}

TEST(Png, RoundTrips) {
    RgbImage img = screendump_of(render_pattern(raster::Pattern::Ramp, MODE_X), default_palette());
    std::string path = temp_dir() + "/roundtrip.png";
    save_png(path, img);
    RgbImage back = load_image(path);
    EXPECT_EQ(back.width, 640);
    EXPECT_EQ(back.height, 480);
    EXPECT_EQ(back.rgb, img.rgb);
}

TEST(Png, RejectsGarbage) {
    EXPECT_THROW(decode_png("\x89PNG\r\n\x1a\n but not really"), HarnessError);
    std::string path = temp_dir() + "/not-an-image.png";
    std::ofstream(path) << "hello";
    EXPECT_THROW(load_image(path), HarnessError);
    EXPECT_THROW(load_image(temp_dir() + "/missing.png"), HarnessError);
}

TEST(Ppm, ParsesP6WithComments) {
    std::string bytes = "P6\n# made by a test\n2 1\n# another\n255\n";
    bytes += std::string("\x01\x02\x03\xfd\xfe\xff", 6);
    RgbImage img = decode_ppm(bytes);
    EXPECT_EQ(img.width, 2);
    EXPECT_EQ(img.height, 1);
    EXPECT_EQ(img.rgb, (std::vector<uint8_t>{1, 2, 3, 253, 254, 255}));
}

TEST(Ppm, RejectsBadFiles) {
    EXPECT_THROW(decode_ppm("P3\n1 1\n255\n0 0 0\n"), HarnessError);          // ASCII PPM
    EXPECT_THROW(decode_ppm("P6\n2 2\n255\n\x01\x02"), HarnessError);         // truncated
    EXPECT_THROW(decode_ppm("P6\n1 1\n65535\n\x01\x02\x03\x04\x05\x06"), HarnessError);
    EXPECT_THROW(decode_ppm("P6\n0 1\n255\n"), HarnessError);
    EXPECT_THROW(decode_ppm("P6\nx 1\n255\n"), HarnessError);
}

TEST(Screendump, DecodesEveryPatternBackToIndices) {
    for (int i = 0; i < raster::PATTERN_COUNT; ++i) {
        IndexImage want = render_pattern(raster::Pattern(i), MODE_X);
        DecodeResult d = decode_screendump(screendump_of(want, default_palette()), default_palette(), MODE_X);
        ASSERT_TRUE(d.ok) << d.error;
        EXPECT_TRUE(compare(d.image, want).equal()) << raster::pattern_name(raster::Pattern(i));
    }
}

TEST(Screendump, ANonUniformBlockIsRejected) {
    RgbImage dump = screendump_of(render_pattern(raster::Pattern::Grid, MODE_X), default_palette());
    set_pixel(dump, 2 * 37 + 1, 2 * 21 + 1, 255, 255, 255);  // one sub-pixel of pixel (37, 21)
    DecodeResult d = decode_screendump(dump, default_palette(), MODE_X);
    EXPECT_FALSE(d.ok);
    EXPECT_NE(d.error.find("(37,21) is not uniform"), std::string::npos) << d.error;
}

TEST(Screendump, AColourOutsideThePaletteIsRejected) {
    RgbImage dump = screendump_of(render_pattern(raster::Pattern::Ramp, MODE_X), default_palette());
    for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) set_pixel(dump, 2 * 5 + dx, 2 * 9 + dy, 1, 2, 3);
    DecodeResult d = decode_screendump(dump, default_palette(), MODE_X);
    EXPECT_FALSE(d.ok);
    EXPECT_NE(d.error.find("(1,2,3) at pixel (5,9) is in no palette entry"), std::string::npos) << d.error;
}

TEST(Screendump, AnAmbiguousPaletteIsRejected) {
    const raster::Palette& gray = raster::palette(raster::PaletteId::Gray);
    RgbImage dump = screendump_of(render_pattern(raster::Pattern::Ramp, MODE_X), gray);
    DecodeResult d = decode_screendump(dump, gray, MODE_X);
    EXPECT_FALSE(d.ok);
    EXPECT_NE(d.error.find("matches 4 palette entries"), std::string::npos) << d.error;
}

TEST(Screendump, OtherModesAreNotModeX) {
    RgbImage text{720, 400, std::vector<uint8_t>(720 * 400 * 3)};
    DecodeResult d = decode_screendump(text, default_palette(), MODE_X);
    EXPECT_FALSE(d.ok);
    EXPECT_NE(d.error.find("720x400, not the 640x480 of mode modex"), std::string::npos) << d.error;

    RgbImage m13 = screendump_of(render_pattern(raster::Pattern::Ramp, MODE_13H), default_palette());
    EXPECT_FALSE(decode_screendump(m13, default_palette(), MODE_X).ok);
    EXPECT_TRUE(decode_screendump(m13, default_palette(), MODE_13H).ok);
}

TEST(Compare, CountsAndLocatesDifferences) {
    IndexImage want = render_pattern(raster::Pattern::Border, MODE_X);
    IndexImage got = want;
    got.index[3 * 320 + 10] ^= 1;
    got.index[239 * 320 + 319] = 200;
    Comparison c = compare(got, want);
    EXPECT_FALSE(c.equal());
    EXPECT_EQ(c.differing, 2u);
    EXPECT_EQ(c.total, 76800u);
    ASSERT_EQ(c.first.size(), 2u);
    EXPECT_EQ(c.first[0].x, 10);
    EXPECT_EQ(c.first[0].y, 3);
    EXPECT_EQ(c.first[1].actual, 200);
    EXPECT_EQ(c.first[1].expected, raster::BORDER_FRAME);
    EXPECT_NE(c.summary().find("2 of 76800 pixels differ; first at (10,3)"), std::string::npos) << c.summary();

    std::string dir = temp_dir();
    std::string note = write_mismatch(dir, "cmp", got, want, default_palette());
    for (const char* f : {"/cmp-actual.png", "/cmp-expected.png", "/cmp-diff.png"}) EXPECT_TRUE(std::filesystem::exists(dir + f)) << f;
    RgbImage diff = load_image(dir + "/cmp-diff.png");
    EXPECT_EQ(diff.at(10, 3)[0], 255);
    EXPECT_EQ(diff.at(10, 3)[1], 0);
    EXPECT_NE(note.find("cmp-"), std::string::npos);
}

TEST(Compare, SizeMismatchIsNeverEqual) {
    Comparison c = compare(render_pattern(raster::Pattern::Ramp, MODE_13H), render_pattern(raster::Pattern::Ramp, MODE_X));
    EXPECT_FALSE(c.equal());
    EXPECT_TRUE(c.size_mismatch);
}

}  // namespace
