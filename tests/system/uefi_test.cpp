// A UEFI-only PC, 64-bit and 32-bit firmware: the ISO booted by OVMF through GRUB EFI, which hands the
// kernel the firmware's framebuffer (the Multiboot header's video fields); the kernel keeps its Mode
// X pages in RAM and draws each flip into the framebuffer, scaled and centred. Every screen equals
// the host's picture scaled the same way, colour for colour, the show's HUD and keys included; the
// pages read back as on a VGA.
#include "tests/system/system.h"

#include "kernel/core/surface.h"
#include "qemu/accuracy/measure.h"

namespace {

using namespace systest;

// The picture as the kernel draws it into a framebuffer of the screendump's size.
RgbImage scaled(const IndexImage& picture, const raster::Palette& palette, int width, int height) {
    RgbImage out;
    out.width = width, out.height = height;
    out.rgb.assign(size_t(width) * height * 3, 0);
    const raster::ScaledPlacement at = raster::scaled_placement(uint32_t(width), uint32_t(height), uint32_t(picture.width), uint32_t(picture.height));
    for (int y = 0; y < picture.height * int(at.scale); ++y)
        for (int x = 0; x < picture.width * int(at.scale); ++x) {
            const raster::Rgb6& c = palette.entry[picture.at(x / int(at.scale), y / int(at.scale))];
            uint8_t* p = &out.rgb[3 * (size_t(at.y + uint32_t(y)) * size_t(width) + at.x + uint32_t(x))];
            p[0] = raster::widen6(c.r), p[1] = raster::widen6(c.g), p[2] = raster::widen6(c.b);
        }
    return out;
}

// The screen after a flip: the picture scaled into a framebuffer of the screendump's size (the
// framebuffer's own: the boot line's width and height).
void expect_screen(Session& s, const IndexImage& want, const raster::Palette& palette, const std::string& stem) {
    const json& fb = s.boot_line()["framebuffer"];
    expect_screendump_rgb(s, scaled(want, palette, fb["width"], fb["height"]), stem);
}

class Uefi : public testing::TestWithParam<Firmware> {};

TEST_P(Uefi, TheIsoBootsByOvmfAndDrawsIntoTheFramebuffer) {
    SessionOptions o = options_for_this_test();
    o.firmware = GetParam();
    o.medium = BootMedium::Cdrom;
    o.boot_timeout = std::chrono::seconds(120);
    Session s(o);
    const json& b = s.boot_line();
    ASSERT_TRUE(b["framebuffer"].is_object()) << "GRUB EFI hands over the firmware's framebuffer: " << b.dump();
    EXPECT_EQ(b["framebuffer"]["bpp"], 32);
    EXPECT_GE(b["framebuffer"]["width"].get<int>(), 320);
    EXPECT_FALSE(b["bochs_vbe_cleared"].get<bool>()) << "the VGA (and the VBE behind the framebuffer) left alone";
    EXPECT_GT(b["modules"].get<int>(), 0);
    EXPECT_TRUE(b["keyboard"]["irq"].get<bool>()) << "QEMU's PC has its 8042 under OVMF too";
    // the show with its HUD, driven by the keyboard: Space pauses, the screen is the host's frame
    // and HUD, scaled
    s.send_key("spc");
    json key = s.wait_event("key");
    EXPECT_TRUE(key["paused"].get<bool>());
    EXPECT_FALSE(key["hud"].empty());
    expect_screen(s, show_screen(key), load_world_file("scenes/" + key["scene"].get<std::string>()).world->palette, "show-paused");
    s.ok("hello");  // (ends the show)

    // Mode X's pages in RAM: a pattern a page, each flip shown scaled, each page read back
    s.ok("mode modex");
    const raster::Pattern in_page[3] = {raster::Pattern::Ramp, raster::Pattern::Grid, raster::Pattern::Planes};
    for (int page = 0; page < 3; ++page) s.ok("pattern " + std::string(raster::pattern_name(in_page[page])) + " " + std::to_string(page));
    for (int page = 0; page < 3; ++page) {
        s.ok("flip " + std::to_string(page));
        const IndexImage want = render_pattern(in_page[page], MODE_X);
        expect_screen(s, want, default_palette(), std::string("page") + std::to_string(page));
        EXPECT_TRUE(compare(s.readback(page), want).equal()) << "page " << page;
    }
    // mode 13h: 320 x 200, scaled the same way
    s.ok("mode 13h");
    s.ok("pattern border 0");
    s.ok("flip 0");
    expect_screen(s, render_pattern(raster::Pattern::Border, MODE_13H), default_palette(), "13h");
    // a 3D frame in the scene's own palette; the loops that program a VGA are not checked (none is there)
    s.ok("mode modex");
    LoadedWorld host = load_world_file("scenes/cube.scene");
    s.ok("load cube.scene");
    json r = s.ok("frame 37 persp-subdiv-16 1 linear");
    raster::RenderStats stats;
    IndexImage want = render_world_frame(host, *world_frame(host, 37), *raster::find_mapper("persp-subdiv-16"), raster::Axis::Rows, &stats);
    EXPECT_EQ(r["pixels"], stats.pixels);
    s.ok("flip 1");
    expect_screen(s, want, host.world->palette, "cube-37");
    EXPECT_FALSE(s.ok("selftest 10")["vga_loops_checked"].get<bool>());
}

INSTANTIATE_TEST_SUITE_P(Firmware, Uefi, testing::Values(Firmware::Uefi64, Firmware::Uefi32),
                         [](const testing::TestParamInfo<Firmware>& i) { return i.param == Firmware::Uefi64 ? "x64" : "ia32"; });

}  // namespace
