// GoogleTest main for modexlab-tests: runs the tests and ends with the line "tests: N passed, N failed".
#include <gtest/gtest.h>

#include <cstdio>

namespace {

class SummaryListener : public testing::EmptyTestEventListener {
    void OnTestProgramEnd(const testing::UnitTest& u) override {
        std::printf("tests: %d passed, %d failed\n", u.successful_test_count(), u.failed_test_count());
        std::fflush(stdout);
    }
};

}  // namespace

int main(int argc, char** argv) {
#if defined(__i386__)
    // As the kernel does (boot/entry.asm): x87 at 53-bit precision, so doubles round as SSE2's.
    const unsigned short control = 0x027F;
    asm volatile("fldcw %0" : : "m"(control));
#endif
    testing::InitGoogleTest(&argc, argv);
    testing::UnitTest::GetInstance()->listeners().Append(new SummaryListener);
    return RUN_ALL_TESTS();
}
