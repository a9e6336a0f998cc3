// The bench in the kernel and the report around it: `bench` answers with figures that add up and
// equal the host's counts, gives identical figures in two boots under icount, refuses bad
// arguments; modexlab-bench writes a report with every mapper on a tiny run.
#include "tests/system/system.h"

#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "qemu/accuracy/measure.h"
#include "qemu/tools/trade.h"

namespace {

using namespace systest;

struct Bench {
    json reply;
    std::vector<json> frames;
};

Bench bench(Session& s, const std::string& args) {
    Bench b;
    b.reply = s.ok("bench " + args, [&](const json& e) { b.frames.push_back(e); });
    return b;
}

std::vector<Bench> bench_run(const std::string& name) {
    SessionOptions o = options_for_this_test();
    o.name += "." + name;
    o.icount = true;
    Session s(o);
    s.ok("mode modex");
    s.ok("load cube.scene");
    std::vector<Bench> out = {bench(s, "3 exact"), bench(s, "3 fast-columns vga"), bench(s, "2 quake-subdiv16 linear twin")};
    s.ok("exit 0");
    s.wait_exit();
    return out;
}

TEST(Bench, FiguresAddUpAndEqualTheHostsCounts) {
    SessionOptions o = options_for_this_test();
    o.icount = true;  // ticks are instructions: the probe's own cost is known exactly
    Session s(o);
    s.ok("mode modex");
    s.ok("load cube.scene");
    LoadedWorld host = load_world_file("scenes/cube.scene");
    for (const char* m : {"exact", "persp-subdiv-16", "hecker-steptable", "xsharp-column", "auto"}) {
        const raster::Mapper& mapper = *raster::find_mapper(m);
        std::string surface = raster::surface_name(raster::home_surface(mapper));
        Bench b = bench(s, std::string("4 ") + m + " " + surface);
        ASSERT_EQ(b.frames.size(), 4u) << m;
        uint64_t pixels = 0, levels[3] = {};  // auto's polygons by the level of their proof (RenderStats)
        for (size_t i = 0; i < b.frames.size(); ++i) {
            const json& f = b.frames[i];
            EXPECT_EQ(f["n"], i);
            int32_t n = f["frame"].get<int32_t>();
            EXPECT_EQ(n, int32_t(i * 240 / 4)) << "frames spread over the animation";
            EXPECT_EQ(f["ticks_setup"].get<uint64_t>() + f["ticks_walk"].get<uint64_t>() + f["ticks_inner"].get<uint64_t>() +
                          f["ticks_choose"].get<uint64_t>(),
                      f["ticks_draw"].get<uint64_t>())
                << m;
            // only auto chooses (its plans, tests and bounds: the phase probe's Choose)
            if (mapper.is_auto) EXPECT_GT(f["ticks_choose"].get<uint64_t>(), 0u) << m;
            else EXPECT_EQ(f["ticks_choose"].get<uint64_t>(), 0u) << m;
            EXPECT_EQ(f["ticks"].get<uint64_t>(), f["ticks_geometry"].get<uint64_t>() + f["ticks_clear"].get<uint64_t>() +
                                                      f["ticks_draw"].get<uint64_t>() + f["ticks_blit"].get<uint64_t>());
            auto frame = world_frame(host, n);
            raster::RenderStats stats;
            render_world_frame(host, *frame, mapper, home_axis(mapper), &stats);
            EXPECT_EQ(f["pixels"], stats.pixels) << m << " frame " << n;
            EXPECT_EQ(f["spans"], stats.spans) << m << " frame " << n;
            EXPECT_EQ(f["polygons"], stats.polygons) << m << " frame " << n;
            if (stats.polygons) {
                EXPECT_GT(f["ticks_inner"].get<uint64_t>(), 0u) << m;
            }
            pixels += stats.pixels;
            levels[0] += stats.enveloped, levels[1] += stats.proven_whole, levels[2] += stats.proven_spans;
            EXPECT_LE(stats.enveloped + stats.proven_whole + stats.proven_spans, stats.polygons) << m << " frame " << n;
        }
        EXPECT_EQ(b.reply["pixels"], pixels);
        EXPECT_EQ(b.reply["enveloped"], levels[0]) << m;
        EXPECT_EQ(b.reply["proven_whole"], levels[1]) << m;
        EXPECT_EQ(b.reply["proven_spans"], levels[2]) << m;
        if (mapper.is_auto) {
            EXPECT_GT(levels[1], 0u) << "the cube's faces, each proven by its whole bound";
        }
        EXPECT_LE(b.reply["ticks"]["min"].get<uint64_t>(), b.reply["ticks"]["median"].get<uint64_t>());
        EXPECT_EQ(b.reply["surface"], surface);
    }
    // bad arguments: an error each, and the kernel serves on
    EXPECT_NE(s.command("bench 0 exact")["error"].get<std::string>().find("bad frame count"), std::string::npos);
    EXPECT_NE(s.command("bench 1001 exact")["error"].get<std::string>().find("bad frame count"), std::string::npos);
    EXPECT_NE(s.command("bench 2 no-such-mapper")["error"].get<std::string>().find("unknown mapper"), std::string::npos);
    EXPECT_NE(s.command("bench 2 xsharp-column linear")["error"].get<std::string>().find("cannot draw through"), std::string::npos);
    s.ok("hello");
}

TEST(Bench, NeedsA3dScene) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    json r = s.command("bench 2 exact");
    EXPECT_FALSE(r["ok"].get<bool>());
    EXPECT_NE(r["error"].get<std::string>().find("no 3D scene"), std::string::npos);
}

TEST(Bench, TwoBootsUnderIcountGiveIdenticalFigures) {
    std::vector<Bench> first = bench_run("first"), second = bench_run("second");
    ASSERT_EQ(first.size(), second.size());
    for (size_t i = 0; i < first.size(); ++i) {
        json a = first[i].reply, b = second[i].reply;
        a.erase("seq"), b.erase("seq");
        EXPECT_EQ(a, b) << a.dump() << "\n" << b.dump();
        EXPECT_EQ(first[i].frames, second[i].frames);
        EXPECT_GT(a["ticks_inner"]["sum"].get<uint64_t>(), 0u);
    }
}


TEST(Bench, ATinyRunReportsEveryMapper) {
    std::string out = build_dir() + "/runs/Bench.ATinyRunReportsEveryMapper/report";
    std::filesystem::remove_all(out);
    std::string cmd = build_dir() + "/host/modexlab-bench --scenes cube --frames 1 --no-wall --out " + out + " >" + out + ".log 2>&1";
    std::filesystem::create_directories(out);
    int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "see " << out << ".log";
    auto lines = read_csv(out + "/trade.csv");
    // every mapper, and auto again at its five budgets (0, 0.5, 1, 2, 4 footprints, exact coverage)
    ASSERT_EQ(lines.size(), size_t(raster::MAPPER_COUNT) + 5 + 1);
    ASSERT_EQ(lines[0], csv_header());
    std::map<std::string, size_t> col;
    for (size_t i = 0; i < lines[0].size(); ++i) col[lines[0][i]] = i;
    // host cycles where this machine runs 32-bit programs natively; else none, and trade.md says why
    const bool native32 = run_command(build_dir() + "/host32/run32 --how").out == "native\n";
    std::set<std::string> mappers;
    int on_front = 0;
    for (size_t r = 1; r < lines.size(); ++r) {
        const auto& f = lines[r];
        ASSERT_EQ(f.size(), lines[0].size());
        const std::string& name = f[col["mapper"]];
        EXPECT_EQ(f[col["scene"]], "cube");
        EXPECT_EQ(f[col["kernel_equals_host[bool]"]], "true") << name;
        if (size_t at = name.find('@'); at != std::string::npos) {  // auto at a budget: within it, exactly covered
            EXPECT_EQ(name.substr(0, at), "auto");
            EXPECT_LE(std::stod(f[col["max_footprint_error[footprints]"]]), std::stod(name.substr(at + 1)) + 1e-9) << name;
            EXPECT_EQ(f[col["gaps[pixels]"]], "0") << name;
            EXPECT_EQ(f[col["overdraw[pixels]"]], "0") << name;
            EXPECT_GT(std::stoull(f[col["pixels[count]"]]), 0u) << name;
            EXPECT_GT(std::stoull(f[col["ticks_choose[instructions]"]]), 0u) << name;
            continue;
        }
        mappers.insert(name);
        if (name != "auto") {
            EXPECT_EQ(f[col["ticks_choose[instructions]"]], "0") << name;
        }
        on_front += f[col["pareto[bool]"]] == "true";
        if (std::stoull(f[col["pixels[count]"]]) == 0) continue;
        for (const char* positive : {"ticks_frame[instructions]", "ticks_inner[instructions]", "inner_per_pixel[instructions/pixel]",
                                     "draw_per_pixel[instructions/pixel]", "setup_per_polygon[instructions/polygon]",
                                     "reference_pixels[pixels]"})
            EXPECT_GT(std::stod(f[col[positive]]), 0.0) << f[col["mapper"]] << " " << positive;
        if (native32) {
            EXPECT_GT(std::stod(f[col["host_cycles_ratio[ratio]"]]), 0.0) << name;
        } else {
            EXPECT_EQ(f[col["host_cycles_ratio[ratio]"]], "") << name;
        }
    }
    EXPECT_EQ(mappers.size(), size_t(raster::MAPPER_COUNT));
    EXPECT_GE(on_front, 1);
    const std::string md = read_whole_file(out + "/trade.md");
    EXPECT_EQ(md.find("Host cycles: not measured, this machine runs no 32-bit programs natively") != std::string::npos, !native32);
    EXPECT_EQ(md.find("Host cycles: the same code built as a 32-bit static program") != std::string::npos, native32);
    EXPECT_TRUE(std::filesystem::exists(out + "/trade-cube.png"));
}

}  // namespace
