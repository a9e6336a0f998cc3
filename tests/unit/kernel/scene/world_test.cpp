// Under test: kernel/scene/world.h.
// Version 2 (3D) scenes: the parser, its limits and every error it names, texture files through the
// resolver, the palette remap, and the arithmetic the frames rest on (sine, cosine, rotations).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "kernel/scene/world.h"
#include "tests/unit/kernel/scene/texture_files.h"

namespace {

using namespace raster;

struct Files {
    std::map<std::string, std::vector<uint8_t>> files;
    FileResolver resolver() const {
        FileResolver r;
        r.context = this;
        r.find = [](const void* ctx, lib::StrView name, const uint8_t** data, size_t* size) {
            const auto& f = static_cast<const Files*>(ctx)->files;
            auto it = f.find(std::string(name.data, name.size));
            if (it == f.end()) return false;
            *data = it->second.data(), *size = it->second.size();
            return true;
        };
        return r;
    }
};

struct Parsed {
    std::unique_ptr<HostWorld> world = std::make_unique<HostWorld>();
    ParseError error;
    bool ok = false;
};

Parsed parse(const std::string& text, const Files& files = Files{}) {
    Parsed p;
    p.ok = parse_world(text.data(), text.size(), files.resolver(), p.world.get(), &p.error);
    return p;
}

const std::string QUAD_MESH =
    "mesh quad\n"
    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
    "vt 0 1\nvt 1 1\nvt 1 0\nvt 0 0\n"
    "f 1/1 2/2 3/3 4/4\n"
    "end\n";
const std::string CAMERA = "camera\nposition 0 0 5\ntarget 0 0 0\nend\n";
const std::string MINIMAL = "modexlab-scene 2\ntexture t checker 64 64\n" + QUAD_MESH + "object a\nmesh quad\ntexture t\nend\n" + CAMERA;

TEST(World, ParsesEveryPart) {
    Files files;
    texfiles::Picture pic = texfiles::random_picture(16, 8, 1);
    files.files["tex/brick.bmp"] = texfiles::encode_bmp(pic, texfiles::BmpKind::Plain);
    std::string text = "modexlab-scene 2\n"
                       "# two textures, one from a file\n"
                       "texture grid numbered 128 64\n"
                       "texture brick file tex/brick.bmp\n"
                       "palette default\n" +
                       QUAD_MESH +
                       "object floor\n  mesh quad\n  texture brick\n  wrap clamp\n  cull none\n  position 1 2 3\n  rotate 1 0 0 -90\n"
                       "  scale 2.5\n  spin 0 1 0 45\n  key 0 0 0 0\n  key 2 0 0 -4\nend\n"
                       "object wall\nmesh quad\ntexture grid\nend\n"
                       "camera\n  position 0 1 5\n  target 0 0 0\n  up 0 1 0\n  fov 75\n  near 0.25\n  far 500\n"
                       "  key 0 0 1 5 0 0 0\n  key 4 0 1 9 0 0 -1\nend\n"
                       "budget max-error 1 coverage exact\n"
                       "frames 90\n";
    Parsed p = parse(text, files);
    ASSERT_TRUE(p.ok) << p.error.line << ": " << p.error.message;
    const World& w = *p.world;
    ASSERT_EQ(w.texture_count, 2);
    EXPECT_EQ(w.textures[0].source, TextureSource::Procedural);
    EXPECT_EQ(w.textures[0].kind, TextureKind::Numbered);
    EXPECT_EQ(w.textures[0].width, 128);
    EXPECT_EQ(w.textures[1].source, TextureSource::File);
    EXPECT_STREQ(w.textures[1].file, "tex/brick.bmp");
    EXPECT_EQ(w.textures[1].width, 16);
    EXPECT_EQ(w.textures[1].offset, 128u * 64u);
    EXPECT_EQ(w.texel_count, 128u * 64u + 16u * 8u);
    ASSERT_EQ(w.mesh_count, 1);
    EXPECT_EQ(w.meshes[0].position_count, 4);
    EXPECT_EQ(w.meshes[0].face_count, 1);
    EXPECT_EQ(w.faces[0].count, 4);
    EXPECT_EQ(w.corners[2].position, 2);
    EXPECT_EQ(w.corners[2].uv, 2);
    EXPECT_EQ(w.uvs[0].v, 1.0);
    ASSERT_EQ(w.object_count, 2);
    const Object& o = w.objects[0];
    EXPECT_EQ(o.texture, 1);
    EXPECT_EQ(o.wrap, Wrap::Clamp);
    EXPECT_EQ(o.cull, Cull::None);
    EXPECT_EQ(o.position.z, 3.0);
    EXPECT_EQ(o.rotate_degrees, -90.0);
    EXPECT_EQ(o.scale, 2.5);
    EXPECT_EQ(o.spin_degrees_per_second, 45.0);
    ASSERT_EQ(o.key_count, 2);
    EXPECT_EQ(o.keys[1].position.z, -4.0);
    EXPECT_EQ(w.objects[1].cull, Cull::Back);
    EXPECT_EQ(w.objects[1].wrap, Wrap::Repeat);
    EXPECT_EQ(w.camera.fov_degrees, 75.0);
    EXPECT_EQ(w.camera.near, 0.25);
    EXPECT_EQ(w.camera.key_count, 2);
    EXPECT_EQ(w.camera.keys[1].target.z, -1.0);
    EXPECT_TRUE(w.budget.given);
    EXPECT_EQ(w.budget.max_error, 1);
    EXPECT_TRUE(w.budget.exact_coverage);
    EXPECT_EQ(w.frames, 90);
    // the default palette: the procedural texture unchanged, the image's colours mapped to their nearest
    std::vector<uint8_t> grid(128 * 64);
    generate_texture(TextureKind::Numbered, 128, 64, grid.data());
    EXPECT_TRUE(std::equal(grid.begin(), grid.end(), w.texels));
    const Palette& def = palette(PaletteId::Default);
    for (int i = 0; i < 16 * 8; ++i) {
        const uint8_t* rgb = pic.palette[pic.pixels[size_t(i)]];
        Rgb6 want{uint8_t(rgb[0] >> 2), uint8_t(rgb[1] >> 2), uint8_t(rgb[2] >> 2)};
        Rgb6 got = def.entry[w.texels[128 * 64 + i]];
        auto d2 = [](Rgb6 a, Rgb6 b) { return (a.r - b.r) * (a.r - b.r) + (a.g - b.g) * (a.g - b.g) + (a.b - b.b) * (a.b - b.b); };
        for (int k = 0; k < 256; ++k) ASSERT_LE(d2(got, want), d2(def.entry[k], want)) << "texel " << i << " is not the nearest colour";
    }
}

// An image tiled to a larger size (the classics' 256 x 256 from a 64 x 64 flat): whole copies of it,
// row y of the result row y mod h of the image, in the image's own palette mapping.
TEST(World, AnImageTilesToAWholeMultipleOfItsSize) {
    Files files;
    texfiles::Picture pic = texfiles::random_picture(8, 4, 5);
    files.files["small.bmp"] = texfiles::encode_bmp(pic, texfiles::BmpKind::Plain);
    Parsed once = parse("modexlab-scene 2\ntexture s file small.bmp\n" + QUAD_MESH + "object a\nmesh quad\ntexture s\nend\n" + CAMERA, files);
    Parsed tiled = parse("modexlab-scene 2\ntexture c checker 4 4\ntexture s file small.bmp tile 32 12\n" + QUAD_MESH +
                             "object a\nmesh quad\ntexture s\nend\n" + CAMERA,
                         files);
    ASSERT_TRUE(once.ok) << once.error.message;
    ASSERT_TRUE(tiled.ok) << tiled.error.message;
    const WorldTexture& t = tiled.world->textures[1];
    EXPECT_EQ(t.width, 32);
    EXPECT_EQ(t.height, 12);
    EXPECT_EQ(t.offset, 16u);
    EXPECT_EQ(tiled.world->texel_count, 16u + 32u * 12u);
    const uint8_t* image = once.world->texels;
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 32; ++x) ASSERT_EQ(tiled.world->texels[16 + y * 32 + x], image[(y % 4) * 8 + x % 8]) << x << ", " << y;
    // the procedural texture before it is untouched
    std::vector<uint8_t> checker(16);
    generate_texture(TextureKind::Checker, 4, 4, checker.data());
    EXPECT_TRUE(std::equal(checker.begin(), checker.end(), tiled.world->texels));
}

TEST(World, ThePaletteCanComeFromAnImage) {
    Files files;
    texfiles::Picture pic = texfiles::random_picture(8, 8, 2);
    for (int i = 0; i < 256; ++i) pic.palette[i][0] = uint8_t(i), pic.palette[i][1] = 0, pic.palette[i][2] = 0;  // reds: 64 distinct levels, each 4 times
    files.files["p.pcx"] = texfiles::encode_pcx(pic);
    Parsed p = parse("modexlab-scene 2\ntexture img file p.pcx\ntexture c checker 16 16\npalette img\n" + QUAD_MESH +
                         "object a\nmesh quad\ntexture img\nend\n" + CAMERA,
                     files);
    ASSERT_TRUE(p.ok) << p.error.message;
    const World& w = *p.world;
    EXPECT_EQ(w.palette_texture, 0);
    for (int i = 0; i < 256; ++i) EXPECT_EQ(w.palette.entry[i].r, i >> 2);
    // each texel becomes the first entry with its colour
    for (int i = 0; i < 64; ++i) EXPECT_EQ(w.texels[i], (pic.pixels[size_t(i)] >> 2) << 2) << i;
    // the checker's white (default palette 15: 63, 63, 63) becomes the brightest red, its blue (1) black
    EXPECT_EQ(w.texels[64], 252);
    EXPECT_EQ(w.texels[64 + 8], 0);
}

// The budget: decimal footprints or any, the target auto prices for; without the line, the default
// auto draws to.
TEST(World, ReadsTheBudget) {
    const std::string head = "modexlab-scene 2\ntexture t checker 8 8\n" + QUAD_MESH + "object a\nmesh quad\ntexture t\nend\n" + CAMERA;
    Parsed quarter = parse(head + "budget max-error 0.25 coverage any\n");
    ASSERT_TRUE(quarter.ok) << quarter.error.message;
    EXPECT_TRUE(quarter.world->budget.given);
    EXPECT_EQ(quarter.world->budget.max_error, 0.25);
    EXPECT_FALSE(quarter.world->budget.exact_coverage);
    EXPECT_EQ(quarter.world->budget.target, CostTarget::Icount);
    for (CostTarget t : {CostTarget::Icount, CostTarget::I486, CostTarget::Pentium}) {
        Parsed priced = parse(head + "budget max-error 2 coverage exact target " + cost_target_name(t) + "\n");
        ASSERT_TRUE(priced.ok) << priced.error.message;
        EXPECT_EQ(priced.world->budget.target, t);
        EXPECT_EQ(priced.world->budget.max_error, 2);
    }
    Parsed any = parse(head + "budget max-error any coverage exact\n");
    ASSERT_TRUE(any.ok) << any.error.message;
    EXPECT_LT(any.world->budget.max_error, 0);
    EXPECT_TRUE(any.world->budget.exact_coverage);
    Parsed none = parse(head);
    ASSERT_TRUE(none.ok) << none.error.message;
    EXPECT_FALSE(none.world->budget.given);
    EXPECT_EQ(none.world->budget.max_error, DEFAULT_BUDGET.max_error);
    EXPECT_EQ(none.world->budget.exact_coverage, DEFAULT_BUDGET.exact_coverage);
}

TEST(World, EveryErrorNamesItsLine) {
    Files files;
    files.files["ok.bmp"] = texfiles::encode_bmp(texfiles::random_picture(4, 4, 3), texfiles::BmpKind::Plain);
    files.files["bad.bmp"] = {'B', 'M', 1, 2};
    const std::string H = "modexlab-scene 2\n";
    const std::string T = H + "texture t checker 64 64\n";
    const std::string TM = T + QUAD_MESH;
    const std::pair<std::string, std::pair<int, std::string>> cases[] = {
        {"modexlab-scene 1\ntexture checker 8 8\n", {1, "a version 1 (screen-space) scene"}},
        {H, {0, "no objects"}},
        {TM + "object a\nmesh quad\ntexture t\nend\n", {0, "no camera block"}},
        {H + "texture t checker 64\n", {2, "usage: texture NAME"}},
        {H + "texture t marble 64 64\n", {2, "unknown texture kind 'marble'"}},
        {H + "texture t checker 0 64\n", {2, "out of range"}},
        {H + "texture b@d checker 8 8\n", {2, "bad texture name 'b@d'"}},
        {T + "texture t xor 8 8\n", {3, "a second texture named 't'"}},
        {H + "texture f file missing.bmp\n", {2, "texture 'f': no file 'missing.bmp'"}},
        {H + "texture f file ../up.bmp\n", {2, "bad file name '../up.bmp'"}},
        {H + "texture f file /abs.bmp\n", {2, "bad file name '/abs.bmp'"}},
        {H + "texture f file bad.bmp\n", {2, "texture 'f' (bad.bmp): byte"}},
        {H + "texture f file ok.bmp tile 6 8\n", {2, "texture 'f': tile 6 x 8 is not whole copies of its 4 x 4 image"}},
        {H + "texture f file ok.bmp tile 8 2048\n", {2, "tile size '8 2048' out of range"}},
        {H + "texture f file ok.bmp tiles 8 8\n", {2, "usage: texture NAME"}},
        {H + "texture f file ok.bmp tile 8\n", {2, "usage: texture NAME"}},
        {H + "texture a checker 1024 1024\ntexture b checker 1024 1024\ntexture c checker 1024 1024\ntexture d checker 1024 1024\ntexture e checker 8 8\n",
         {6, "textures too large together"}},
        {T + "palette t\n", {3, "is procedural"}},
        {T + "palette nothing\n", {3, "no texture named 'nothing'"}},
        {H + "texture i file ok.bmp\npalette i\npalette default\n", {4, "a second palette line"}},
        {T + "mesh m\nv 0 0 0\nend\n", {5, "mesh 'm' has no faces"}},
        {T + "mesh m\nv 0 0\n", {4, "usage: v X Y Z"}},
        {T + "mesh m\nv 0 0 x\n", {4, "bad number 'x'"}},
        {T + "mesh m\nv 0 0 2000000\n", {4, "a position '2000000' out of range (-1000000 to 1000000)"}},
        {T + "mesh m\nvt 0 20000\n", {4, "v '20000' out of range (-16384 to 16384)"}},
        {T + "mesh m\nvt 0 1 2\n", {4, "usage: vt U V"}},
        {T + "mesh m\nv 0 0 0\nvt 0 0\nf 1/1 1/1\n", {6, "3 to 10 corners"}},
        {T + "mesh m\nv 0 0 0\nvt 0 0\nf 1/1 1/1 2/1\n", {6, "bad corner '2/1'"}},
        {T + "mesh m\nv 0 0 0\nvt 0 0\nf 1/1 1/1 1/2\n", {6, "bad corner '1/2'"}},
        {T + "mesh m\nv 0 0 0\nvt 0 0\nf 1 1 1\n", {6, "bad corner '1'"}},
        {T + "mesh m\nv 0 0 0\nvt 0 0\nf 1/1 1/1 1/1 1/1 1/1 1/1 1/1 1/1 1/1 1/1 1/1\n", {6, "3 to 10 corners"}},
        {T + "mesh m\nfoo\n", {4, "unknown line 'foo' in a mesh"}},
        {T + "mesh m\n", {3, "this block has no 'end'"}},
        {TM + "mesh quad\n", {14, "a second mesh named 'quad'"}},
        {TM + "object a\nend\n", {15, "object 'a' has no mesh"}},
        {TM + "object a\nmesh quad\nend\n", {16, "object 'a' has no texture"}},
        {TM + "object a\nmesh cube\n", {15, "no mesh named 'cube'"}},
        {TM + "object a\ntexture u\n", {15, "no texture named 'u'"}},
        {TM + "object a\nwrap mirror\n", {15, "usage: wrap repeat|clamp"}},
        {TM + "object a\ncull front\n", {15, "usage: cull back|none"}},
        {TM + "object a\nrotate 0 0 0 90\n", {15, "the axis must not be 0 0 0"}},
        {TM + "object a\nscale 0\n", {15, "scale '0' out of range (0.000001 to 1000000)"}},
        {TM + "object a\nkey 1 0 0 0\nkey 1 0 0 0\n", {16, "path key times must increase"}},
        {TM + "object a\nkey -1 0 0 0\n", {15, "time '-1' out of range"}},
        {TM + "object a\nmesh quad\ntexture t\nend\nobject a\n", {18, "a second object named 'a'"}},
        {TM + "object a\nbogus\n", {15, "unknown line 'bogus' in an object"}},
        {TM + "camera\nfov 180\n", {15, "fov '180' out of range (1 to 170)"}},
        {TM + "camera\nnear 0\n", {15, "near '0' out of range"}},
        {TM + "camera\nnear 5\nfar 2\nend\n", {17, "near distance must be below its far"}},
        {TM + "camera\nposition 0 0 0\ntarget 0 0 0\nend\n", {17, "the camera must look somewhere"}},
        {TM + "camera\nposition 0 5 0\ntarget 0 0 0\nend\n", {17, "the camera must look somewhere"}},
        {TM + "camera\nkey 0 0 0 5 0 0 0\nkey 1 0 0 1 0 0 1\nend\n", {17, "the camera must look somewhere"}},
        {TM + "camera\nkey 0 0 0 5\n", {15, "usage: key TIME X Y Z TARGET_X"}},
        // between keys: the eye passes through its target at 0.5 s; the view turns along up at 1.5 s
        {TM + "camera\nkey 0 0 0 0 0 0 -2\nkey 1 0 0 -2 0 0 0\nend\n", {17, "between its keys too: from 0 s to 1 s"}},
        {TM + "camera\nkey 0 0 0 0 0 0 -1\nkey 1 0 0 0 0 0 -1\nkey 2 0 0 0 0 2 1\nend\n", {18, "from 1 s to 2 s"}},
        {TM + CAMERA + "camera\n", {18, "a second camera"}},
        {T + "budget max-error 1\n", {3, "usage: budget"}},
        {T + "budget max-error 1 coverage exact target\n", {3, "usage: budget max-error N|any coverage exact|any [target icount|486|pentium]"}},
        {T + "budget max-error 1 coverage exact aim 486\n", {3, "usage: budget"}},
        {T + "budget max-error 1 coverage exact target p5\n", {3, "bad target 'p5' (icount, 486 or pentium: the machine auto is to be cheapest on)"}},
        {T + "budget max-error x coverage exact\n", {3, "bad max-error 'x'"}},
        {T + "budget max-error -1 coverage exact\n", {3, "bad max-error '-1' (a footprint error 0..1000000, or any)"}},
        {T + "budget max-error 1000001 coverage exact\n", {3, "bad max-error '1000001'"}},
        {T + "budget max-error any coverage any\nbudget max-error 1 coverage any\n", {4, "a second budget line"}},
        {T + "frames 0\n", {3, "usage: frames N"}},
        {T + "frames 10\nframes 10\n", {4, "a second frames line"}},
        {T + "sky blue\n", {3, "unknown keyword 'sky'"}},
        {T + "end\n", {3, "unknown keyword 'end'"}},
        {T + "mesh m\nend x\n", {4, "usage: end"}},
        {T + std::string("x\0", 2), {3, "binary data"}},
    };
    for (const auto& [text, want] : cases) {
        Parsed p = parse(text, files);
        EXPECT_FALSE(p.ok) << text;
        EXPECT_EQ(p.error.line, want.first) << text << " -> " << p.error.message;
        EXPECT_NE(std::string(p.error.message).find(want.second), std::string::npos) << "got '" << p.error.message << "', want '" << want.second << "'";
    }
    // the file size limit
    std::string huge = H + std::string(4 << 20, '#');
    EXPECT_NE(std::string(parse(huge).error.message).find("file too large"), std::string::npos);
}

TEST(World, EnforcesTheCountLimits) {
    // objects: 64
    std::string text = "modexlab-scene 2\ntexture t checker 8 8\n" + QUAD_MESH;
    for (int i = 0; i <= MAX_WORLD_OBJECTS; ++i) text += "object o" + std::to_string(i) + "\nmesh quad\ntexture t\nend\n";
    Parsed p = parse(text + CAMERA);
    EXPECT_NE(std::string(p.error.message).find("too many objects (at most 64)"), std::string::npos) << p.error.message;
    // path keys: 32
    text = "modexlab-scene 2\ntexture t checker 8 8\n" + QUAD_MESH + "object o\n";
    for (int i = 0; i <= MAX_PATH_KEYS; ++i) text += "key " + std::to_string(i) + " 0 0 0\n";
    p = parse(text);
    EXPECT_NE(std::string(p.error.message).find("too many path keys"), std::string::npos) << p.error.message;
    // textures: 16
    text = "modexlab-scene 2\n";
    for (int i = 0; i <= MAX_WORLD_TEXTURES; ++i) text += "texture t" + std::to_string(i) + " checker 8 8\n";
    p = parse(text);
    EXPECT_NE(std::string(p.error.message).find("too many textures"), std::string::npos) << p.error.message;
    // positions: 32768
    text = "modexlab-scene 2\nmesh m\n";
    for (int i = 0; i <= MAX_WORLD_POSITIONS; ++i) text += "v 0 0 0\n";
    p = parse(text);
    EXPECT_NE(std::string(p.error.message).find("too many positions (at most 32768)"), std::string::npos) << p.error.message;
    EXPECT_EQ(p.error.line, 3 + MAX_WORLD_POSITIONS);
}

// Random damage to a good scene: refused with a message or parsed, never a crash (the sanitizer
// build runs this too).
TEST(World, FuzzedScenesNeverCrash) {
    Files files;
    files.files["ok.bmp"] = texfiles::encode_bmp(texfiles::random_picture(4, 4, 3), texfiles::BmpKind::Rle8);
    const std::string good = "modexlab-scene 2\ntexture t checker 64 64\ntexture f file ok.bmp\npalette f\n" + QUAD_MESH +
                             "object a\nmesh quad\ntexture t\nspin 0 1 0 10\nkey 0 0 0 0\nkey 1 1 1 1\nend\n" + CAMERA + "budget max-error 2 coverage any\nframes 5\n";
    ASSERT_TRUE(parse(good, files).ok);
    std::mt19937 rng(9);
    const char alphabet[] = "0123456789 ./-\n#abcdefmnotv";
    int ok = 0, refused = 0;
    auto world = std::make_unique<HostWorld>();
    for (int trial = 0; trial < 3000; ++trial) {
        std::string t = good;
        int edits = 1 + int(rng() % 4);
        for (int e = 0; e < edits; ++e) {
            size_t at = rng() % t.size();
            switch (rng() % 3) {
            case 0: t[at] = alphabet[rng() % (sizeof alphabet - 1)]; break;
            case 1: t.erase(at, 1 + rng() % 8); break;
            default: t.insert(at, 1, alphabet[rng() % (sizeof alphabet - 1)]); break;
            }
        }
        ParseError e;
        if (parse_world(t.data(), t.size(), files.resolver(), world.get(), &e)) ++ok;
        else {
            ++refused;
            EXPECT_STRNE(e.message, "");
        }
    }
    EXPECT_GT(ok, 20);
    EXPECT_GT(refused, 500);
}

TEST(World, SceneVersionReadsOnlyTheHeader) {
    ParseError e;
    EXPECT_EQ(scene_version("# c\nmodexlab-scene 2\nanything\n", 27, &e), 2);
    EXPECT_EQ(scene_version("modexlab-scene 1\n", 17, &e), 1);
    EXPECT_EQ(scene_version("hello\n", 6, &e), 0);
    EXPECT_NE(std::string(e.message).find("not a modexlab scene"), std::string::npos);
}

TEST(Math3d, SineAndCosineOfDegrees) {
    // against libm: within a few ulp for angles of a turn or two; beyond, the angle's own ulp
    // (2664 degrees is known to 6e-13 degrees) dominates both computations
    double worst_octant = 0, worst_small = 0, worst = 0;
    for (int i = -7200; i <= 7200; ++i) {
        double d = i * 0.37 + (i % 7) * 1e-3;
        double s, c;
        sin_cos_degrees(d, &s, &c);
        double r = d * M_PI / 180;
        double e = std::max(std::fabs(s - std::sin(r)), std::fabs(c - std::cos(r)));
        worst = std::max(worst, e);
        if (std::fabs(d) <= 720) worst_small = std::max(worst_small, e);
        if (d >= 0 && d <= 45) worst_octant = std::max(worst_octant, e);
    }
    EXPECT_LT(worst_octant, 3e-16);
    EXPECT_LT(worst_small, 4e-15);
    EXPECT_LT(worst, 3e-14);
    for (int k = -8; k <= 8; ++k) {  // multiples of 90 degrees: exact
        double s, c;
        sin_cos_degrees(90.0 * k, &s, &c);
        int q = ((k % 4) + 4) % 4;
        EXPECT_EQ(s, q == 1 ? 1.0 : q == 3 ? -1.0 : 0.0) << k;
        EXPECT_EQ(c, q == 0 ? 1.0 : q == 2 ? -1.0 : 0.0) << k;
    }
}

TEST(Math3d, RotationsTurnCounterClockwiseAboutTheirAxis) {
    Rotation r = Rotation::about(Vec3{0, 0, 2}, 90);
    Vec3 p = r.apply(Vec3{1, 0, 0});
    EXPECT_EQ(p.x, 0.0);
    EXPECT_EQ(p.y, 1.0);
    EXPECT_EQ(p.z, 0.0);
    // composition: 30 then 60 degrees about one axis is 90
    Vec3 q = Rotation::about(Vec3{1, 1, 1}, 60).after(Rotation::about(Vec3{1, 1, 1}, 30)).apply(Vec3{1, -1, 0.5});
    Vec3 q90 = Rotation::about(Vec3{1, 1, 1}, 90).apply(Vec3{1, -1, 0.5});
    EXPECT_NEAR(q.x, q90.x, 1e-14);
    EXPECT_NEAR(q.y, q90.y, 1e-14);
    EXPECT_NEAR(q.z, q90.z, 1e-14);
    // a rotation keeps lengths
    EXPECT_NEAR(length(q), length(Vec3{1, -1, 0.5}), 1e-14);
}

}  // namespace

namespace {

// world_room counts what parse_world then takes: exactly, for a scene that parses, every part (its
// v, vt, f lines, corners, and the texels of procedural, file and tiled textures, BMP and PCX).
TEST(World, TheRoomCountedIsWhatTheParserTakes) {
    Files files;
    files.files["a.bmp"] = texfiles::encode_bmp(texfiles::random_picture(16, 8, 1), texfiles::BmpKind::Plain);
    files.files["b.pcx"] = texfiles::encode_pcx(texfiles::random_picture(12, 6, 2));
    files.files["c.bmp"] = texfiles::encode_bmp(texfiles::random_picture(4, 10, 3), texfiles::BmpKind::TopDown);
    files.files["d.bmp"] = texfiles::encode_bmp(texfiles::random_picture(6, 2, 4), texfiles::BmpKind::Os2);
    const std::string text = "modexlab-scene 2\ntexture t checker 64 32\ntexture f file a.bmp\ntexture g file b.pcx\n"
                             "texture h file a.bmp tile 32 16\ntexture c file c.bmp\ntexture d file d.bmp\n" +
                             QUAD_MESH +
                             "mesh tri\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\nf 3/3 2/2 1/1\nend\n"
                             "object a\nmesh quad\ntexture t\nend\nobject b\nmesh tri\ntexture h\nend\n" +
                             CAMERA;
    const Parsed p = parse(text, files);
    ASSERT_TRUE(p.ok) << p.error.message;
    const WorldRoom r = world_room(text.data(), text.size(), files.resolver());
    EXPECT_EQ(r.texels, p.world->texel_count);
    EXPECT_EQ(r.texels, uint32_t(64 * 32 + 16 * 8 + 12 * 6 + 32 * 16 + 4 * 10 + 6 * 2));
    EXPECT_EQ(r.positions, p.world->position_count);
    EXPECT_EQ(r.uvs, p.world->uv_count);
    EXPECT_EQ(r.faces, p.world->face_count);
    EXPECT_EQ(r.corners, p.world->corner_count);

    // and a world in just that room parses the same
    HostWorld exact;
    exact.room = r;
    ParseError e;
    ASSERT_TRUE(parse_world(text.data(), text.size(), files.resolver(), &exact, &e)) << e.message;
    EXPECT_EQ(exact.texel_count, p.world->texel_count);
    // one position less: refused, with the room as the limit
    WorldRoom less = r;
    --less.positions;
    exact.room = less;
    EXPECT_FALSE(parse_world(text.data(), text.size(), files.resolver(), &exact, &e));
    EXPECT_NE(std::string(e.message).find("too many positions (at most " + std::to_string(less.positions) + ")"), std::string::npos) << e.message;
}

}  // namespace
