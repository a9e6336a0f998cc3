// The host tools as users run them: modexlab-render's output lines, files and error handling.
#include "tests/system/system.h"

#include "kernel/core/mapper.h"
#include "kernel/version.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace {

using namespace systest;

ToolRun run(const std::string& args) { return run_command(build_dir() + "/host/modexlab-render " + args); }

std::map<std::string, std::string> keys(const std::string& out) {
    std::map<std::string, std::string> k;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) {
        size_t sp = line.find(' ');
        if (sp != std::string::npos) k[line.substr(0, sp)] = line.substr(sp + 1);
    }
    return k;
}

std::string tmp(const std::string& name) {
    std::filesystem::create_directories(build_dir() + "/test-tmp/cli");
    return build_dir() + "/test-tmp/cli/" + name;
}

TEST(RenderTool, ComparesAMapperWithTheReference) {
    std::string png = tmp("affine.png"), diff = tmp("diff.png");
    std::filesystem::remove(png);
    std::filesystem::remove(diff);
    ToolRun r = run("scenes/screen/floor-perspective.scene --mapper affine --out " + png + " --compare --diff " + diff);
    ASSERT_EQ(r.status, 0) << r.out;
    auto k = keys(r.out);
    EXPECT_EQ(k["modexlab-render"], "1");
    EXPECT_EQ(k["mapper"], "affine rows");
    EXPECT_EQ(k["texture"], "checker 64x64 repeat");
    EXPECT_EQ(k["polygons_drawn"], "2");
    EXPECT_EQ(k["gaps"], "0");
    EXPECT_EQ(k["overdraw"], "0");
    EXPECT_EQ(k["pixels_drawn"], k["reference_pixels"]);
    EXPECT_GT(std::stoi(k["max_texel_error"]), 10) << "a floor from depth 1 to 8 is far from affine";
    for (const char* key : {"overlaps", "compared_pixels", "mean_texel_error", "share_exact", "share_within_one", "pixels_index_differs", "share_index_differs"})
        EXPECT_TRUE(k.count(key)) << key;
    RgbImage picture = load_image(png), difference = load_image(diff);
    EXPECT_EQ(picture.width, 320);
    EXPECT_EQ(picture.height, 240);
    EXPECT_EQ(difference.width, 320);
}

TEST(RenderTool, TheExactMapperHasNoError) {
    for (const char* axis : {"rows", "columns"}) {
        ToolRun r = run(std::string("scenes/screen/tunnel.scene --mapper exact --axis ") + axis + " --out " + tmp("exact.png") + " --compare");
        ASSERT_EQ(r.status, 0) << r.out;
        auto k = keys(r.out);
        EXPECT_EQ(k["max_texel_error"], "0");
        EXPECT_EQ(k["pixels_index_differs"], "0");
        EXPECT_EQ(k["share_exact"], "1.000000");
    }
    ToolRun ref = run("scenes/screen/tunnel.scene --mapper reference --out " + tmp("reference.png"));
    ASSERT_EQ(ref.status, 0) << ref.out;
    EXPECT_EQ(keys(ref.out)["mapper"], "reference");
}

TEST(RenderTool, Compares3dFramesPolygonByPolygon) {
    std::map<std::string, double> mean;
    for (const char* m : {"exact", "persp-subdiv-8", "affine"}) {
        ToolRun r = run(std::string("scenes/corridor.scene --frame 45 --mapper ") + m + " --out " + tmp("corridor.png") + " --compare");
        ASSERT_EQ(r.status, 0) << r.out;
        auto k = keys(r.out);
        EXPECT_EQ(k["frame"], "45");
        EXPECT_EQ(k["gaps"], "0") << m;
        EXPECT_EQ(k["overdraw"], "0") << m;
        EXPECT_EQ(k["reference_pixels"], "76800") << m << ": the corridor fills the screen";
        mean[m] = std::stod(k["mean_texel_error"]);
        if (std::string(m) == "exact") {
            EXPECT_EQ(k["max_texel_error"], "0");
        }
    }
    EXPECT_EQ(mean["exact"], 0.0);
    EXPECT_GT(mean["persp-subdiv-8"], 0.0);
    EXPECT_GT(mean["affine"], 10 * mean["persp-subdiv-8"]) << "the corridor is the perspective stress case";
}

TEST(RenderTool, BadInputGetsAClearError) {
    ToolRun unknown = run("scenes/screen/tunnel.scene --mapper marble --out " + tmp("x.png"));
    EXPECT_EQ(unknown.status, 2);
    EXPECT_NE(unknown.out.find("unknown mapper 'marble' (the mappers, the nearest first: "), std::string::npos) << unknown.out;
    EXPECT_NE(run("scenes/screen/tunnel.scene --mapper fastaffine --compare").out.find("the nearest first: fast-affine, affine,"), std::string::npos);
    for (int m = 0; m < raster::MAPPER_COUNT; ++m)
        EXPECT_NE(unknown.out.find(std::string(" ") + raster::MAPPERS[m].name), std::string::npos) << "lists " << raster::MAPPERS[m].name;
    EXPECT_EQ(run("scenes/screen/tunnel.scene --mapper exact").status, 2) << "no --out and no --compare";
    EXPECT_EQ(run("--mapper exact --out " + tmp("x.png")).status, 2) << "no scene";
    std::string bad = tmp("bad.scene");
    std::ofstream(bad) << "modexlab-scene 1\ntexture checker 64 64\ntriangle 1 2 3\n";
    ToolRun parse = run(bad + " --mapper exact --out " + tmp("x.png"));
    EXPECT_EQ(parse.status, 1);
    EXPECT_NE(parse.out.find(bad + ":3: expected 15 numbers"), std::string::npos) << parse.out;
    ToolRun missing = run(tmp("missing.scene") + " --mapper exact --out " + tmp("x.png"));
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.out.find(tmp("missing.scene") + ": cannot open (No such file or directory)"), std::string::npos) << missing.out;
    // a mapper that cannot take the scene's texture says so rather than drawing nothing
    ToolRun texture = run("scenes/screen/odd-texture.scene --mapper fast-affine --out " + tmp("x.png"));
    EXPECT_EQ(texture.status, 1);
    EXPECT_NE(texture.out.find("fast-affine cannot take this scene's texture (gradient 37x300 repeat)"), std::string::npos) << texture.out;
}

std::string harness_tool() { return build_dir() + "/host/modexlab"; }
std::string kernel_option() { return " --kernel " + build_dir() + "/kernel/modexlab.elf"; }

// A demo scene by its name, --option=value, --compare without a picture: what auto chose on a 3D
// frame (drawn_by, its pixels summing to what was drawn), and --diff's picture of a 3D frame, red
// exactly where the palette index differs.
TEST(RenderTool, TakesDemoNamesAndSaysWhatAutoChoseAndDiffs3dFrames) {
    const ToolRun r = run("corridor --mapper=auto --frame=0 --compare");
    ASSERT_EQ(r.status, 0) << r.out;
    auto k = keys(r.out);
    EXPECT_EQ(k["scene"], "scenes/corridor.scene");
    EXPECT_EQ(k["frame"], "0");
    std::istringstream lines(r.out);
    uint64_t pixels = 0, mappers = 0;
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("drawn_by ", 0) != 0) continue;
        std::istringstream f(line.substr(9));
        std::string name;
        uint64_t polygons = 0, drawn = 0;
        f >> name >> polygons >> drawn;
        EXPECT_NE(raster::find_mapper({name.data(), name.size()}), nullptr) << line;
        EXPECT_NE(name, "auto") << "auto names the mappers it chose";
        pixels += drawn, ++mappers;
    }
    EXPECT_GE(mappers, 2u) << r.out;
    EXPECT_EQ(std::to_string(pixels), k["pixels_drawn"]);

    const std::string diff = tmp("corridor-diff.png");
    std::filesystem::remove(diff);
    const ToolRun d = run("corridor --mapper fast-affine --compare --diff " + diff);
    ASSERT_EQ(d.status, 0) << d.out;
    auto dk = keys(d.out);
    ASSERT_EQ(dk["gaps"], "0");
    ASSERT_EQ(dk["overdraw"], "0");
    const RgbImage picture = load_image(diff);
    ASSERT_EQ(picture.width, 320);
    size_t red = 0;
    for (size_t i = 0; i + 2 < picture.rgb.size(); i += 3) red += picture.rgb[i] == 255 && picture.rgb[i + 1] == 0 && picture.rgb[i + 2] == 0;
    EXPECT_EQ(std::to_string(red), dk["pixels_index_differs"]);
    EXPECT_GT(red, 1000u) << "the corridor is far from affine";
}

// The harness's usage names the default mapper make run draws with: auto.
TEST(Tools, TheUsageSaysTheDefaultMapperIsAuto) {
    const ToolRun r = run_command(build_dir() + "/host/modexlab --help");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("with the mapper (default auto: the scene's budget)"), std::string::npos) << r.out;
}

// Every tool answers --version with its name and the version.
TEST(Tools, EveryToolSaysItsVersion) {
    for (const char* tool : {"modexlab", "modexlab-render", "modexlab-scene", "modexlab-wad", "modexlab-bench", "modexlab-gallery", "modexlab-extremes",
                             "modexlab-timing", "modexlab-profile"}) {
        const ToolRun r = run_command(build_dir() + "/host/" + tool + " --version");
        EXPECT_EQ(r.status, 0) << tool;
        EXPECT_EQ(r.out, std::string(tool) + " " MODEXLAB_VERSION "\n");
    }
}

// make run's arguments are checked before QEMU boots: an unknown scene or mapper is named with the
// names, the nearest first; a scene file's error is named by its file and line.
TEST(RunTool, ChecksTheSceneAndTheMapperBeforeBooting) {
    const ToolRun scene = run_command(harness_tool() + " run" + kernel_option() + " --scene corridr");
    EXPECT_EQ(scene.status, 2) << scene.out;
    EXPECT_NE(scene.out.find("no demo scene or scene file 'corridr' (the demo scenes, the nearest first: corridor, corridor-cut,"), std::string::npos)
        << scene.out;
    EXPECT_EQ(scene.out.find("modexlab run: booting"), std::string::npos) << scene.out;
    const ToolRun mapper = run_command(harness_tool() + " run" + kernel_option() + " --mapper fastaffine");
    EXPECT_EQ(mapper.status, 2) << mapper.out;
    EXPECT_NE(mapper.out.find("unknown mapper 'fastaffine' (the mappers, the nearest first: fast-affine, affine,"), std::string::npos) << mapper.out;
    EXPECT_EQ(mapper.out.find("modexlab run: booting"), std::string::npos) << mapper.out;
    const std::string bad = tmp("bad.scene");
    std::ofstream(bad) << "modexlab-scene 2\ntexture t file nosuch.bmp\n";
    const ToolRun file = run_command(harness_tool() + " run" + kernel_option() + " --scene " + bad);
    EXPECT_EQ(file.status, 1) << file.out;
    EXPECT_NE(file.out.find(bad + ":2: texture 't': no file 'nosuch.bmp' (looked in " + build_dir() + "/test-tmp/cli and " + build_dir() + "/scenes)"),
              std::string::npos)
        << file.out;
    EXPECT_EQ(file.out.find("modexlab run: booting"), std::string::npos) << file.out;
    // a near name where it looked is offered
    std::filesystem::create_directories(tmp("near"));
    std::filesystem::copy_file(build_dir() + "/scenes/freedoom/brown1.bmp", tmp("near/tiles.bmp"), std::filesystem::copy_options::overwrite_existing);
    std::ofstream(tmp("near/room.scene")) << "modexlab-scene 2\ntexture t file tile.bmp\n";
    const ToolRun near = run_command(harness_tool() + " run" + kernel_option() + " --scene " + tmp("near/room.scene"));
    EXPECT_EQ(near.status, 1) << near.out;
    EXPECT_NE(near.out.find("no file 'tile.bmp' (looked in " + tmp("near") + " and " + build_dir() + "/scenes; is it 'tiles.bmp'?)"), std::string::npos)
        << near.out;
}

// A scene of one's own with its own texture files plays in the kernel as the demo scenes do: the
// files go up under the names the scene gives them, and the last frame equals the host's.
TEST(RunTool, PlaysASceneFileOfOnesOwnWithItsTextures) {
    const std::string dir = tmp("own");
    std::filesystem::create_directories(dir + "/tex");
    for (const char* name : {"floor0_1", "ceil3_5", "startan3", "comptall", "brown1"})
        std::filesystem::copy_file(build_dir() + "/scenes/freedoom/" + name + ".bmp", dir + "/tex/" + name + ".bmp",
                                   std::filesystem::copy_options::overwrite_existing);
    std::string text = read_whole_file("scenes/freedoom.scene");
    for (size_t at; (at = text.find("file freedoom/")) != std::string::npos;) text.replace(at, 14, "file tex/");
    std::ofstream(dir + "/my-room.scene") << text;
    const ToolRun r = run_command(harness_tool() + " run" + kernel_option() + " --scene " + dir + "/my-room.scene --frames 2 --out " + dir + "/out");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("my-room"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" equal\n"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir + "/out/scene-my-room.png"));
}

// make run with a mapper that refuses every polygon of the scene says so, why, and which demo
// scenes it draws whole (for X-Sharp's DDA, which cannot wrap: corridor-cut), and fails.
TEST(RunTool, AMapperThatDrawsNothingSaysWhyAndWhereToGo) {
    const ToolRun r = run_command(harness_tool() + " run" + kernel_option() + " --out " + tmp("run-refused") + " --scene corridor --mapper xsharp-dda --frames 2");
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_NE(r.out.find("xsharp-dda Cannot draw this scene: refuses every polygon (it needs "), std::string::npos) << r.out;
    const size_t whole = r.out.find("the demo scenes it draws whole: ");
    ASSERT_NE(whole, std::string::npos) << r.out;
    EXPECT_NE(r.out.substr(whole, r.out.find('\n', whole) - whole).find("corridor-cut"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("modexlab run: xsharp-dda drew nothing of corridor\n"), std::string::npos) << r.out;
}

// make run's figures: drawing instructions a pixel (icount) and the last frame's footprint errors
// against the exact reference, as the host measures them; the closing line sums the run.
TEST(RunTool, SaysTheErrorAgainstTheReferenceAndTheInstructionsAPixel) {
    const ToolRun r = run_command(harness_tool() + " run" + kernel_option() + " --out " + tmp("run-figures") + " --scene corridor --mapper fast-affine --frames 3");
    ASSERT_EQ(r.status, 0) << r.out;
    const size_t row = r.out.find("\ncorridor ");
    ASSERT_NE(row, std::string::npos) << r.out;
    std::istringstream fields(r.out.substr(row + 1, r.out.find('\n', row + 1) - row - 1));
    std::string scene, frames, polygons, pixels, per_pixel, max_error, mean_error;
    fields >> scene >> frames >> polygons >> pixels >> per_pixel >> max_error >> mean_error;
    EXPECT_GT(std::stod(per_pixel), 3.0) << "fast-affine's loop alone is over 5 instructions a pixel";
    EXPECT_LT(std::stod(per_pixel), 50.0);
    const LoadedWorld host = load_world_file("scenes/corridor.scene");
    const raster::Mapper& m = *raster::find_mapper("fast-affine");
    const raster::AccuracyMetrics want = measure_world_frame(host, *world_frame(host, 2), m, raster::home_axis(m));
    char max_text[32], mean_text[32];
    std::snprintf(max_text, sizeof max_text, "%.3f", want.max_footprint_error);
    std::snprintf(mean_text, sizeof mean_text, "%.4f", want.mean_footprint_error);
    EXPECT_EQ(max_error, max_text) << r.out;
    EXPECT_EQ(mean_error, mean_text) << r.out;
    EXPECT_GT(want.max_footprint_error, 10.0) << "the corridor is far from affine";
    EXPECT_NE(r.out.find("fast-affine: 1 scene, 3 frames, " + per_pixel + " drawing instructions a pixel (icount), error against the exact reference max " +
                         max_error + ", mean " + mean_error + " footprints (the last frames); every screenshot equal to the host's"),
              std::string::npos)
        << r.out;
}

// make run MAPPER=xsharp-column: the mapper draws through its own surface (the VGA planes).
TEST(RunTool, AMapperThatWritesThePlanesPlaysWithoutASurfaceNamed) {
    const ToolRun r = run_command(harness_tool() + " run" + kernel_option() + " --scene cube --mapper xsharp-column --frames 2 --out " + tmp("run-planes"));
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find(" equal\n"), std::string::npos) << r.out;
}

// The tools find their build beside themselves: a copied tree boots its own kernel and writes its
// runs into its own build, and says where relative to the working directory.
TEST(ExecTool, ACopiedTreeRunsInItsOwnBuild) {
    const std::string tree = tmp("tree");
    std::filesystem::remove_all(tree);
    std::filesystem::create_directories(tree + "/build/host");
    std::filesystem::create_directories(tree + "/build/kernel");
    std::filesystem::copy_file(harness_tool(), tree + "/build/host/modexlab");
    std::filesystem::copy_file(build_dir() + "/kernel/modexlab.elf", tree + "/build/kernel/modexlab.elf");
    const ToolRun r = run_command("cd " + tree + " && env -u MODEXLAB_BUILD_DIR build/host/modexlab exec 'hello' screendump:shot 'exit 0'");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("\nscreendump build/runs/exec/shot.png (640x480)\n"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(tree + "/build/runs/exec/serial.log"));
    EXPECT_EQ(r.out.find(std::filesystem::current_path().string()), std::string::npos) << r.out;
}

// exec drives the show's keyboard: key:b starts the on-screen bench, wait: prints the events up to
// the one named, key:esc stops the bench.
TEST(ExecTool, KeysDriveTheShowAndWaitPrintsItsEvents) {
    const ToolRun r = run_command(harness_tool() + " exec" + kernel_option() +
                                  " --append 'boot=demo scene=cube.scene mapper=exact' key:b wait:bench_row key:esc wait:bench_done 'exit 0'");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("\nkey b\n{\"event\":\"bench_row\""), std::string::npos) << r.out;
    const size_t done = r.out.find("{\"event\":\"bench_done\"");
    ASSERT_NE(done, std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"interrupted\":true", done), std::string::npos) << r.out;
    EXPECT_EQ(run_command(harness_tool() + " exec" + kernel_option() + " key:nosuchkey").status, 1);
}

// exec passes the kernel's exit code on; a reply that is not ok makes it 1.
TEST(ExecTool, PassesTheKernelsExitCodeOn) {
    EXPECT_EQ(run_command(harness_tool() + " exec" + kernel_option() + " 'exit 3'").status, 3);
    EXPECT_EQ(run_command(harness_tool() + " exec" + kernel_option() + " 'exit 0'").status, 0);
    const ToolRun refused = run_command(harness_tool() + " exec" + kernel_option() + " 'nosuch' 'exit 0'");
    EXPECT_EQ(refused.status, 1) << refused.out;
}

}  // namespace
