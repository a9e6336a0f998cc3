// The kernel's clock where the CPU has no TSC: the PIT (forced with clock=pit) against QEMU's
// icount, under which the TSC counts instructions and the PIT ticks once every 838.1 of them.
#include "tests/system/system.h"

namespace {

using namespace systest;

struct ClockRun {
    json boot, hello;
    uint64_t blit = 0, frames = 0, wall = 0;
};

// The blit of four frames of the cube through the RAM surface: an interval with no clock read
// inside it, the same instructions in every boot.
ClockRun boot_and_blit(const std::string& clock) {
    SessionOptions o = options_for_this_test();
    o.name += "." + clock;
    o.icount = true;
    o.append += " clock=" + clock;
    Session s(o);
    ClockRun r;
    r.boot = s.boot_line();
    r.hello = s.ok("hello");
    s.ok("mode modex");
    s.ok("load cube.scene");
    const json b = s.ok("bench 4 affine linear", [](const json&) {});
    r.blit = b["ticks_blit"]["sum"].get<uint64_t>();
    r.frames = b["frames"].get<uint64_t>();
    // and 300 frames played: some 300 million instructions, past channel 0's wrap (65536 ticks) a few times
    r.wall = s.ok("play 300 affine linear", [](const json&) {})["ticks_wall"].get<uint64_t>();
    s.ok("exit 0");
    s.wait_exit();
    return r;
}

TEST(Clock, ThePitAgainstIcount) {
    if (!machine().has_tsc()) GTEST_SKIP() << "no TSC to count the instructions: the PIT is the clock here (Boot.*, Bench.* check it)";
    const ClockRun tsc = boot_and_blit("tsc"), pit = boot_and_blit("pit");
    EXPECT_EQ(tsc.boot["clock"], "tsc");
    EXPECT_EQ(pit.boot["clock"], "pit");
    EXPECT_EQ(pit.boot["clock_hz"], 1193182u);
    EXPECT_EQ(pit.hello["clock"]["name"], "pit");
    EXPECT_EQ(pit.boot["tsc_hz"], 0u) << "the TSC is neither calibrated nor used";
    EXPECT_EQ(pit.boot["clock_read_cost"], 0u) << "a PIT read is a few dozen instructions: under a tick";
    EXPECT_LT(tsc.boot["clock_read_cost"].get<uint64_t>(), 20u) << "a TSC read is a few instructions";
    ASSERT_EQ(tsc.frames, 4u);
    // the same instructions, counted in PIT ticks: within one tick a frame and 1% of it
    const double expected = double(tsc.blit) * 1193182.0 / 1e9;
    EXPECT_GT(expected, 100.0) << "an interval of many PIT ticks";
    EXPECT_NEAR(double(pit.blit), expected, 0.01 * expected + double(pit.frames))
        << pit.blit << " PIT ticks for " << tsc.blit << " instructions";
    const double played = double(tsc.wall) * 1193182.0 / 1e9;
    EXPECT_GT(played, 4 * 65536.0) << "an interval across several wraps of the PIT's count";
    EXPECT_NEAR(double(pit.wall), played, 0.01 * played) << pit.wall << " PIT ticks for " << tsc.wall << " instructions";
}

}  // namespace
