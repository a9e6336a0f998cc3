// Under test: kernel/scene/scene.h.
// The screen-space scene format: what it accepts, and an error with a line number for everything else.
#include <gtest/gtest.h>

#include <cstring>

#include <filesystem>
#include <fstream>

#include "qemu/lib/error.h"
#include "qemu/harness/session.h"
#include "kernel/scene/scene_text.h"
#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

std::unique_ptr<Scene> parse_ok(const std::string& text) {
    auto s = std::make_unique<Scene>();
    ParseError e;
    EXPECT_TRUE(parse_scene(text.data(), text.size(), s.get(), &e)) << "line " << e.line << ": " << e.message;
    return s;
}

ParseError parse_error(const std::string& text) {
    auto s = std::make_unique<Scene>();
    ParseError e;
    EXPECT_FALSE(parse_scene(text.data(), text.size(), s.get(), &e)) << text;
    return e;
}

const std::string HEAD = "modexlab-scene 1\ntexture checker 64 64\n";

TEST(SceneFormat, ParsesTrianglesPolygonsAndSettings) {
    auto s = parse_ok("# a comment\n\n  modexlab-scene   1  # trailing comment\r\n"
                      "texture xor 256 128\nwrap clamp\n"
                      "triangle 1 2 1 0 0   3.5 4.25 2 -16 32.5   -5 6 0.5 1 1\n"
                      "polygon 4  0 0 1 0 0  10 0 1 1 0  10 10 1 1 1  0 10 1 0 1\n"
                      "\ttriangle\t0 0 1 0 0 1 0 1 0 0 0 1 1 0 0");
    EXPECT_EQ(s->texture_kind, TextureKind::Xor);
    EXPECT_EQ(s->texture_width, 256);
    EXPECT_EQ(s->texture_height, 128);
    EXPECT_EQ(s->wrap, Wrap::Clamp);
    ASSERT_EQ(s->polygon_count, 3);
    EXPECT_EQ(s->polygon_size[0], 3);
    EXPECT_EQ(s->polygon_size[1], 4);
    EXPECT_EQ(s->vertex_count, 10);
    EXPECT_EQ(s->vertices[1].x.raw, 896);   // 3.5 pixels
    EXPECT_EQ(s->vertices[1].y.raw, 1088);  // 4.25
    EXPECT_EQ(s->vertices[1].u, -16);
    EXPECT_EQ(s->vertices[1].v, 32.5);
    EXPECT_EQ(s->vertices[2].x.raw, -1280);
    EXPECT_EQ(s->vertices[2].w, 0.5);
}

TEST(SceneFormat, DecimalsAreExactAndSnapToTheGrid) {
    auto s = parse_ok(HEAD + "triangle 0.001953 0.001954 0.1 0.000001 -123456.789012   1 0 1 0 0   0 1 1 0 0\n");
    const Vertex& v = s->vertices[0];
    EXPECT_EQ(v.x.raw, 0);  // 0.001953 * 256 = 0.49997: rounds down
    EXPECT_EQ(v.y.raw, 1);  // 0.001954 * 256 = 0.50022: rounds up
    EXPECT_EQ(v.w, 0.1);    // the nearest double to 1/10, as everywhere
    EXPECT_EQ(v.u, 1e-6);
    EXPECT_EQ(v.v, -123456.789012);
}

TEST(SceneFormat, DefaultsToRepeat) { EXPECT_EQ(parse_ok(HEAD)->wrap, Wrap::Repeat); }

TEST(SceneFormat, EveryErrorNamesItsLine) {
    const std::pair<std::string, std::pair<int, std::string>> cases[] = {
        {"", {0, "empty file"}},
        {"# only a comment\n", {0, "empty file"}},
        {"modexlab-scene\n", {1, "not a modexlab scene"}},
        {"scene 1\n", {1, "not a modexlab scene"}},
        {"modexlab-scene 2\n", {1, "a version 2 (3D) scene"}},
        {"modexlab-scene 3\n", {1, "scene version '3' not supported"}},
        {"modexlab-scene 1\n", {0, "no 'texture' line"}},
        {HEAD + "texture checker 64 64\n", {3, "a second 'texture' line"}},
        {"modexlab-scene 1\ntexture marble 64 64\n", {2, "unknown texture 'marble'"}},
        {"modexlab-scene 1\ntexture checker 0 64\n", {2, "out of range"}},
        {"modexlab-scene 1\ntexture checker 64 1025\n", {2, "out of range"}},
        {"modexlab-scene 1\ntexture checker 64\n", {2, "usage: texture"}},
        {HEAD + "wrap mirror\n", {3, "usage: wrap"}},
        {HEAD + "triangel 0 0 1 0 0 1 0 1 0 0 0 1 1 0 0\n", {3, "unknown keyword 'triangel'"}},
        {HEAD + "\n\ntriangle 0 0 1 0 0 1 0 1 0 0 0 1 1 0\n", {5, "expected 15 numbers"}},
        {HEAD + "triangle 0 0 1 0 0 1 0 1 0 0 0 1 1 0 0 7\n", {3, "found 16"}},
        {HEAD + "triangle 0 0 1 0 0 1 0 1 0 0 0 1 1 0 x\n", {3, "bad number 'x' for v"}},
        {HEAD + "triangle 0 0 1 0 0 1 0 1 0 0 0 1 1e3 0 0\n", {3, "bad number '1e3' for w"}},
        {HEAD + "triangle 0 0 1 0 0 1 0 1 0 0 0 1 1 0.1234567 0\n", {3, "bad number"}},
        {HEAD + "triangle 0 0 1 0 0 1 0 1 0 0 0 1 1 1.2.3 0\n", {3, "bad number"}},
        {HEAD + "triangle 0 0 1 0 0 1 0 1 0 0 0 1 1 - 0\n", {3, "bad number"}},
        {HEAD + "triangle 0 0 1 0 0 1 0 1234567890123456 0 0 0 1 1 0 0\n", {3, "bad number"}},
        {HEAD + "triangle 0 0 0 0 0 1 0 1 0 0 0 1 1 0 0\n", {3, "w must lie within"}},
        {HEAD + "triangle 0 0 -1 0 0 1 0 1 0 0 0 1 1 0 0\n", {3, "w must lie within"}},
        {HEAD + "triangle 16384.1 0 1 0 0 1 0 1 0 0 0 1 1 0 0\n", {3, "x, y must lie within"}},
        {HEAD + "triangle 0 0 1 16777217 0 1 0 1 0 0 0 1 1 0 0\n", {3, "u, v must lie within"}},
        {HEAD + "polygon 2 0 0 1 0 0 1 0 1 0 0\n", {3, "usage: polygon N"}},
        {HEAD + "polygon 17\n", {3, "usage: polygon N"}},
        {HEAD + "polygon 4 0 0 1 0 0 1 0 1 0 0 0 1 1 0 0\n", {3, "expected 20 numbers"}},
        {HEAD + std::string("triangle 0 0 1 0 0 1 0 1 0 0 0 1 1 0 0\n\0", 41), {4, "binary data"}},
        {HEAD + std::string(3000, 'x') + "\n", {3, "line too long"}},
    };
    for (const auto& [text, want] : cases) {
        ParseError e = parse_error(text);
        EXPECT_EQ(e.line, want.first) << text.substr(0, 80) << " -> " << e.message;
        EXPECT_NE(std::string(e.message).find(want.second), std::string::npos) << text.substr(0, 80) << " -> " << e.message;
    }
}

// A parse error's message is never cut silently: one as long as a message can be is kept whole, a
// longer one ends saying it was cut.
TEST(SceneFormat, AnErrorTooLongForItsRoomSaysSo) {
    ParseError e;
    const std::string whole(lib::Fmt::CAPACITY, 'x'), longer(lib::Fmt::CAPACITY + 40, 'y');
    scene_text::fail(&e, 3, whole.c_str());
    EXPECT_EQ(std::string(e.message), whole);
    scene_text::fail(&e, 3, longer.c_str());
    const std::string got = e.message;
    EXPECT_EQ(got.size(), lib::Fmt::CAPACITY);
    EXPECT_EQ(got.substr(got.size() - std::strlen(lib::Fmt::CUT)), lib::Fmt::CUT);
}

TEST(SceneFormat, EnforcesTheLimits) {
    std::string text = HEAD;
    for (int i = 0; i <= MAX_SCENE_POLYGONS; ++i) text += "triangle 0 0 1 0 0 1 0 1 0 0 0 1 1 0 0\n";
    ParseError e = parse_error(text);
    EXPECT_EQ(e.line, 3 + MAX_SCENE_POLYGONS);
    EXPECT_NE(std::string(e.message).find("too many polygons"), std::string::npos) << e.message;
    std::string huge(MAX_SCENE_BYTES + 1, '\n');
    EXPECT_NE(std::string(parse_error(huge).message).find("file too large"), std::string::npos);
}

TEST(SceneFormat, EveryShippedSceneParses) {
    int n = 0;
    for (const auto& f : std::filesystem::directory_iterator("scenes/screen")) {
        if (f.path().extension() != ".scene") continue;
        EXPECT_NO_THROW(load_scene_file(f.path().string())) << f.path();
        ++n;
    }
    EXPECT_GT(n, 0);
}

TEST(SceneFormat, LoadErrorsNameTheFileAndLine) {
    std::string path = build_dir() + "/test-tmp/bad.scene";
    std::filesystem::create_directories(build_dir() + "/test-tmp");
    std::ofstream(path) << HEAD << "wrap sideways\n";
    try {
        load_scene_file(path);
        FAIL();
    } catch (const HarnessError& e) {
        EXPECT_EQ(std::string(e.what()), path + ":3: usage: wrap repeat|clamp");
    }
    EXPECT_THROW(load_scene_file(build_dir() + "/test-tmp/missing.scene"), HarnessError);
}

}  // namespace
