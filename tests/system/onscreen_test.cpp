// The on-screen bench: started by a boot option (and the show's B key), it times every mapper on the
// scene with the TSC, sends each row as a `bench_row` event and draws its pages; the rows equal the
// `bench` command's figures for the same frames (QEMU icount: ticks are instructions), every page
// equals the host's drawing of its lines, and each QR code page decodes (zbarimg, on QEMU's
// screendump) to its part of the CSV, whose rows are the events'.
#include "tests/system/system.h"

#include <sys/wait.h>

#include <cstdio>
#include <map>
#include <sstream>
#include <thread>

#include "kernel/core/policy.h"
#include "kernel/scene/text.h"
#include "qemu/accuracy/measure.h"

namespace {

using namespace systest;

std::string zbar(const std::string& png) {
    FILE* p = popen(("zbarimg --quiet --raw -Sbinary " + png + " 2>/dev/null").c_str(), "r");
    std::string out;
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    pclose(p);
    return out;
}

// A boot into the on-screen bench on the cube, `frames` a row, under icount.
SessionOptions bench_boot(int frames) {
    SessionOptions o = options_for_this_test();
    o.append = "boot=demo bench=" + std::to_string(frames) + " scene=cube.scene mapper=exact";
    o.icount = true;
    o.command_timeout = std::chrono::milliseconds(120000);
    return o;
}

TEST(OnScreenBench, RowsPagesAndQrCodesSayWhatTheBenchMeasured) {
    Session s(bench_boot(1));
    // the rows: one a mapper, in registry order
    std::vector<json> rows;
    for (int i = 0; i < raster::MAPPER_COUNT; ++i) {
        json r = s.wait_event("bench_row");
        EXPECT_EQ(r["scene"], "cube.scene");
        EXPECT_EQ(r["mapper"], raster::MAPPERS[i].name);
        EXPECT_EQ(r["frames"], 1);
        EXPECT_EQ(r["row"], i + 1);
        rows.push_back(r);
    }
    json done = s.wait_event("bench_done");
    EXPECT_EQ(done["rows"], raster::MAPPER_COUNT);
    EXPECT_FALSE(done["interrupted"].get<bool>());
    EXPECT_GT(done["tsc_hz"].get<uint64_t>(), 0u);
    const int pages = done["pages"];
    ASSERT_EQ(pages, 1 + 2 + done["qr_codes"].get<int>()) << "the machine, the cube's table on two pages, the QR codes";
    ASSERT_GE(done["qr_codes"].get<int>(), 1);

    LoadedWorld host = load_world_file("scenes/cube.scene");
    const raster::TextColours colours = raster::text_colours(host.world->palette);
    std::string csv;
    for (int k = 0; k < pages; ++k) {
        SCOPED_TRACE("page " + std::to_string(k));
        json p = s.wait_event("bench_page");
        EXPECT_EQ(p["page"], k);
        EXPECT_EQ(p["of"], pages);
        const std::string stem = "page-" + std::to_string(k);
        if (p.contains("lines")) {
            std::vector<std::string> text = p["lines"];
            std::vector<lib::StrView> lines;
            for (const std::string& l : text) lines.push_back({l.data(), l.size()});
            IndexImage want{320, 240, std::vector<uint8_t>(320 * 240, 0)};
            raster::Target t = raster::linear_target(want.index.data(), 320, 240, 320);
            raster::fill_target(t, colours.paper);
            raster::draw_text_box(t, 0, 0, lines.data(), int(lines.size()), colours);
            expect_screendump(s, want, host.world->palette, stem);
            if (k == 0) {
                EXPECT_EQ(text[0], "modexlab on-screen bench");
            }
            if (k == 1) {
                EXPECT_EQ(text[0], "cube.scene, frames: 1 (page 1/2)");
                EXPECT_EQ(text[1], "mapper               inner   frame  err");
            }
        } else {
            const std::string qr = p["qr"];
            s.screendump(stem);
            EXPECT_EQ(zbar(s.run_dir() + "/" + stem + ".png"), qr) << "the QR code on screen reads as its part";
            const std::string head = "modexlab-bench part " + std::to_string(k - 2) + "/" + std::to_string(done["qr_codes"].get<int>()) + "\n";
            ASSERT_EQ(qr.rfind(head, 0), 0u) << qr.substr(0, 60);
            csv += qr.substr(head.size());
        }
        if (k + 1 < pages) s.send_key("right");
    }
    // the CSV: the machine, the header, then the rows as the events had them
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line.rfind("modexlab-bench,2,", 0), 0u) << line;
    EXPECT_NE(line.find(",tsc," + std::to_string(done["clock_hz"].get<uint64_t>()) + ","), std::string::npos) << line << ": the clock, named";
    EXPECT_EQ(done["clock"], "tsc");
    std::getline(in, line);
    EXPECT_EQ(line, "scene,mapper,pixels,polygons,inner_ticks,frame_ticks,max_footprint_error");
    for (const json& r : rows) {
        ASSERT_TRUE(std::getline(in, line));
        std::ostringstream want;
        want << "cube.scene," << r["mapper"].get<std::string>() << "," << r["pixels"] << "," << r["polygons"] << "," << r["ticks_inner"] << ","
             << r["ticks"] << ",";
        EXPECT_EQ(line.rfind(want.str(), 0), 0u) << line << " against " << want.str();
    }
    // Escape: back to the show; then the server: the bench command on the same frame gives the
    // same figures (icount)
    s.send_key("esc");
    s.ok("mode modex");
    for (const json& r : rows) {
        const std::string name = r["mapper"];
        const raster::Mapper* m = raster::find_mapper({name.data(), name.size()});
        json b = s.ok("bench 1 " + name + " " + raster::surface_name(raster::home_surface(*m)), [](const json&) {});
        EXPECT_EQ(b["pixels"], r["pixels"]) << name;
        EXPECT_EQ(b["polygons"], r["polygons"]) << name;
        EXPECT_EQ(b["ticks_inner"]["sum"], r["ticks_inner"]) << name;
        EXPECT_EQ(b["ticks"]["sum"], r["ticks"]) << name;
    }
}

// The progress line (the row, the scene, the mapper, and from the second row the time left) is
// drawn over every frame before it is shown, so every screendump during the bench has it: the line
// of the row just reported or of the next (the events say which line each row showed).
TEST(OnScreenBench, ProgressAndTheTimeLeftStayOnScreenThroughTheFlips) {
    // rows of 30 frames, shots taken a few frames into the first rows: then the row in hand is the
    // one after the event's, or still the event's own (its last frame not yet replaced)
    Session s(bench_boot(30));
    constexpr int ROWS = 10;
    std::vector<std::string> lines;  // by row, from 0
    std::vector<RgbImage> shots;     // after row k's event
    for (int i = 0; i <= ROWS; ++i) {
        const json r = s.wait_event("bench_row");
        lines.push_back(r["progress"]);
        if (i == ROWS) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(60));
        shots.push_back(s.screendump("during-" + std::to_string(i), false));
    }
    EXPECT_EQ(lines[0], "bench 1/" + std::to_string(raster::MAPPER_COUNT) + ": cube.scene " + raster::MAPPERS[0].name);
    for (size_t k = 1; k < lines.size(); ++k) {
        EXPECT_EQ(lines[k].rfind("bench " + std::to_string(k + 1) + "/", 0), 0u) << lines[k];
        EXPECT_NE(lines[k].find(", about "), std::string::npos) << lines[k];
        EXPECT_EQ(lines[k].substr(lines[k].size() - 5), " left") << lines[k];
    }
    const LoadedWorld host = load_world_file("scenes/cube.scene");
    const raster::TextColours colours = raster::text_colours(host.world->palette);
    // whether the shot shows `line` in its box at the top left, colour for colour
    auto shows = [&](const RgbImage& shot, const std::string& line) {
        IndexImage box{320, 240, std::vector<uint8_t>(320 * 240, 0)};
        std::vector<uint8_t> marked(320 * 240, 1);
        raster::Target t = raster::linear_target(box.index.data(), 320, 240, 320), m = raster::linear_target(marked.data(), 320, 240, 320);
        const lib::StrView l{line.data(), line.size()};
        raster::draw_text_box(t, 0, 0, &l, 1, colours);
        raster::draw_text_box(m, 0, 0, &l, 1, raster::TextColours{0, 0});  // (0 where the box is)
        const RgbImage want = screendump_of(box, host.world->palette);
        for (int y = 0; y < 240; ++y)
            for (int x = 0; x < 320; ++x)
                if (!marked[size_t(y) * 320 + size_t(x)] && !std::equal(want.at(2 * x, 2 * y), want.at(2 * x, 2 * y) + 3, shot.at(2 * x, 2 * y))) return false;
        return true;
    };
    for (size_t k = 0; k < shots.size(); ++k) {
        bool shown = false;
        for (size_t j = k; j <= k + 1 && !shown; ++j) shown = shows(shots[k], lines[j]);
        EXPECT_TRUE(shown) << "after row " << k + 1 << ": neither '" << lines[k] << "' nor the next row's line";
    }
}

// B in the show starts it over every scene; Escape stops it after the frame in hand, its pages show
// what it measured so far; Escape again goes back to the show, where the key's event arrives.
TEST(OnScreenBench, TheBKeyStartsItAndEscapeStopsIt) {
    SessionOptions o = options_for_this_test();
    o.append = "boot=demo scene=cube.scene mapper=exact";
    Session s(o);
    s.send_key("b");
    json first = s.wait_event("bench_row");
    EXPECT_EQ(first["row"], 1);
    EXPECT_GT(first["of"].get<int>(), raster::MAPPER_COUNT) << "every scene, not only the one shown";
    s.send_key("esc");
    json row = first;
    while (!row["interrupted"].get<bool>()) row = s.wait_event("bench_row");
    json done = s.wait_event("bench_done");
    EXPECT_TRUE(done["interrupted"].get<bool>());
    EXPECT_EQ(done["rows"], row["row"]);
    json page = s.wait_event("bench_page");
    EXPECT_EQ(page["page"], 0);
    s.send_key("esc");
    json key = s.wait_event("key");
    EXPECT_EQ(key["action"], "bench");
    EXPECT_EQ(key["scene"], "cube.scene") << "back to the show's scene";
    EXPECT_EQ(s.ok("hello")["mode"], "modex");
}

}  // namespace
