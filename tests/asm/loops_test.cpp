// The NASM loops against their C++ twins, in a 32-bit static host program: 100000 random argument
// blocks per loop, or MODEXLAB_ASM_CASES (spans 0..320 long, positive and negative steps and
// strides, every texture size the loop accepts, extreme start values), destination buffers
// compared byte for byte.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "kernel/core/selftest.h"
#include "kernel/mappers/exact.h"

namespace {

using namespace raster;

// MODEXLAB_ASM_CASES=N checks N instead (the short run under the emulator in make test).
uint32_t cases() {
    const char* env = std::getenv("MODEXLAB_ASM_CASES");
    return env ? uint32_t(std::max(1L, std::atol(env))) : 100000;
}
const uint32_t CASES = cases();

// The mappers with a NASM loop, one per loop.
struct Checked {
    const Mapper* loops[32] = {};
    int count = checked_loops(loops, 32);
};
const Checked CHECKED;

class Loops : public testing::TestWithParam<int> {};

TEST_P(Loops, NasmMatchesTheTwinBitForBit) {
    const Mapper& loop = *CHECKED.loops[GetParam()];
    ASSERT_NE(loop.asm_loop, nullptr) << loop.name << " has no NASM loop in this build";
    if (loop.needs & NEED_VGA_FOR_ASM) GTEST_SKIP() << loop.name << " programs the VGA: the kernel's selftest checks it (Mappers.TheKernelSelftest...)";
    std::vector<uint8_t> a(CHECK_DST_BYTES), b(CHECK_DST_BYTES), texels(CHECK_TEXEL_BYTES);
    CheckBuffers buffers{a.data(), b.data(), a.size(), texels.data()};
    LoopCheck c = loop.check(loop, loop.asm_loop, 20261121, CASES, buffers);
    EXPECT_EQ(c.cases, CASES);
    EXPECT_GT(c.pixels, CASES * 100) << "the cases drew spans worth comparing";
    EXPECT_EQ(c.mismatches, 0u) << loop.name << ": first mismatch in case " << c.first_mismatch;
    std::printf("%s: %u cases, %u pixels, %u mismatches\n", loop.name, c.cases, c.pixels, c.mismatches);
}

// A check that could not fail would prove nothing: a deliberately wrong loop must be caught.
void off_by_one(const void* raw) {
    ExactArgs a = *static_cast<const ExactArgs*>(raw);
    exact_loop(&a);
    if (a.count > 0) a.dst[0] ^= 1;
}

TEST(LoopCheck, CatchesAWrongLoop) {
    std::vector<uint8_t> a(CHECK_DST_BYTES), b(CHECK_DST_BYTES), texels(CHECK_TEXEL_BYTES);
    CheckBuffers buffers{a.data(), b.data(), a.size(), texels.data()};
    LoopCheck c = check_exact(*find_mapper("exact"), off_by_one, 1, 1000, buffers);
    EXPECT_GT(c.mismatches, 900u);
}

INSTANTIATE_TEST_SUITE_P(All, Loops, testing::Range(0, CHECKED.count),
                         [](const testing::TestParamInfo<int>& p) {
                             std::string n = CHECKED.loops[p.param]->name;
                             for (char& ch : n)
                                 if (ch == '-') ch = '_';
                             return n;
                         });

}  // namespace
