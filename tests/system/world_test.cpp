// System tests for 3D scenes: every demo scene at fixed frames, built in, loaded as a Multiboot
// module and uploaded, equals the host's frame pixel for pixel (screendump and readback); bad files
// are refused with the host's message while the kernel keeps serving; play reports every frame;
// the boot show plays scenes and gives way to the first command.
#include "tests/system/system.h"

#include <unistd.h>

#include <filesystem>
#include <map>

#include "qemu/tools/demo_scenes.h"
#include "qemu/accuracy/measure.h"

namespace {

using namespace systest;

std::string scene_path(const std::string& name) { return "scenes/" + name + ".scene"; }

// The kernel's shown page (screendump, in the scene's palette as QEMU widens it) and the page read
// back (palette indices, by its checksum) against the host's frame.
void expect_same_frame(Session& s, const IndexImage& want, const raster::Palette& palette, int page, const std::string& stem) {
    expect_screendump(s, want, palette, stem);
    EXPECT_EQ(s.readback_crc(page), crc32_of(want)) << stem << " readback: " << compare(s.readback(page), want).summary();
}

// Draws `frame` of the loaded scene with `mapper` into `page`, shows it, and compares.
void check_frame(Session& s, const LoadedWorld& host, int32_t frame, const std::string& mapper, const std::string& surface, int page,
                 const std::string& stem) {
    const raster::Mapper* m = raster::find_mapper({mapper.data(), mapper.size()});
    ASSERT_NE(m, nullptr);
    json r = s.ok("frame " + std::to_string(frame) + " " + mapper + " " + std::to_string(page) + " " + surface);
    raster::Axis axis = r["walker"] == "rows" ? raster::Axis::Rows : raster::Axis::Columns;
    auto f = world_frame(host, frame);
    raster::RenderStats stats;
    IndexImage want = render_world_frame(host, *f, *m, axis, &stats);
    EXPECT_EQ(r["polygons"], stats.polygons) << stem;
    EXPECT_EQ(r["pixels"], stats.pixels) << stem;
    EXPECT_EQ(r["rejected"], stats.rejected) << stem;
    EXPECT_EQ(r["culled"], f->stats.culled) << stem;
    EXPECT_EQ(r["clipped"], f->stats.clipped) << stem;
    s.ok("flip " + std::to_string(page));
    expect_same_frame(s, want, host.world->palette, page, stem);
}

TEST(Scenes3d, EveryBuiltInSceneEqualsTheHostAtFixedFrames) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    const std::vector<std::pair<std::string, std::string>> mappers = {
        {"exact", "linear"}, {"persp-subdiv-16", "planar"}, {"fast-affine", "linear"}, {"fast-columns", "vga"}, {"quake-subdiv16", "linear"},
        {"auto", "linear"}};
    int checked = 0;
    for (const DemoScene& d : demo_scenes()) {
        SCOPED_TRACE(d.name);
        LoadedWorld host = load_world_file(scene_path(d.name));
        json load = s.ok(std::string("load ") + d.name + ".scene");
        match_kernel_copies(host, load);
        EXPECT_EQ(load["origin"], "builtin");
        EXPECT_EQ(load["version"], 2);
        EXPECT_EQ(load["faces"], host.world->face_count);
        EXPECT_EQ(load["frames"], host.world->frames);
        const int32_t frames[2] = {37, host.world->frames / 2 + 11};
        for (int k = 0; k < 2; ++k) {
            const auto& [mapper, surface] = mappers[size_t(checked) % mappers.size()];
            check_frame(s, host, frames[k], mapper, surface, checked % 3, std::string(d.name) + "-" + std::to_string(frames[k]) + "-" + mapper);
            ++checked;
        }
    }
    EXPECT_EQ(checked, 2 * int(demo_scenes().size()));
}

TEST(Scenes3d, ModulesAndUploadsAreScenesToo) {
    SessionOptions o = options_for_this_test();
    // a module under a name of its own, and one that takes a built-in's name (it wins)
    o.modules = {"scenes/cube.scene cube-module.scene", "scenes/rotozoom.scene ball.scene"};
    Session s(o);
    EXPECT_EQ(s.boot_line()["modules"], 2);
    s.ok("mode modex");
    json files = s.ok("files");
    int modules = 0;
    for (const json& f : files["files"]) modules += f["origin"] == "module";
    EXPECT_EQ(modules, 2);

    json cube = s.ok("load cube-module.scene");
    EXPECT_EQ(cube["origin"], "module");
    LoadedWorld host_cube = load_world_file("scenes/cube.scene");
    check_frame(s, host_cube, 50, "persp-subdiv-8", "linear", 1, "cube-module-50");

    json ball = s.ok("load ball.scene");
    EXPECT_EQ(ball["origin"], "module") << "a module takes the place of a built-in of its name";
    EXPECT_EQ(ball["faces"], 1) << "it is the rotozoom quad";

    // an upload: a scene whose texture is a file uploaded under a path of our choosing
    std::string bmp = read_whole_file(build_dir() + "/scenes/freedoom/startan3.bmp");
    json up = s.upload_file("walls/stone.bmp", bmp);
    ASSERT_TRUE(up["ok"].get<bool>()) << up.dump();
    EXPECT_EQ(up["bytes"], bmp.size());
    std::string text = "modexlab-scene 2\ntexture stone file walls/stone.bmp\npalette stone\n"
                       "mesh quad\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 1\nvt 2 1\nvt 2 0\nvt 0 0\nf 1/1 2/2 3/3 4/4\nend\n"
                       "object q\nmesh quad\ntexture stone\nspin 0 0 1 30\nend\n"
                       "camera\nposition 0 0.3 2\ntarget 0 0 0\nend\n";
    json scene = s.upload_scene(text);
    ASSERT_TRUE(scene["ok"].get<bool>()) << scene.dump();
    EXPECT_EQ(scene["origin"], "upload");
    EXPECT_EQ(scene["palette"], "stone");
    // the host reads the same texture under the same name
    std::filesystem::path dir = std::filesystem::path(s.run_dir()) / "upload" / "walls";
    std::filesystem::create_directories(dir);
    std::filesystem::copy_file(build_dir() + "/scenes/freedoom/startan3.bmp", dir / "stone.bmp", std::filesystem::copy_options::overwrite_existing);
    LoadedWorld host = parse_world_text(text, "upload.scene", {s.run_dir() + "/upload"});
    check_frame(s, host, 20, "exact", "linear", 2, "upload-20");
    check_frame(s, host, 20, "hecker-steptable", "linear", 0, "upload-20-hecker");
}

TEST(Scenes3d, BadFilesAreRefusedWithTheHostsMessageAndTheKernelServesOn) {
    Session s(options_for_this_test());
    const std::string good = read_whole_file("scenes/cube.scene");
    struct Case {
        std::string text, want;
    };
    std::vector<Case> cases = {
        {"modexlab-scene 2\ntexture t checker 8 8\nmesh m\nv 0 0 0\nf 1/1 1/1 1/1\nend\n", ""},
        {"modexlab-scene 2\ntexture t file nowhere.bmp\n", ""},
        {good.substr(0, good.size() / 2), ""},
        {"modexlab-scene 9\n", ""},
        {good + "frames 0\n", ""},
    };
    for (Case& c : cases) {
        try {
            parse_world_text(c.text, "upload.scene", {"/nonexistent"});
            ADD_FAILURE() << "the host took a bad scene: " << c.text.substr(0, 60);
        } catch (const HarnessError& e) {
            c.want = e.what();  // "upload.scene:LINE: message"
        }
        json r = s.upload_scene(c.text);
        EXPECT_FALSE(r["ok"].get<bool>());
        std::string got = r.value("error", "");
        // the kernel says "upload.scene: line N: message"; the host "upload.scene:N: message", and
        // for a file not found, where it looked (a host's directories, which the kernel has not)
        std::string message = c.want.substr(c.want.find(": ") + 2);
        message = message.substr(0, message.find(" (looked in "));
        EXPECT_NE(got.find(message), std::string::npos) << "kernel: " << got << "\nhost: " << c.want;
        EXPECT_EQ(r.value("file", ""), "upload.scene");
    }
    // a texture file the decoder refuses
    json bad = s.upload_file("broken.bmp", "BM not really a bitmap");
    ASSERT_TRUE(bad["ok"].get<bool>());
    json r = s.upload_scene("modexlab-scene 2\ntexture t file broken.bmp\n");
    EXPECT_NE(r.value("error", "").find("texture 't' (broken.bmp): byte"), std::string::npos) << r.dump();
    // uploads that break the protocol
    EXPECT_NE(s.command("file x.bmp 10 0x12345678").value("error", "").find("upload stalled"), std::string::npos);
    EXPECT_NE(s.command("file x.bmp 99999999 0").value("error", "").find("bad length"), std::string::npos);
    EXPECT_NE(s.command("load nothing.scene").value("error", "").find("no file 'nothing.scene'"), std::string::npos);
    EXPECT_NE(s.command("frame 0 exact 0").value("error", "").find("Mode X"), std::string::npos);
    s.ok("mode modex");
    EXPECT_NE(s.command("frame 0 exact 0").value("error", "").find("no 3D scene"), std::string::npos) << "the failed loads left none";
    // and it still draws
    s.ok("load cube.scene");
    EXPECT_GT(s.ok("frame 10 exact 0")["pixels"].get<int>(), 1000);
}

TEST(Scenes3d, PlayReportsEveryFrameAndFlipsPages) {
    SessionOptions o = options_for_this_test();
    o.icount = true;
    Session s(o);
    s.ok("mode modex");
    s.ok("load mesh.scene");
    std::vector<json> events;
    json r = s.ok("play 12 fast-affine", [&](const json& e) { events.push_back(e); });
    ASSERT_EQ(events.size(), 12u);
    uint64_t pixels = 0;
    for (size_t i = 0; i < events.size(); ++i) {
        EXPECT_EQ(events[i]["event"], "frame");
        EXPECT_EQ(events[i]["n"], i);
        EXPECT_EQ(events[i]["page"], i % 2 == 0 ? 1 : 0) << "into the hidden page, then shown";
        EXPECT_GT(events[i]["pixels"].get<int>(), 1000);
        pixels += events[i]["pixels"].get<uint64_t>();
    }
    EXPECT_EQ(r["frames"], 12);
    EXPECT_EQ(r["pixels"], pixels);
    EXPECT_LE(r["ticks_min"].get<uint64_t>(), r["ticks_median"].get<uint64_t>());
    EXPECT_LE(r["ticks_median"].get<uint64_t>(), r["ticks_max"].get<uint64_t>());
    // the last frame drawn is on the screen
    LoadedWorld host = load_world_file("scenes/mesh.scene");
    auto f = world_frame(host, 11);
    expect_same_frame(s, render_world_frame(host, *f, *raster::find_mapper({"fast-affine", 11}), raster::Axis::Rows), host.world->palette,
                      events.back()["page"], "play-last");
    // icount: the same frame costs the same instructions every time
    json again = s.ok("play 12 fast-affine", [&](const json& e) { EXPECT_EQ(e["ticks"], events[e["n"].get<size_t>()]["ticks"]); });
    EXPECT_EQ(again["ticks"], r["ticks"]);
}

// Without a surface named, a mapper draws through its own: the VGA planes for those that write
// them (xsharp-column, the fast column loops), rows in RAM for the rest; the picture is the host's.
TEST(Scenes3d, AMapperDrawsThroughItsOwnSurfaceUnlessOneIsNamed) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    s.ok("load cube.scene");
    const LoadedWorld host = load_world_file(scene_path("cube"));
    int planar = 0;
    for (int i = 0; i < raster::MAPPER_COUNT; ++i) {
        const raster::Mapper& m = raster::MAPPERS[i];
        const json r = s.ok(std::string("frame 20 ") + m.name + " 1");
        EXPECT_EQ(r["surface"], raster::surface_name(raster::home_surface(m))) << m.name;
        if (raster::home_surface(m) == raster::Surface::Linear) continue;
        ++planar;
        s.ok("flip 1");
        auto f = world_frame(host, 20);
        expect_same_frame(s, render_world_frame(host, *f, m, raster::home_axis(m)), host.world->palette, 1, std::string("home-") + m.name);
    }
    EXPECT_GE(planar, 4) << "xsharp-column, xsharp-row-out, fast-columns, fast-table-columns";
}

// The background is palette index 0: with a scene palette whose entry 0 is red, what no polygon
// covers is red on the screen (docs/scene-format.md, "The background").
TEST(Scenes3d, TheBackgroundIsPaletteEntryZero) {
    std::string bmp(14 + 40 + 256 * 4 + 8 * 8, '\0');
    auto put = [&](size_t at, uint32_t v, int bytes) {
        for (int i = 0; i < bytes; ++i) bmp[at + size_t(i)] = char(v >> (8 * i));
    };
    bmp[0] = 'B', bmp[1] = 'M';
    put(2, uint32_t(bmp.size()), 4), put(10, 14 + 40 + 1024, 4), put(14, 40, 4), put(18, 8, 4), put(22, 8, 4), put(26, 1, 2), put(28, 8, 2);
    put(54, 0x00FF0000, 4);  // entry 0: red (B, G, R, 0)
    put(58, 0x0000FF00, 4);  // entry 1: green
    for (size_t i = 0; i < 64; ++i) bmp[14 + 40 + 1024 + i] = 1;
    const std::string scene = "modexlab-scene 2\ntexture t file red0.bmp\npalette t\nmesh quad\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                              "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\nend\nobject q\nmesh quad\ntexture t\ncull none\nend\n"
                              "camera\nposition 0 0 -6\ntarget 0 0 0\nend\n";
    Session s(options_for_this_test());
    s.ok("mode modex");
    ASSERT_TRUE(s.upload_file("red0.bmp", bmp)["ok"].get<bool>());
    ASSERT_TRUE(s.upload_scene(scene)["ok"].get<bool>());
    const json r = s.ok("frame 0 exact 1");
    ASSERT_GT(r["pixels"].get<int>(), 1000);
    ASSERT_LT(r["pixels"].get<int>(), 320 * 240 / 2);
    s.ok("flip 1");
    const RgbImage shot = s.screendump("background");
    EXPECT_EQ(std::vector<uint8_t>(shot.rgb.begin(), shot.rgb.begin() + 3), (std::vector<uint8_t>{255, 0, 0})) << "the corner, which no polygon covers";
    const size_t centre = 3 * (size_t(shot.height / 2) * size_t(shot.width) + size_t(shot.width / 2));
    EXPECT_EQ(std::vector<uint8_t>(shot.rgb.begin() + long(centre), shot.rgb.begin() + long(centre) + 3), (std::vector<uint8_t>{0, 255, 0})) << "the quad";
}

// The budget command: what auto draws to, until `budget scene` or the next load; auto at budget 0
// draws the reference's texels (only exact has bound 0 on a polygon it draws pixels of), and every
// picture equals the host's at the same budget, priced for each target; bad budgets are refused with
// the usage.
TEST(Scenes3d, TheBudgetCommandSetsWhatAutoDrawsTo) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    s.ok("load corridor.scene");
    LoadedWorld host = load_world_file(scene_path("corridor"));
    EXPECT_EQ(s.ok("budget")["source"], "scene");
    EXPECT_EQ(s.ok("budget")["budget"]["target"], "icount");
    for (const char* bad : {"budget -1", "budget x", "budget 1 maybe", "budget 1000001", "budget 1 exact p5", "budget 1 exact 486 more"}) {
        json r = s.command(bad);
        EXPECT_EQ(r["ok"], false) << bad;
        EXPECT_NE(r["error"].get<std::string>().find("usage: budget"), std::string::npos) << bad;
    }
    struct Asked {
        std::string word;
        double max_error;
        raster::CostTarget target;
    };
    const std::vector<Asked> budgets = {{"0", 0, raster::CostTarget::Icount},
                                        {"4", 4, raster::CostTarget::Icount},
                                        {"1", 1, raster::CostTarget::I486},
                                        {"1", 1, raster::CostTarget::Pentium},
                                        {"any", raster::ANY_ERROR, raster::CostTarget::Icount}};
    for (const auto& [word, max_error, target] : budgets) {
        const std::string name = raster::cost_target_name(target);
        json b = s.ok("budget " + word + " exact" + (target == raster::CostTarget::Icount ? "" : " " + name));
        EXPECT_EQ(b["source"], "command");
        EXPECT_EQ(b["budget"]["target"], name);
        json r = s.ok("frame 40 auto 1 linear");
        auto f = world_frame(host, 40);
        f->budget = raster::Budget{true, max_error, true, target};
        raster::RenderStats stats;
        IndexImage want = render_world_frame(host, *f, *raster::find_mapper("auto"), raster::Axis::Rows, &stats);
        uint64_t pixels = 0;
        for (const json& d : r["drawn_by"]) {
            pixels += d["pixels"].get<uint64_t>();
            if (max_error == 0 && d["mapper"] != "exact") {
                EXPECT_EQ(d["pixels"], 0) << d.dump();
            }
        }
        EXPECT_EQ(pixels, r["pixels"].get<uint64_t>());
        EXPECT_EQ(r["pixels"], stats.pixels) << word;
        s.ok("flip 1");
        expect_same_frame(s, want, host.world->palette, 1, "budget-" + word + "-" + name);
    }
    EXPECT_EQ(s.ok("budget scene")["source"], "scene");
    s.ok("budget 0.5");
    s.ok("load corridor.scene");
    json after = s.ok("budget");
    EXPECT_EQ(after["source"], "scene") << "a load goes back to the scene's budget";
    EXPECT_EQ(after["budget"]["max_error"], 1);
}

// Priced for the machine: the corridor's columns at any error and coverage, where fast-columns and
// fast-table-columns are both within the budget; a 486 pays the table's base + index read a clock
// and auto priced for it takes fast-columns, for the Pentium fast-table-columns (docs/accuracy.md,
// "auto on a 486 and on a Pentium"); each picture the host's priced the same.
TEST(Scenes3d, AutoPricedForEachTargetTakesItsCheapestColumns) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    s.ok("load corridor.scene");
    LoadedWorld host = load_world_file(scene_path("corridor"));
    for (raster::CostTarget target : {raster::CostTarget::I486, raster::CostTarget::Pentium}) {
        const std::string name = raster::cost_target_name(target);
        s.ok("budget any any " + name);
        const json r = s.ok("frame 0 auto 1 planar");
        std::map<std::string, uint64_t> pixels;
        for (const json& d : r["drawn_by"]) pixels[d["mapper"].get<std::string>()] += d["pixels"].get<uint64_t>();
        const std::string cheap = target == raster::CostTarget::I486 ? "fast-columns" : "fast-table-columns";
        const std::string dear = target == raster::CostTarget::I486 ? "fast-table-columns" : "fast-columns";
        EXPECT_GT(pixels[cheap] * 10, r["pixels"].get<uint64_t>() * 9) << name << ": " << r["drawn_by"].dump();
        EXPECT_LT(pixels[dear] * 100, r["pixels"].get<uint64_t>()) << name << ": " << r["drawn_by"].dump();
        auto f = world_frame(host, 0);
        f->budget = raster::Budget{true, raster::ANY_ERROR, false, target};
        const IndexImage want = render_world_frame(host, *f, *raster::find_mapper("auto"), raster::Axis::Columns);
        s.ok("flip 1");
        expect_same_frame(s, want, host.world->palette, 1, "priced-" + name);
    }
}

// The mesh at its budget: auto draws nearly every triangle as the torus's envelope proves (the
// kernel says how many, as many as the host's drawing of the same frame), the picture the host's.
TEST(Scenes3d, AutoDrawsTheMeshByItsEnvelopeAsTheHostDoes) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    s.ok("load mesh.scene");
    LoadedWorld host = load_world_file(scene_path("mesh"));
    json r = s.ok("frame 60 auto 1 linear");
    auto f = world_frame(host, 60);
    raster::RenderStats stats;
    IndexImage want = render_world_frame(host, *f, *raster::find_mapper("auto"), raster::Axis::Rows, &stats);
    EXPECT_EQ(r["enveloped"], stats.enveloped);
    EXPECT_GT(r["enveloped"].get<uint64_t>(), r["polygons"].get<uint64_t>() * 9 / 10) << r.dump();
    s.ok("flip 1");
    expect_same_frame(s, want, host.world->palette, 1, "mesh-envelope");
}

TEST(Scenes3d, TheBootShowPlaysAScene) {
    SessionOptions o = options_for_this_test();
    o.append = "boot=demo scene=cube.scene mapper=exact";
    Session s(o);
    EXPECT_EQ(s.boot_line()["boot"], "demo");
    // the show draws while nobody speaks: some frames later the screen holds the cube
    RgbImage dump;
    int lit = 0;
    for (int tries = 0; tries < 50 && lit < 1000; ++tries) {
        usleep(100000);
        dump = s.screendump("show");
        lit = 0;
        for (size_t i = 0; i < dump.rgb.size(); i += 3) lit += dump.rgb[i] | dump.rgb[i + 1] | dump.rgb[i + 2] ? 1 : 0;
    }
    EXPECT_GE(lit, 1000 * 4) << "the cube covers thousands of pixels (2x2 in the dump)";
    // the first command stops the show and is answered
    json hello = s.ok("hello");
    EXPECT_EQ(hello["mode"], "modex");
}

}  // namespace
