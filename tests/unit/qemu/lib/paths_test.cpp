// Under test: qemu/lib/paths.h.
// The tools' build directory is the one they were built into, shown relative to the working
// directory; a path outside it is shown as given.
#include <gtest/gtest.h>

#include <filesystem>

#include "qemu/lib/paths.h"

namespace {

using namespace harness;

TEST(Paths, APathUnderTheWorkingDirectoryIsShownRelativeToIt) {
    const std::string cwd = std::filesystem::current_path().string();
    EXPECT_EQ(shown_path(cwd + "/build/runs/run/serial.log"), "build/runs/run/serial.log");
    EXPECT_EQ(shown_path(cwd + "/build/../scenes/cube.scene"), "scenes/cube.scene");
    EXPECT_EQ(shown_path("build/run"), "build/run");
    EXPECT_EQ(shown_path("/nonexistent-top/x.png"), "/nonexistent-top/x.png");
    EXPECT_EQ(shown_path("../elsewhere/x.png"), "../elsewhere/x.png");
}

// The tests run from the repository's top, built into build/: the build they belong to.
TEST(Paths, TheBuildIsTheOneTheProgramWasBuiltInto) {
    if (const char* env = std::getenv("MODEXLAB_BUILD_DIR"); env && *env) GTEST_SKIP() << "MODEXLAB_BUILD_DIR names it";
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe");
    EXPECT_EQ(std::filesystem::absolute(build_dir()).lexically_normal(), program.parent_path().parent_path());
    EXPECT_TRUE(std::filesystem::exists(build_dir() + "/kernel")) << build_dir();
}

}  // namespace

