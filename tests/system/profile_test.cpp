// modexlab-profile (docs/bench.md, "Where the instructions go"): the instructions it counts by
// function add up to what the kernel's own clock counts under icount, the functions only one
// mapper runs show in its column alone, and a mapper against itself differs nowhere.
#include "tests/system/system.h"

#include <cstdio>
#include <sstream>

namespace {

using namespace systest;

struct ProfileLine {
    double mine, against, difference;
    std::string what;
};

// Its table's lines: three figures a polygon, then the function (or what the line sums).
std::vector<ProfileLine> table(const std::string& out) {
    std::vector<ProfileLine> lines;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) {
        ProfileLine l{};
        int used = 0;
        if (std::sscanf(line.c_str(), "%lf %lf %lf %n", &l.mine, &l.against, &l.difference, &used) == 3 && used > 0) {
            l.what = line.substr(size_t(used));
            lines.push_back(l);
        }
    }
    return lines;
}

const ProfileLine* find(const std::vector<ProfileLine>& lines, const std::string& what) {
    for (const ProfileLine& l : lines)
        if (l.what.find(what) != std::string::npos) return &l;
    return nullptr;
}

ToolRun profile(const std::string& args) { return run_command(build_dir() + "/host/modexlab-profile " + args); }

TEST(Profile, CountsWhatTheKernelsClockCountsAndNamesWhereAutoSpendsIt) {
    const ToolRun r = profile("--scene cube --budget 1 --frames 2 --top 60");
    ASSERT_EQ(r.status, 0) << r.out;
    const std::vector<ProfileLine> lines = table(r.out);
    const ProfileLine *total = find(lines, "total inside the frames"), *ticks = find(lines, "the bench's frame ticks");
    ASSERT_TRUE(total && ticks) << r.out;
    // the frames' window holds the timed phases and a few reads of the clock about them, the same
    // for either mapper: what auto spends beyond the other is what the kernel's clock says
    EXPECT_GT(total->mine, ticks->mine) << r.out;
    EXPECT_NEAR(total->difference, ticks->difference, 0.15) << r.out;
    double sum[2] = {0, 0};
    for (const ProfileLine& l : lines)
        if (l.what.find("total") == std::string::npos && l.what.find("the bench's") == std::string::npos) sum[0] += l.mine, sum[1] += l.against;
    EXPECT_NEAR(sum[0], total->mine, 0.1 * double(lines.size())) << "the functions add up to the total";
    EXPECT_NEAR(sum[1], total->against, 0.1 * double(lines.size()));
    // the oriented path's proof runs in auto alone
    const ProfileLine* guard = find(lines, "fast_oriented_guard(");
    ASSERT_TRUE(guard) << r.out;
    EXPECT_GT(guard->mine, 0);
    EXPECT_EQ(guard->against, 0);
}

TEST(Profile, AMapperAgainstItselfDiffersNowhere) {
    const ToolRun r = profile("--scene ball --mapper fast-affine --against fast-affine --frames 1 --top 1000");
    ASSERT_EQ(r.status, 0) << r.out;
    const std::vector<ProfileLine> lines = table(r.out);
    ASSERT_GT(lines.size(), 10u) << r.out;
    for (const ProfileLine& l : lines) EXPECT_EQ(l.difference, 0) << l.what;
}

TEST(Profile, NamesWhatItDoesNotKnowBeforeBooting) {
    const ToolRun mapper = profile("--scene cube --mapper nosuch");
    EXPECT_EQ(mapper.status, 2) << mapper.out;
    EXPECT_NE(mapper.out.find("no mapper 'nosuch'"), std::string::npos) << mapper.out;
    const ToolRun scene = profile("--scene nosuch");
    EXPECT_EQ(scene.status, 2) << scene.out;
    EXPECT_NE(scene.out.find("no demo scene or scene file 'nosuch'"), std::string::npos) << scene.out;
    EXPECT_EQ(scene.out.find(", in QEMU with -icount"), std::string::npos) << "it did not boot: " << scene.out;
    const ToolRun budget = profile("--scene cube --budget lots");
    EXPECT_EQ(budget.status, 2) << budget.out;
}

}  // namespace
