// `modexlab run --display` (make run DISPLAY=1): a QEMU window where a display exists, a clear
// failure where none does, never a silent wait. The window is checked on Xvfb, whose screen is a
// file (-fbdir: an XWD image) the test reads.
#include "tests/system/system.h"

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <set>
#include <thread>

namespace {

using namespace systest;

std::string harness_run() {
    return build_dir() + "/host/modexlab run --kernel " + build_dir() + "/kernel/modexlab.elf --display --scene cube";
}

// The colours on an X screen dumped as XWD (big-endian header: its size first, bits a pixel at
// word 11, bytes a line at 12, colour-map entries at 19), 24-bit colour in 32-bit pixels, that are
// not a grey: what a window's chrome does not have and a texture-mapped scene does.
size_t colours_not_grey(const std::string& xwd) {
    const std::string bytes = read_whole_file(xwd);
    auto word = [&](size_t i) {
        const auto* b = reinterpret_cast<const unsigned char*>(bytes.data()) + 4 * i;
        return uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | b[3];
    };
    if (bytes.size() < 100 || word(11) != 32) return 0;
    const size_t width = word(4), height = word(5), line = word(12), start = word(0) + 12 * size_t(word(19));
    std::set<uint32_t> colours;
    for (size_t y = 0; y < height && start + (y + 1) * line <= bytes.size(); ++y)
        for (size_t x = 0; x < width; ++x) {
            const auto* p = reinterpret_cast<const unsigned char*>(bytes.data()) + start + y * line + 4 * x;
            if (p[0] != p[1] || p[1] != p[2]) colours.insert(uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16);
        }
    return colours.size();
}

// An X display number with no server (no socket in /tmp/.X11-unix), from this process's id.
int free_display() {
    for (int n = 100 + getpid() % 400;; ++n)
        if (!std::filesystem::exists("/tmp/.X11-unix/X" + std::to_string(n)) && !std::filesystem::exists("/tmp/.X" + std::to_string(n) + "-lock"))
            return n;
}

TEST(DisplayRun, WithoutADisplayFailsAtOnceAndSaysWhy) {
    const ToolRun r = run_command("env -u DISPLAY -u WAYLAND_DISPLAY timeout 30 " + harness_run());
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_NE(r.out.find("no display for a window: neither DISPLAY nor WAYLAND_DISPLAY is set"), std::string::npos) << r.out;
}

TEST(DisplayRun, ADisplayThatCannotBeOpenedEndsTheRunWithQemusWords) {
    const ToolRun r = run_command("env -u WAYLAND_DISPLAY DISPLAY=:" + std::to_string(free_display()) + " timeout 60 " + harness_run());
    EXPECT_EQ(r.status, 1) << r.out << "(124: it waited)";
    EXPECT_NE(r.out.find("gtk initialization failed"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("a QEMU window plays"), std::string::npos) << r.out;
}

// The window opens on an X server and shows the scene: many colours that are not greys.
TEST(DisplayRun, OpensAWindowThatShowsTheScene) {
    const std::string dir = build_dir() + "/test-tmp/display";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string display = ":" + std::to_string(free_display());
    ASSERT_EQ(std::system(("Xvfb " + display + " -screen 0 800x600x24 -fbdir " + dir + " -br -nolisten tcp >" + dir +
                           "/xvfb.log 2>&1 & echo $! >" + dir + "/xvfb.pid").c_str()), 0);
    ASSERT_EQ(std::system(("env -u WAYLAND_DISPLAY DISPLAY=" + display + " timeout 120 " + harness_run() + " >" + dir +
                           "/run.log 2>&1 & echo $! >" + dir + "/run.pid").c_str()), 0);
    const std::string said = "a QEMU window plays cube with auto; close it to stop";
    size_t colours = 0;
    std::string out;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while ((colours < 64 || out.find(said) == std::string::npos) && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
        if (std::filesystem::exists(dir + "/Xvfb_screen0")) colours = colours_not_grey(dir + "/Xvfb_screen0");
        out = read_whole_file(dir + "/run.log");
    }
    std::system(("kill $(cat " + dir + "/run.pid) $(cat " + dir + "/xvfb.pid) 2>/dev/null").c_str());
    EXPECT_GE(colours, 64u) << "the screen stayed without the scene\n" << out;
    EXPECT_NE(out.find(said), std::string::npos) << out;
}

}  // namespace
