// Helpers for the QEMU system tests: sessions named after the running test, kernel symbols.
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "kernel/core/policy.h"
#include "kernel/scene/text.h"
#include "qemu/accuracy/measure.h"
#include "qemu/harness/session.h"

namespace systest {

using namespace harness;

// The machine QEMU models for this run of the tests: its default (a P6), or the CPU tier's, named by
// MODEXLAB_TEST_CPU (QEMU's -cpu: 486, pentium) and MODEXLAB_TEST_MEMORY_MIB (tests/run, make test).
struct Machine {
    std::string cpu;     // empty: QEMU's default
    int memory_mib = 0;  // 0: the harness's default
    bool has_tsc() const { return cpu != "486"; }
    bool has_cmov() const { return cpu.empty(); }
    std::string cpu_class() const { return cpu == "486" ? "486" : cpu == "pentium" ? "Pentium (P5)" : "P6 or later"; }
    std::string isa() const { return has_cmov() ? "p6" : "i486"; }
};
inline Machine machine() {
    Machine m;
    if (const char* c = std::getenv("MODEXLAB_TEST_CPU")) m.cpu = c;
    if (const char* mem = std::getenv("MODEXLAB_TEST_MEMORY_MIB")) m.memory_mib = std::atoi(mem);
    return m;
}

// Session options whose run directory (build/runs/...) is named after the current test, on this
// run's machine (the CPU tier's name added).
inline SessionOptions options_for_this_test() {
    const testing::TestInfo* t = testing::UnitTest::GetInstance()->current_test_info();
    SessionOptions o;
    o.name = std::string(t->test_suite_name()) + "." + t->name();
    for (char& c : o.name)
        if (c == '/') c = '_';
    const Machine m = machine();
    o.cpu = m.cpu, o.memory_mib = m.memory_mib;
    if (!m.cpu.empty()) o.name += ".cpu-" + m.cpu;
    if (m.memory_mib) o.name += ".m" + std::to_string(m.memory_mib);
    return o;
}

// The address of a symbol in the kernel ELF (nm -P), or 0 when missing.
inline uint32_t kernel_symbol(const std::string& name) { return uint32_t(elf_symbol(build_dir() + "/kernel/modexlab.elf", name)); }

struct ToolRun {
    int status;
    std::string out;
};

// A command line's exit status and its output (stdout and stderr).
inline ToolRun run_command(const std::string& command) {
    std::string cmd = command + " 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    std::string out;
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    int st = pclose(p);
    return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out};
}

// The screendump against the expected screen, colour for colour; on a difference the expected
// picture is saved beside the dump, RUN_DIR/STEM-expected.png.
inline void expect_screendump_rgb(Session& s, const RgbImage& expected, const std::string& stem) {
    RgbImage dump = s.screendump(stem);
    ASSERT_EQ(dump.width, expected.width);
    ASSERT_EQ(dump.height, expected.height);
    size_t differing = 0;
    for (size_t i = 0; i < dump.rgb.size(); i += 3)
        differing += dump.rgb[i] != expected.rgb[i] || dump.rgb[i + 1] != expected.rgb[i + 1] || dump.rgb[i + 2] != expected.rgb[i + 2];
    if (differing) save_png(s.run_dir() + "/" + stem + "-expected.png", expected);
    EXPECT_EQ(differing, 0u) << stem << ": screendump pixels differ (see " << s.run_dir() << "/" << stem << "{,-expected}.png)";
}

// The same against a picture as QEMU's VGA shows it in the palette (compared by colour: some
// scenes' palettes repeat a colour, so a dump does not always decode to indices).
inline void expect_screendump(Session& s, const IndexImage& want, const raster::Palette& palette, const std::string& stem) {
    expect_screendump_rgb(s, screendump_of(want, palette), stem);
}

// The host's world with the copies the kernel's load reply says it has (`doubled_copies` false:
// left out, short of memory), so that both draw alike.
inline void match_kernel_copies(LoadedWorld& host, const json& load_reply) {
    if (!load_reply.value("doubled_copies", true)) leave_out_doubled_copies(host);
}

// The screen as the show should have it after a key: the frame the event names, drawn on the host
// with the event's mapper, surface and budget, and the HUD's lines over it.
inline IndexImage show_screen(const json& e) {
    LoadedWorld host = load_world_file("scenes/" + e["scene"].get<std::string>());
    auto f = world_frame(host, e["frame"].get<int32_t>());
    const std::string name = e["mapper"];
    const raster::Mapper* m = raster::find_mapper({name.data(), name.size()});
    EXPECT_NE(m, nullptr) << name;
    if (!m) return IndexImage{};
    const json& b = e["budget"];
    f->budget.given = b["given"];
    f->budget.max_error = b["max_error"].is_string() ? raster::ANY_ERROR : b["max_error"].get<double>();
    f->budget.exact_coverage = b["exact_coverage"];
    const raster::Surface surface = e["surface"] == "vga" ? raster::Surface::Vga : raster::Surface::Linear;
    IndexImage want = render_world_frame(host, *f, *m, raster::surface_axis(*m, surface));
    raster::Target t = raster::linear_target(want.index.data(), want.width, want.height, want.width);
    std::vector<std::string> text = e["hud"];
    std::vector<lib::StrView> lines;
    for (const std::string& l : text) lines.push_back({l.data(), l.size()});
    if (!lines.empty()) raster::draw_text_box(t, raster::HUD_X, raster::HUD_Y, lines.data(), int(lines.size()), raster::text_colours(host.world->palette));
    return want;
}

inline const raster::Palette& default_palette() { return raster::palette(raster::PaletteId::Default); }

// Runs a long `command` and, at its first event, sends a line (`hello`, whose reply comes after the
// command's): a line stops long work. Returns the command's reply, checking that the last event it
// sent was its progress event (`cmd` the command's name, `of` all the work it was asked).
inline json stopped_at_first_progress(Session& s, const std::string& command, const std::string& cmd, int of) {
    json progress;
    json r = s.command(command, [&](const json& e) {
        if (progress.is_null()) s.send("hello\n");
        progress = e;
    });
    EXPECT_EQ(progress.value("event", ""), "progress") << progress.dump();
    EXPECT_EQ(progress.value("cmd", ""), cmd);
    EXPECT_EQ(progress.value("of", 0), of);
    return r;
}

}  // namespace systest
