// System tests: every pattern in every page, by screendump and by readback; flips; mode 13h; palettes.
#include <chrono>
#include <thread>

#include "qemu/harness/readback.h"
#include "tests/system/system.h"

namespace {

using namespace systest;

TEST(Video, EveryPatternInEveryPageMatchesTheHostRendering) {
    Session s(options_for_this_test());
    json m = s.ok("mode modex");
    EXPECT_EQ(m["width"], 320);
    EXPECT_EQ(m["height"], 240);
    EXPECT_EQ(m["pages"], 3);
    for (int page = 0; page < 3; ++page) {
        for (int i = 0; i < raster::PATTERN_COUNT; ++i) {
            auto pattern = raster::Pattern(i);
            std::string name = raster::pattern_name(pattern);
            SCOPED_TRACE(name + " in page " + std::to_string(page));
            IndexImage want = render_pattern(pattern, MODE_X);
            s.ok("pattern " + name + " " + std::to_string(page));
            json f = s.ok("flip " + std::to_string(page));
            EXPECT_TRUE(f["retrace"].get<bool>());
            std::string stem = name + "-page" + std::to_string(page);
            IndexImage dump = s.screenshot(stem, MODE_X, default_palette());
            Comparison by_dump = compare(dump, want);
            EXPECT_TRUE(by_dump.equal()) << by_dump.summary() << "\n" << write_mismatch(s.run_dir(), stem, dump, want, default_palette());
            if (i == 0) {  // the encoding's path, once a page; the checksum for every pattern
                Comparison by_readback = compare(s.readback(page), want);
                EXPECT_TRUE(by_readback.equal()) << "readback: " << by_readback.summary();
            }
            EXPECT_EQ(s.readback_crc(page), crc32_of(want)) << "readback crc: " << compare(s.readback(page), want).summary();
        }
    }
}

TEST(Video, FlipShowsTheChosenPageAndPagesAreIndependent) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    s.ok("pattern ramp 0");
    s.ok("pattern grid 1");
    s.ok("flip 0");
    EXPECT_TRUE(compare(s.screenshot("flip0", MODE_X, default_palette()), render_pattern(raster::Pattern::Ramp, MODE_X)).equal());
    s.ok("flip 1");
    IndexImage shown = s.screenshot("flip1", MODE_X, default_palette());
    EXPECT_TRUE(compare(shown, render_pattern(raster::Pattern::Grid, MODE_X)).equal()) << "the flip changed the screendump";
    s.ok("pattern border 2");  // drawing into a hidden page leaves the shown one alone
    EXPECT_TRUE(compare(s.screenshot("hidden-draw", MODE_X, default_palette()), shown).equal());
    EXPECT_TRUE(compare(s.readback(0), render_pattern(raster::Pattern::Ramp, MODE_X)).equal());
    s.ok("clear 1 9");
    IndexImage cleared = s.screenshot("cleared", MODE_X, default_palette());
    EXPECT_EQ(std::count(cleared.index.begin(), cleared.index.end(), 9), 320 * 240);
    s.ok("flip 2");
    EXPECT_TRUE(compare(s.screenshot("flip2", MODE_X, default_palette()), render_pattern(raster::Pattern::Border, MODE_X)).equal());
    EXPECT_EQ(s.ok("hello")["page"], 2);
}

TEST(Video, Mode13hIsLinear320x200WithOnePage) {
    Session s(options_for_this_test());
    json m = s.ok("mode 13h");
    EXPECT_EQ(m["height"], 200);
    EXPECT_EQ(m["pages"], 1);
    s.ok("pattern border 0");
    s.ok("flip 0");
    RgbImage dump = s.screendump("border-13h");
    EXPECT_EQ(dump.width, 640);
    EXPECT_EQ(dump.height, 400);
    EXPECT_FALSE(decode_screendump(dump, default_palette(), MODE_X).ok) << "a 13h screen is not Mode X";
    DecodeResult d = decode_screendump(dump, default_palette(), MODE_13H);
    ASSERT_TRUE(d.ok) << d.error;
    EXPECT_TRUE(compare(d.image, render_pattern(raster::Pattern::Border, MODE_13H)).equal());
    s.ok("pattern ramp 0");
    EXPECT_TRUE(compare(s.readback(0), render_pattern(raster::Pattern::Ramp, MODE_13H)).equal());
    EXPECT_FALSE(s.command("pattern ramp 1")["ok"].get<bool>());
    // and back to Mode X from 13h
    s.ok("mode modex");
    s.ok("pattern planes 1");
    s.ok("flip 1");
    EXPECT_TRUE(compare(s.screenshot("planes-after-13h", MODE_X, default_palette()), render_pattern(raster::Pattern::Planes, MODE_X)).equal());
}

TEST(Video, TheGrayPaletteReachesTheDac) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    s.ok("pattern ramp 0");
    s.ok("flip 0");
    EXPECT_EQ(s.ok("palette gray")["palette"], "gray");
    const raster::Palette& gray = raster::palette(raster::PaletteId::Gray);
    RgbImage dump = s.screendump("gray");
    EXPECT_EQ(dump.rgb, screendump_of(render_pattern(raster::Pattern::Ramp, MODE_X), gray).rgb);
    EXPECT_FALSE(decode_screendump(dump, gray, MODE_X).ok) << "64 grays cannot name 256 indices";
    s.ok("palette default");
    EXPECT_TRUE(compare(s.screenshot("default", MODE_X, default_palette()), render_pattern(raster::Pattern::Ramp, MODE_X)).equal());
    // the palette survives a mode change
    s.ok("palette gray");
    s.ok("mode modex");
    EXPECT_EQ(s.ok("hello")["palette"], "gray");
}

TEST(Video, ABochsVbeModeLeftOnIsSwitchedOffBeforeTheVgaIsProgrammed) {
    Session s(options_for_this_test());
    json v = s.ok("vbe on");  // as a loader that set a VBE mode might leave the adapter
    EXPECT_EQ(v["mode"], "bochs-vbe");
    RgbImage vbe = s.screendump("vbe");
    EXPECT_EQ(vbe.width, 640) << "the VBE mode is on (text mode dumps 720x400)";
    EXPECT_EQ(vbe.height, 480);
    EXPECT_FALSE(s.command("pattern ramp 0")["ok"].get<bool>()) << "no VGA mode of ours is on";
    s.ok("mode modex");
    s.ok("pattern planes 2");
    s.ok("flip 2");
    IndexImage shot = s.screenshot("modex-after-vbe", MODE_X, default_palette());
    EXPECT_TRUE(compare(shot, render_pattern(raster::Pattern::Planes, MODE_X)).equal());
}

// QEMU passes a full socket back to the guest's UART as a transmitter that does not drain. A client
// that stops reading while a page streams (a loaded host deschedules the harness) must lose no byte:
// the kernel's wait for the transmitter must not give up and drop it (docs/platform.md, "Measured in
// QEMU 7.2"). A frame of the corridor packs to ~58 KB (78 KB of base64), more than the socket holds,
// so the kernel is made to wait.
TEST(Video, AClientThatStopsReadingLosesNoByteOfAReadback) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    s.ok("load corridor.scene");
    s.ok("frame 3 exact 0");
    const IndexImage whole = s.readback(0);
    s.send("readback 0\n");
    std::this_thread::sleep_for(std::chrono::seconds(3));
    const json late = s.raw("");
    EXPECT_GT(late.value("packed_bytes", 0), 50000) << "the page must not fit the socket";
    EXPECT_TRUE(compare(decode_readback(late), whole).equal());
    EXPECT_TRUE(s.ok("hello")["ok"].get<bool>());
}

TEST(Video, ATextModeScreenIsNotModeX) {
    Session s(options_for_this_test());
    RgbImage text = s.screendump("text");
    DecodeResult d = decode_screendump(text, default_palette(), MODE_X);
    EXPECT_FALSE(d.ok);
    EXPECT_NE(d.error.find("not the 640x480 of mode modex"), std::string::npos) << d.error;
    EXPECT_FALSE(s.command("readback 0")["ok"].get<bool>()) << "no pages in text mode";
}

}  // namespace
