// System tests: the kernel renders screen-space scenes uploaded over COM1; its pictures equal the
// host build of the same mapper, pixel for pixel, by screendump and by readback.
#include "tests/system/system.h"

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "kernel/lib/encode.h"
#include "kernel/core/selftest.h"
#include "qemu/accuracy/measure.h"

namespace {

using namespace systest;

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string decimal(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f", x);
    return buf;
}

// Generated scenes: random triangles of every size, in the file format (so the upload and the
// parser are tested too). Subpixel positions print with 6 decimals and snap back exactly.
std::string random_scene(uint32_t seed) {
    std::mt19937 rng(seed);
    auto any = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    const char* kinds[] = {"checker", "grid", "xor", "gradient"};
    int32_t w = 1 << (rng() % 9), h = 1 + int32_t(rng() % 300);
    std::string s = "modexlab-scene 1\n# random scene " + std::to_string(seed) + "\ntexture " + kinds[seed % 4] + " " + std::to_string(w) + " " +
                    std::to_string(h) + "\nwrap " + (seed % 3 ? "repeat" : "clamp") + "\n";
    for (int k = 0; k < 30 + int(rng() % 60); ++k) {
        double cx = any(-20, 340), cy = any(-20, 260), size = std::exp(any(std::log(0.5), std::log(150.0)));
        s += "triangle";
        for (int i = 0; i < 3; ++i) {
            double x = std::round((cx + any(-size, size)) * 256) / 256, y = std::round((cy + any(-size, size)) * 256) / 256;
            s += "  " + decimal(x) + " " + decimal(y) + " " + decimal(std::exp(any(0, std::log(16.0)))) + " " + decimal(any(-400, 400)) + " " +
                 decimal(any(-400, 400));
        }
        s += "\n";
    }
    return s;
}

struct NamedScene {
    std::string name, text;
};

std::vector<NamedScene> test_scenes() {
    std::vector<NamedScene> out;
    std::vector<std::string> files;
    for (const auto& f : std::filesystem::directory_iterator("scenes/screen"))
        if (f.path().extension() == ".scene") files.push_back(f.path().string());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) out.push_back({std::filesystem::path(f).stem().string(), read_file(f)});
    for (uint32_t seed = 1; out.size() < 22; ++seed) out.push_back({"random-" + std::to_string(seed), random_scene(seed)});
    return out;
}

TEST(Render, KernelPicturesEqualTheHostsForEveryMapperOnEveryScene) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    json listed = s.ok("mappers")["mappers"];
    ASSERT_EQ(listed.size(), size_t(raster::MAPPER_COUNT));
    int compared = 0;
    std::vector<NamedScene> all = test_scenes();
    ASSERT_GE(all.size(), 20u);
    for (size_t i = 0; i < all.size(); ++i) {
        const NamedScene& sc = all[i];
        SCOPED_TRACE(sc.name);
        LoadedScene host = parse_scene_text(sc.text, sc.name);
        json up = s.upload_scene(sc.text);
        ASSERT_TRUE(up["ok"].get<bool>()) << up.dump();
        EXPECT_EQ(up["polygons"], host.scene->polygon_count);
        for (int m = 0; m < raster::MAPPER_COUNT; ++m) {
            const raster::Mapper& mapper = raster::MAPPERS[m];
            const json& surfaces = listed[size_t(m)]["surfaces"];
            ASSERT_FALSE(surfaces.empty()) << mapper.name;
            std::string surface = surfaces[(i + size_t(m)) % surfaces.size()];
            int page = int(i % 3);
            json r = s.command("render " + std::string(mapper.name) + " " + std::to_string(page) + " " + surface);
            if (!r["ok"].get<bool>()) {  // a texture the mapper cannot take (e.g. not 256 wide): the host agrees
                EXPECT_FALSE(mapper_takes(host, mapper)) << mapper.name << ": " << r.dump();
                continue;
            }
            raster::Axis axis = r["walker"] == "rows" ? raster::Axis::Rows : raster::Axis::Columns;
            raster::RenderStats host_stats;
            IndexImage want = render_mapper(host, mapper, axis, &host_stats);
            EXPECT_EQ(r["pixels"], host_stats.pixels) << mapper.name << " " << surface;
            EXPECT_EQ(r["spans"], host_stats.spans) << mapper.name << " " << surface;
            EXPECT_EQ(r["polygons"], host_stats.polygons) << mapper.name << " " << surface;
            s.ok("flip " + std::to_string(page));
            std::string stem = sc.name + "-" + mapper.name + "-" + surface;
            IndexImage got = s.screenshot(stem, MODE_X, default_palette(), false);  // (write_mismatch keeps a mismatch's pictures)
            Comparison c = compare(got, want);
            EXPECT_TRUE(c.equal()) << stem << ": " << c.summary() << "\n" << write_mismatch(s.run_dir(), stem, got, want, default_palette());
            if (std::string(mapper.name) == "exact") {  // and so the kernel's exact picture is the reference's
                auto ref = render_reference(host);
                EXPECT_TRUE(compare(got, IndexImage{ref->view.width, ref->view.height, ref->index}).equal()) << stem << " vs the reference";
            }
            // read back too: every page by its checksum, the first scene's first mappers whole (the
            // encoding's path, through each surface)
            if (i == 0 && m < 3) {
                Comparison rb = compare(s.readback(page), want);
                EXPECT_TRUE(rb.equal()) << stem << " readback: " << rb.summary();
            } else {
                EXPECT_EQ(s.readback_crc(page), crc32_of(want)) << stem << " readback: " << compare(s.readback(page), want).summary();
            }
            ++compared;
        }
    }
    EXPECT_GE(compared, int(all.size()) * 2);
}

TEST(Render, EverySurfaceGivesTheSamePictureForTheExactMapper) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    std::string text = read_file("scenes/screen/tunnel.scene");
    ASSERT_TRUE(s.upload_scene(text)["ok"].get<bool>());
    IndexImage want = render_mapper(parse_scene_text(text, "tunnel"), *raster::find_mapper({"exact", 5}), raster::Axis::Rows);
    int page = 0;
    for (const char* surface : {"linear", "planar", "vga"}) {
        s.ok(std::string("render exact ") + std::to_string(page) + " " + surface);
        s.ok("flip " + std::to_string(page));
        EXPECT_TRUE(compare(s.screenshot(std::string("tunnel-") + surface, MODE_X, default_palette()), want).equal()) << surface;
        page = (page + 1) % 3;
    }
}

TEST(Render, BadUploadsAreRefusedWithTheHostsMessageAndTheSceneStays) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    EXPECT_FALSE(s.command("render exact 0")["ok"].get<bool>()) << "no scene yet";
    std::string good = read_file("scenes/screen/rotated-quad.scene");
    ASSERT_TRUE(s.upload_scene(good)["ok"].get<bool>());

    std::string bad = "modexlab-scene 1\ntexture checker 64 64\ntriangle 0 0 1 0 0  1 0 1 0 0  0 1 0 0 0\n";
    json r = s.upload_scene(bad);
    EXPECT_FALSE(r["ok"].get<bool>());
    EXPECT_EQ(r["line"], 3);
    auto scene = std::make_unique<raster::Scene>();
    raster::ParseError e;
    ASSERT_FALSE(raster::parse_scene(bad.data(), bad.size(), scene.get(), &e));
    EXPECT_EQ(r["error"].get<std::string>(), "upload.scene: line 3: " + std::string(e.message)) << "kernel and host say the same";

    // a wrong checksum
    r = s.raw("scene " + std::to_string(good.size()) + " 0x12345678\n" + good);
    EXPECT_FALSE(r["ok"].get<bool>());
    EXPECT_NE(r["error"].get<std::string>().find("checksum mismatch"), std::string::npos);
    // a length out of range: refused before any byte is read
    EXPECT_FALSE(s.command("scene 0 0")["ok"].get<bool>());
    EXPECT_FALSE(s.command("scene 5000000 0")["ok"].get<bool>());
    EXPECT_FALSE(s.command("render marble 0")["ok"].get<bool>());
    EXPECT_FALSE(s.command("render exact 0 sideways")["ok"].get<bool>());

    // the good scene is still the current one
    s.ok("render exact 1 vga");
    s.ok("flip 1");
    IndexImage want = render_mapper(parse_scene_text(good, "good"), *raster::find_mapper({"exact", 5}), raster::Axis::Columns);
    EXPECT_TRUE(compare(s.screenshot("still-good", MODE_X, default_palette()), want).equal());
}

TEST(Render, AStalledUploadTimesOutAndTheServerCarriesOn) {
    Session s(options_for_this_test());
    std::string text = read_file("scenes/screen/rotated-quad.scene");
    char crc[16];
    std::snprintf(crc, sizeof crc, "0x%08x", lib::crc32(0, reinterpret_cast<const uint8_t*>(text.data()), text.size()));
    json r = s.raw("scene " + std::to_string(text.size() + 10) + " " + crc + "\n" + text);  // 10 bytes never come
    EXPECT_FALSE(r["ok"].get<bool>());
    EXPECT_NE(r["error"].get<std::string>().find("upload stalled"), std::string::npos) << r.dump();
    EXPECT_TRUE(s.ok("hello")["ok"].get<bool>());
}

}  // namespace

namespace {

using namespace systest;

TEST(Mappers, TheKernelListsTheRegistry) {
    Session s(options_for_this_test());
    json r = s.ok("mappers");
    ASSERT_EQ(r["mappers"].size(), size_t(raster::MAPPER_COUNT));
    for (int i = 0; i < raster::MAPPER_COUNT; ++i) {
        const json& m = r["mappers"][size_t(i)];
        EXPECT_EQ(m["name"], raster::MAPPERS[i].name);
        EXPECT_EQ(m["family"], raster::MAPPERS[i].family);
        EXPECT_EQ(m["promise"], raster::MAPPERS[i].promise);
        EXPECT_EQ(m["exact_coverage"], raster::MAPPERS[i].guarantee.exact_coverage);
        EXPECT_EQ(m["max_error"], raster::MAPPERS[i].guarantee.max_error);
        EXPECT_EQ(m["max_error_flat"], raster::MAPPERS[i].guarantee.max_error_flat);
        EXPECT_FALSE(m["walkers"].empty());
    }
}

TEST(Mappers, TheKernelSelftestComparesEveryNasmLoopWithItsTwin) {
    Session s(options_for_this_test());
    json text_mode = s.ok("selftest 100");
    EXPECT_FALSE(text_mode["vga_loops_checked"].get<bool>()) << "loops that program the VGA need Mode X";
    s.ok("mode modex");
    json r = s.ok("selftest 3000");
    EXPECT_TRUE(r["vga_loops_checked"].get<bool>());
    const raster::Mapper* loops[32];
    int count = raster::checked_loops(loops, 32);
    ASSERT_EQ(r["loops"].size(), size_t(count)) << "every loop with a NASM twin";
    for (int i = 0; i < count; ++i) EXPECT_EQ(r["loops"][size_t(i)]["loop"], loops[i]->name);
    for (const json& loop : r["loops"]) {
        EXPECT_EQ(loop["cases"], 3000) << loop.dump();
        EXPECT_EQ(loop["mismatches"], 0) << loop.dump();
        EXPECT_GT(loop["pixels"].get<uint32_t>(), 100000u) << loop.dump();
    }
    EXPECT_FALSE(s.command("selftest 0")["ok"].get<bool>());
}

TEST(Mappers, AsmAndTwinDrawTheSamePictureInTheKernel) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    // a 256 x 256 texture with coordinates inside it: every mapper draws it
    ASSERT_TRUE(s.upload_scene(read_file("scenes/screen/mesh-grid.scene"))["ok"].get<bool>());
    json listed = s.ok("mappers")["mappers"];  // the kernel's registry knows which loops it has in NASM
    int with_asm = 0;
    for (const json& m : listed) {
        std::string name = m["name"];
        // a loop shared with an earlier mapper (persp-subdiv-N, constant-depth, persp-adaptive-B)
        // is checked through every surface there, here through the first only
        const bool shared = m.contains("asm_loop") && m["asm_loop"] != name;
        EXPECT_EQ(m.contains("asm_loop"), m["asm"].get<bool>()) << name;
        for (const json& surface_json : m["surfaces"]) {
            if (shared && surface_json != m["surfaces"][0]) continue;
            std::string surface = surface_json;
            json a = s.ok("render " + name + " 0 " + surface + " asm");
            bool asm_here = m["asm"].get<bool>() && (surface == "vga" || name != "xsharp-row-out");
            EXPECT_EQ(a["loop"], asm_here ? "asm" : "twin") << name << " " << surface;
            with_asm += asm_here;
            json t = s.ok("render " + name + " 1 " + surface + " twin");
            EXPECT_EQ(t["loop"], "twin");
            // the two pages by their checksums; where they differ, the pictures say how
            EXPECT_EQ(s.readback_crc(1), s.readback_crc(0)) << name << " " << surface << ": " << compare(s.readback(1), s.readback(0)).summary();
        }
    }
    EXPECT_GT(with_asm, 0);
    EXPECT_FALSE(s.command("render exact 0 vga fastest")["ok"].get<bool>());
}

}  // namespace
