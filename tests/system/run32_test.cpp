// The 32-bit programs on any machine: run32 runs them natively where this machine's kernel can,
// else under qemu-i386. The emulated path is taken here whatever the machine can do.
#include "tests/system/system.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace {

using namespace systest;

std::string run32() { return build_dir() + "/host32/run32"; }

TEST(Run32, SaysHowItRunsThem) {
    ToolRun probed = run_command(run32() + " --how");
    ASSERT_EQ(probed.status, 0) << probed.out;
    EXPECT_TRUE(probed.out == "native\n" || probed.out.rfind("emulated: ", 0) == 0) << probed.out;
    ToolRun forced = run_command("MODEXLAB_RUN32=emulated " + run32() + " --how");
    EXPECT_EQ(forced.out, "emulated: MODEXLAB_RUN32=emulated\n");
    ToolRun wrong = run_command("MODEXLAB_RUN32=sometimes " + run32() + " --how");
    EXPECT_EQ(wrong.status, 2);
    EXPECT_NE(wrong.out.find("native or emulated"), std::string::npos) << wrong.out;
}

// Every NASM loop against its twin on a few thousand cases, and the check that must catch a wrong
// loop, through the emulator: a qemu-i386 first on PATH notes that it ran, then hands over.
TEST(Run32, TheEmulatorRunsTheNasmAgainstTwinTests) {
    const std::string dir = build_dir() + "/test-tmp/run32", marker = dir + "/emulator-ran";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    ToolRun real = run_command("command -v qemu-i386");
    ASSERT_EQ(real.status, 0) << "qemu-i386 is missing: make deps installs qemu-user";
    {
        std::ofstream wrapper(dir + "/qemu-i386");
        wrapper << "#!/bin/sh\necho \"$@\" >> '" << marker << "'\nexec '" << real.out.substr(0, real.out.size() - 1) << "' \"$@\"\n";
    }
    std::filesystem::permissions(dir + "/qemu-i386", std::filesystem::perms::owner_all);
    ToolRun r = run_command("PATH='" + dir + "':\"$PATH\" MODEXLAB_RUN32=emulated MODEXLAB_ASM_CASES=2000 " + run32() + " " + build_dir() +
                            "/host32/modexlab-asm-tests --gtest_filter='All/Loops.*:LoopCheck.*'");
    EXPECT_EQ(r.status, 0) << r.out;
    const size_t summary = r.out.rfind("\ntests: ");
    int passed = -1, failed = -1;
    ASSERT_NE(summary, std::string::npos) << r.out;
    ASSERT_EQ(std::sscanf(r.out.c_str() + summary, "\ntests: %d passed, %d failed", &passed, &failed), 2) << r.out;
    EXPECT_GE(passed, 10) << r.out;
    EXPECT_EQ(failed, 0) << r.out;
    EXPECT_NE(r.out.find("[       OK ] LoopCheck.CatchesAWrongLoop"), std::string::npos) << r.out;
    std::ifstream ran(marker);
    std::string line;
    ASSERT_TRUE(std::getline(ran, line)) << "run32 did not go through qemu-i386";
    EXPECT_NE(line.find("modexlab-asm-tests"), std::string::npos) << line;
}

}  // namespace
