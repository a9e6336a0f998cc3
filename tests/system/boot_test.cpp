// System tests: booting by -kernel, from the ISO as a CD and as a USB stick, boot options, the loader check.
#include "tests/system/system.h"

#include "qemu/tools/demo_scenes.h"

#include <thread>

namespace {

using namespace systest;

void expect_hello(Session& s, const std::string& mode) {
    json hello = s.ok("hello");
    EXPECT_EQ(hello["cmd"], "hello");
    EXPECT_EQ(hello["version"], s.boot_line()["version"]);
    EXPECT_FALSE(hello["cpu"]["vendor"].get<std::string>().empty());
    auto features = hello["cpu"]["features"];
    const Machine m = machine();
    EXPECT_EQ(std::find(features.begin(), features.end(), "tsc") != features.end(), m.has_tsc()) << features;
    EXPECT_NE(std::find(features.begin(), features.end(), "fpu"), features.end()) << features;
    if (m.has_tsc()) {
        EXPECT_GT(hello["tsc_hz"].get<uint64_t>(), 1'000'000u);  // calibrated against the PIT
    } else {
        EXPECT_EQ(hello["tsc_hz"], 0u);
    }
    EXPECT_EQ(hello["clock"]["name"], m.has_tsc() ? "tsc" : "pit");
    EXPECT_EQ(hello["cpu_class"], m.cpu_class());
    EXPECT_EQ(hello["isa"], m.isa());
    EXPECT_EQ(hello["mode"], mode);
}

TEST(Boot, KernelByMultiboot) {
    SessionOptions o = options_for_this_test();
    Session s(o);
    EXPECT_EQ(s.boot_line()["boot"], "serve");
    EXPECT_TRUE(s.boot_line()["bochs_vbe_cleared"].get<bool>()) << "QEMU's std VGA has the Bochs VBE registers";
    expect_hello(s, "text");
    s.ok("exit 0");
    ExitInfo e = s.wait_exit();
    EXPECT_TRUE(e.exited);
    EXPECT_EQ(e.status, 1) << e.describe();
}

TEST(Boot, IcountMakesTheTscCountInstructions) {
    SessionOptions o = options_for_this_test();
    o.icount = true;
    Session s(o);
    // shift=0: one instruction per virtual nanosecond, so the PIT-calibrated rate is 1 GHz
    double hz = double(s.ok("hello")["tsc_hz"].get<uint64_t>());
    EXPECT_NEAR(hz, 1e9, 1e6);
}

// Which test pattern fills the screen, or -1.
int pattern_shown(const IndexImage& shown) {
    for (int i = 0; i < raster::PATTERN_COUNT; ++i)
        if (compare(shown, render_pattern(raster::Pattern(i), MODE_X)).equal()) return i;
    return -1;
}

size_t lit_pixels(const RgbImage& dump) {
    size_t lit = 0;
    for (size_t i = 0; i < dump.rgb.size(); i += 3) lit += (dump.rgb[i] | dump.rgb[i + 1] | dump.rgb[i + 2]) ? 1 : 0;
    return lit;
}

// The ISO's default GRUB entry loads every demo scene and its textures as Multiboot modules and
// starts the show, which plays them in Mode X; the first command ends it. The modules are then
// the scenes `load` finds (a module comes before a built-in of the same name).
void boot_iso(BootMedium medium, bool watch_the_show) {
    SessionOptions o = options_for_this_test();
    o.medium = medium;
    Session s(o);
    EXPECT_EQ(s.boot_line()["cmdline"], "boot=demo") << "GRUB passes the menu entry's options";
    EXPECT_EQ(s.boot_line()["boot"], "demo");
    EXPECT_EQ(s.boot_line()["modules"], int(harness::demo_scenes().size()) + 5) << "every demo scene and freedoom's five texture files";
    EXPECT_EQ(s.boot_line()["modules_skipped"], 0);
    if (watch_the_show) {
        std::this_thread::sleep_for(std::chrono::milliseconds(700));
        RgbImage first = s.screendump("show-1");
        std::this_thread::sleep_for(std::chrono::milliseconds(700));
        RgbImage second = s.screendump("show-2");
        EXPECT_GT(lit_pixels(first), 4000u) << "a scene on screen";
        EXPECT_NE(first.rgb, second.rgb) << "and moving";
    }
    expect_hello(s, "modex");
    json load = s.ok("load freedoom.scene");
    EXPECT_EQ(load["origin"], "module");
    EXPECT_EQ(load["palette"], "floor");
    json f = s.ok("frame 0 exact 0");
    EXPECT_EQ(f["pixels"], 76800) << "the corridor fills the screen";
    EXPECT_EQ(f["rejected"], 0);
    s.ok("exit 5");
    EXPECT_EQ(s.wait_exit().status, 11);
}

TEST(Boot, IsoAsCdrom) { boot_iso(BootMedium::Cdrom, true); }

TEST(Boot, IsoAsUsbStick) { boot_iso(BootMedium::Usb, false); }

// show=patterns: the test patterns in turn, every 2 s (always drawn into a hidden page first).
TEST(Boot, ThePatternShow) {
    SessionOptions o = options_for_this_test();
    o.append = "boot=demo show=patterns";
    Session s(o);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    int first = pattern_shown(s.screenshot("show-1", MODE_X, default_palette()));
    EXPECT_GE(first, 0) << "the show has a whole pattern on screen";
    // the next pattern comes 2 s of the guest's time later: polled for up to 10 s of ours, since a
    // loaded host can run the guest slower than real time
    int second = first;
    for (int tries = 0; tries < 20 && (second == first || second < 0); ++tries) {
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
        second = pattern_shown(s.screenshot("show-2", MODE_X, default_palette()));
    }
    EXPECT_GE(second, 0);
    EXPECT_NE(second, first) << "the show moved on to the next pattern";
    expect_hello(s, "modex");
}

TEST(Boot, OptionsAreParsedAndUnknownOnesReported) {
    SessionOptions o = options_for_this_test();
    o.append = "boot=serve interval=250 colour=blue interval=0";
    Session s(o);
    const json& b = s.boot_line();
    EXPECT_EQ(b["boot"], "serve");
    EXPECT_EQ(b["interval_ms"], 250);
    EXPECT_EQ(b["ignored_options"], json({"colour=blue", "interval=0"}));
}

TEST(Boot, TheShowRunsUntilTheFirstCommand) {
    SessionOptions o = options_for_this_test();
    o.append = "boot=demo interval=1";
    Session s(o);
    json hello = s.ok("hello");
    EXPECT_EQ(hello["mode"], "modex");
    // the server answers and the show no longer flips: two screendumps a while apart are equal
    IndexImage a = s.screenshot("first", MODE_X, default_palette());
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // 200 show intervals, were it still running
    s.ok("hello");
    IndexImage b = s.screenshot("second", MODE_X, default_palette());
    EXPECT_TRUE(compare(a, b).equal());
}

TEST(Boot, AWrongMultibootMagicIsReportedAndHalts) {
    // a fixture loader enters the kernel with eax = 0x0BADC0DE
    QemuConfig c;
    c.image = build_dir() + "/kernel/tests/wrong_magic_loader.elf";
    c.extra_args = {"-initrd", build_dir() + "/kernel/modexlab.elf"};
    c.run_dir = build_dir() + "/runs/Boot.AWrongMultibootMagic";
    QemuProcess q(c);
    KernelLink k(q.take_serial());
    try {
        k.wait_boot(std::chrono::seconds(30));
        FAIL() << "booted despite the wrong magic";
    } catch (const HarnessError& e) {
        EXPECT_NE(std::string(e.what()).find("bad multiboot magic 0x0badc0de"), std::string::npos) << e.what();
    }
    auto e = q.wait_exit(std::chrono::seconds(10));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->status, 2 * 0x60 + 1) << e->describe();
}

}  // namespace
