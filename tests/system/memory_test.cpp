// The kernel's memory: its image is small and loaded at 1 MiB, its buffers come from the largest
// stretch of RAM the loader reports (the pool), and a machine with too little is told so, with
// what it needs and what it has, on COM1 (and the screen) before the kernel halts.
#include "tests/system/system.h"

namespace {

using namespace systest;

TEST(Memory, ThePoolIsTheLargestStretchOfRamAboveTheImage) {
    SessionOptions o = options_for_this_test();
    o.memory_mib = 128;
    Session s(o);
    const json& pool = s.boot_line()["pool"];
    const uint32_t start = uint32_t(std::stoul(pool["start"].get<std::string>(), nullptr, 16));
    EXPECT_GE(start, kernel_symbol("__kernel_end")) << "above the image and its static buffers";
    EXPECT_LT(kernel_symbol("__kernel_end"), 8u << 20) << "a small image: the big buffers are the pool's";
    EXPECT_EQ(pool["kib"], 96u << 10) << "128 MiB leave more than the page tables cover";
    EXPECT_GT(pool["taken_kib"].get<uint32_t>(), 0u);
    EXPECT_LT(pool["taken_kib"].get<uint32_t>(), pool["kib"].get<uint32_t>());
}

TEST(Memory, TooLittleIsRefusedWithWhatItNeedsAndWhatItHas) {
    SessionOptions o = options_for_this_test();
    o.memory_mib = 32;
    try {
        Session s(o);
        FAIL() << "booted in 32 MiB: " << s.boot_line().dump();
    } catch (const HarnessError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("not enough memory: modexlab needs 48 MiB of free RAM for its buffers"), std::string::npos) << what;
        EXPECT_NE(what.find("the largest stretch the loader reports is 26 MiB"), std::string::npos) << what;
    }
}

}  // namespace
