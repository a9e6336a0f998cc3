// The machines of the era: the boot line names the CPU's class, the clock and the build of the C++
// that runs, as the machine QEMU models has them (the CPU tier: tests/system/system.h, Machine),
// and isa=i486 keeps the 486's build on a P6; a PC without an FPU is refused, saying why.
#include "tests/system/system.h"

namespace {

using namespace systest;

TEST(Cpu, TheBootLineNamesTheCpuTheClockAndTheBuild) {
    const Machine m = machine();
    Session s(options_for_this_test());
    const json& boot = s.boot_line();
    EXPECT_EQ(boot["cpu_class"], m.cpu_class());
    EXPECT_EQ(boot["isa"], m.isa());
    EXPECT_EQ(boot["cpu_isa"], m.isa());
    EXPECT_EQ(boot["clock"], m.has_tsc() ? "tsc" : "pit");
    if (!m.has_tsc()) {
        EXPECT_EQ(boot["clock_hz"], 1193182u);
        EXPECT_EQ(boot["tsc_hz"], 0u);
    }
    s.ok("mode modex");
    s.ok("load cube.scene");
    const json r = s.ok("frame 37 exact 0 linear");
    EXPECT_GT(r["ticks"].get<uint64_t>(), 0u) << "the frame is timed by the machine's clock";
    s.ok("exit 0");
    s.wait_exit();
}

TEST(Cpu, Isa486KeepsThe486BuildOnAP6) {
    const Machine m = machine();
    if (!m.has_cmov()) GTEST_SKIP() << "this CPU runs the 486's build anyway";
    SessionOptions o = options_for_this_test();
    o.append += " isa=i486";
    Session s(o);
    EXPECT_EQ(s.boot_line()["isa"], "i486");
    EXPECT_EQ(s.boot_line()["cpu_isa"], "p6");
    EXPECT_TRUE(s.boot_line()["ignored_options"].empty()) << s.boot_line()["ignored_options"];
    EXPECT_EQ(s.ok("hello")["isa"], "i486");
}

// A 486 has no TSC: its clock is measured by a loop of known clocks against the PIT. Under icount
// (one instruction a nanosecond) the loop's DEC and JNZ, 4 clocks on a 486, take 2 ns: 2 GHz.
TEST(Cpu, A486sClockIsMeasuredAgainstThePit) {
    SessionOptions o = options_for_this_test();
    o.cpu = "486";
    o.icount = true;
    Session s(o);
    EXPECT_EQ(s.boot_line()["clock"], "pit");
    EXPECT_EQ(s.boot_line()["cpu_hz_from"], "486 loop");
    EXPECT_NEAR(s.boot_line()["cpu_hz"].get<double>(), 2e9, 2e7) << s.boot_line().dump();
}

// A 486SX (QEMU's 486 without its FPU flag: TCG runs x87 code all the same, so the flag is what
// says so here) is told why on COM1 before the kernel halts.
TEST(Cpu, WithoutAnFpuItSaysWhyAndHalts) {
    SessionOptions o = options_for_this_test();
    o.cpu = "486,-fpu";
    try {
        Session s(o);
        FAIL() << "booted without an FPU: " << s.boot_line().dump();
    } catch (const HarnessError& e) {
        EXPECT_NE(std::string(e.what()).find("no FPU (a 486SX, or a 386 without a 387)"), std::string::npos) << e.what();
    }
}

}  // namespace
