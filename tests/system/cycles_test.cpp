// The timing model over whole frames (docs/cycles.md, "Whole frames"): the kernel benched under
// QEMU with the timing plugin gives the same instruction counts as without it, the plugin sees the
// instructions the kernel counts, and its cycles split into the probe's phases as the loops' own
// figures say they must; over the ISA bus the display writes stall the CPU.
#include "tests/system/system.h"

#include <filesystem>

#include "qemu/harness/timing_plugin.h"

namespace {

using namespace systest;

struct BenchRun {
    json reply;
    std::vector<json> frames;
    std::vector<json> rows;  // the plugin's
};

// `bench 2 fatmap-lut` on the 256-texel ball, under icount on QEMU's `cpu`, with the plugin and
// its bus models where `buses` are given.
BenchRun bench(const std::string& cpu, const std::vector<std::string>& buses) {
    SessionOptions o = options_for_this_test();
    o.cpu = cpu;
    o.icount = true;
    o.name += "." + cpu + (buses.empty() ? "" : ".plugin");
    TimingPlugin p;
    p.cpu = cpu, p.buses = buses;
    p.out = build_dir() + "/runs/" + o.name + ".cycles.jsonl";
    std::filesystem::create_directories(build_dir() + "/runs");
    std::filesystem::remove(p.out);
    if (!buses.empty()) o.plugin = timing_plugin_spec(p, build_dir() + "/kernel/modexlab.elf");
    BenchRun r;
    {
        Session s(o);
        s.ok("mode modex");
        s.ok("load ball-256.scene");
        r.reply = s.ok("bench 2 fatmap-lut", [&](const json& e) { r.frames.push_back(e); });
        s.ok("exit 0");
        s.wait_exit();
    }
    if (!buses.empty()) r.rows = timing_plugin_rows(p.out);
    return r;
}

TEST(WholeFrames, ThePluginCountsWhatTheKernelRunsAndChangesNoFigure) {
    const BenchRun plain = bench("pentium", {}), timed = bench("pentium", {"zero-wait"});
    ASSERT_EQ(plain.frames.size(), 2u);
    ASSERT_EQ(timed.frames.size(), 2u);
    for (size_t i = 0; i < 2; ++i) EXPECT_EQ(plain.frames[i], timed.frames[i]) << "the plugin observes, it does not alter";
    ASSERT_EQ(timed.rows.size(), 1u);
    const json& row = timed.rows[0];
    EXPECT_EQ(row["frames"], 2);
    EXPECT_EQ(row["cpu"], "pentium");
    // the instructions of each lap's interval, as the plugin counted them between the probe's
    // marks, less the kernel's own lap cost, against the kernel's icount of the phase: the same
    // within a few instructions a lap (a mark is stored a few instructions after the clock is read,
    // how many depending on where the lap is inlined); walking is the rest of the drawing in the
    // kernel's figures, not a lap's
    const uint64_t lap_cost = timed.reply["lap_cost"];
    const char* const PHASES[] = {"setup", "walk", "inner", "choose"};
    for (int p : {0, 2, 3}) {
        uint64_t kernel = 0;
        for (const json& f : timed.frames) kernel += f[std::string("ticks_") + PHASES[p]].get<uint64_t>();
        const uint64_t raw = row["phase_instructions"][p], laps = row["laps"][p];
        EXPECT_NEAR(double(raw - laps * lap_cost), double(kernel), 4.0 * double(laps) + 16) << PHASES[p] << ": " << row.dump();
    }
    uint64_t pixels = 0;
    for (const json& f : timed.frames) pixels += f["pixels"].get<uint64_t>();
    const uint64_t seen = row["instructions"];
    EXPECT_LT(row["unmodelled"].get<uint64_t>(), seen / 1000) << row.dump();
    // the inner loops' cycles: at least fatmap-lut's 4 cycles a pixel (its loop's steady state,
    // make listing), and every phase counted
    EXPECT_GE(row["inner"].get<uint64_t>(), 4 * pixels) << row.dump();
    EXPECT_GT(row["setup"].get<uint64_t>(), 0u);
    EXPECT_GT(row["walk"].get<uint64_t>(), 0u);
    EXPECT_EQ(row["bus_stall"], 0) << "zero-wait";
    EXPECT_GT(row["display_writes"].get<uint64_t>(), 0u) << "the blit to the VGA";
}

// One run, two buses: the same instructions, the frames longer over ISA by the bus's stalls.
TEST(WholeFrames, TheIsaBusStallsTheDisplayWrites) {
    const BenchRun run = bench("486", {"zero-wait", "isa"});
    ASSERT_EQ(run.rows.size(), 2u);
    const json &z = run.rows[0], &i = run.rows[1];
    ASSERT_EQ(z["bus"], "zero-wait");
    ASSERT_EQ(i["bus"], "isa");
    auto number = [](const json& j, const char* key) { return j[key].get<uint64_t>(); };
    EXPECT_EQ(number(z, "instructions"), number(i, "instructions"));
    EXPECT_EQ(number(z, "display_writes"), number(i, "display_writes"));
    EXPECT_GT(number(i, "display_writes"), 0u) << "the blit to the VGA";
    EXPECT_GT(number(i, "outs"), 0u) << "Mode X's map mask, for the blit; the PIT, for the clock";
    EXPECT_EQ(number(z, "inner"), number(i, "inner")) << "the inner loops draw into RAM: no bus";
    EXPECT_EQ(number(z, "bus_stall"), 0u);
    EXPECT_GT(number(i, "bus_stall"), 0u);
    EXPECT_EQ(number(i, "frame_cycles") - number(i, "bus_stall"), number(z, "frame_cycles"))
        << "the frames longer by the bus's stalls: " << z.dump() << "\n" << i.dump();
}

}  // namespace
