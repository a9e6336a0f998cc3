// Doom WAD reading and BMP writing: a synthetic WAD checked pixel by pixel, the error paths, and freedoom when installed.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>

#include "qemu/lib/error.h"
#include "qemu/harness/session.h"
#include "qemu/tools/wad.h"

namespace {

using namespace harness;

const char* FREEDOOM1 = "/usr/share/games/doom/freedoom1.wad";

std::string le(uint32_t v, int bytes) {
    std::string out;
    for (int i = 0; i < bytes; ++i) out += char((v >> (8 * i)) & 0xFF);
    return out;
}
std::string i16(int v) { return le(uint32_t(v), 2); }
std::string i32(int v) { return le(uint32_t(v), 4); }
std::string name8(std::string_view n) {
    std::string s(n);
    s.resize(8, '\0');
    return s;
}

struct Lump {
    std::string name;  // written as given, so tests can use lower case or odd padding
    std::string data;
};

// Lumps after the header, the directory last, as most tools lay WADs out.
std::string build_wad(const std::vector<Lump>& lumps, std::string_view magic = "PWAD") {
    std::string body, dir;
    for (const Lump& l : lumps) {
        dir += i32(int(12 + body.size())) + i32(int(l.data.size())) + name8(l.name);
        body += l.data;
    }
    return std::string(magic) + i32(int(lumps.size())) + i32(int(12 + body.size())) + body + dir;
}

struct Post {
    int topdelta;  // raw, as stored: relative to the previous post's row when tall
    std::vector<uint8_t> pixels;
};
using Column = std::vector<Post>;

std::string build_picture(int height, const std::vector<Column>& columns) {
    std::string head = i16(int(columns.size())) + i16(height) + i16(3) + i16(5);  // offsets: ignored for walls
    std::string data;
    const size_t table_end = 8 + 4 * columns.size();
    for (const Column& c : columns) {
        head += i32(int(table_end + data.size()));
        for (const Post& p : c) {
            data += char(p.topdelta);
            data += char(p.pixels.size());
            data += '\0';
            data.append(p.pixels.begin(), p.pixels.end());
            data += '\0';
        }
        data += char(0xFF);
    }
    return head + data;
}

struct Placement {
    int x, y, patch;
};
struct TextureSpec {
    std::string name;
    int width, height;
    std::vector<Placement> patches;
};

std::string texture_lump(const std::vector<TextureSpec>& textures) {
    std::string head = i32(int(textures.size())), body;
    const size_t table_end = 4 + 4 * textures.size();
    for (const TextureSpec& t : textures) {
        head += i32(int(table_end + body.size()));
        body += name8(t.name) + i32(0) + i16(t.width) + i16(t.height) + i32(0) + i16(int(t.patches.size()));
        for (const Placement& p : t.patches) body += i16(p.x) + i16(p.y) + i16(p.patch) + i16(1) + i16(0);
    }
    return head + body;
}

std::string pnames_lump(const std::vector<std::string>& names) {
    std::string out = i32(int(names.size()));
    for (const std::string& n : names) out += name8(n);
    return out;
}

uint8_t palette_component(int entry, int component) {
    return uint8_t(component == 0 ? entry : component == 1 ? 255 - entry : (entry * 7) & 0xFF);
}

// Two palettes, as PLAYPAL holds several: only the first may be read.
std::string playpal_lump() {
    std::string out;
    for (int i = 0; i < 256; ++i)
        for (int c = 0; c < 3; ++c) out += char(palette_component(i, c));
    return out + std::string(768, char(0xAA));
}

uint8_t flat_pixel(int x, int y) { return uint8_t((x * 3 + y * 5 + 1) & 0xFF); }
std::string flat_lump() {
    std::string out;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) out += char(flat_pixel(x, y));
    return out;
}

// PATCHA: an ordinary 3x3 picture with a hole in its middle column.
std::string patch_a() { return build_picture(3, {{{0, {11, 12, 13}}}, {{0, {21}}, {2, {23}}}, {{0, {31, 32, 33}}}}); }
// PATCHB: a tall patch: column 0's third post has topdelta 2 <= 3, so it starts at row 3 + 2 = 5.
std::string patch_b() {
    return build_picture(8, {{{1, {41}}, {3, {43}}, {2, {45, 46}}}, {{0, {51, 52, 53}}}, {{4, {64, 65, 66, 67}}}, {{0, {71}}}});
}

// CANVAS (4x6): PATCHA at (-1,-1) sticks out left and top, PATCHB at (1,0) right and bottom, and
// PATCHB's (1,1) lands on PATCHA's.
const std::vector<std::vector<uint8_t>> CANVAS_PIXELS = {
    {0, 32, 51, 0},   //
    {23, 41, 52, 0},  //
    {0, 0, 53, 0},    //
    {0, 43, 0, 0},    //
    {0, 0, 0, 64},    //
    {0, 45, 0, 65},   //
};

std::vector<Lump> sample_lumps() {
    return {
        {"PLAYPAL", playpal_lump()},
        {"PNAMES", pnames_lump({"PATCHA", "patchb", "NOPATCH"})},
        {"TEXTURE1", texture_lump({{"CANVAS", 4, 6, {{-1, -1, 0}, {1, 0, 1}}},
                                   {"SOLO", 3, 3, {{0, 0, 0}}},
                                   {"BADINDEX", 8, 8, {{0, 0, 0}, {0, 0, 7}}},
                                   {"MISSING", 8, 8, {{0, 0, 2}}}})},
        {"P_START", ""},
        {"PATCHA", patch_a()},
        {"patchb", patch_b()},
        {"P_END", ""},
        {"F_START", ""},
        {"F1_START", ""},
        {"FLOOR1", flat_lump()},
        {"BADFLAT", std::string(100, '\x07')},
        {"F1_END", ""},
        {"F_END", ""},
    };
}

Wad sample_wad() { return Wad(build_wad(sample_lumps()), "sample.wad"); }

std::vector<uint8_t> flatten(const std::vector<std::vector<uint8_t>>& rows) {
    std::vector<uint8_t> out;
    for (const auto& r : rows) out.insert(out.end(), r.begin(), r.end());
    return out;
}

// Expects a HarnessError whose message holds every one of `parts`.
void expect_error(const std::function<void()>& f, const std::vector<std::string>& parts) {
    try {
        f();
        ADD_FAILURE() << "no HarnessError thrown";
    } catch (const HarnessError& e) {
        const std::string message = e.what();
        for (const std::string& p : parts) EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
    }
}

std::string temp_dir() {
    std::string d = build_dir() + "/test-tmp/wad";
    std::filesystem::create_directories(d);
    return d;
}

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

uint32_t u32(const std::string& b, size_t at) {
    return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 | uint32_t(uint8_t(b[at + 2])) << 16 |
           uint32_t(uint8_t(b[at + 3])) << 24;
}
uint32_t u16(const std::string& b, size_t at) { return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8; }

TEST(WadFile, ReadsTheDirectory) {
    std::vector<Lump> lumps = sample_lumps();
    lumps.push_back({"PNAMES", pnames_lump({"PATCHA"})});                 // a later duplicate wins
    lumps.push_back({std::string("ab\0junk", 7), "x"});                   // padding after the NUL is ignored
    Wad wad(build_wad(lumps, "IWAD"), "sample.wad");
    EXPECT_TRUE(wad.is_iwad());
    ASSERT_EQ(wad.lumps().size(), lumps.size());
    EXPECT_EQ(wad.lumps()[5].name, "PATCHB");
    EXPECT_EQ(wad.lumps()[5].size, patch_b().size());
    EXPECT_EQ(wad.find_lump("patchb"), 5);
    EXPECT_EQ(wad.find_lump("PNAMES"), int(lumps.size()) - 2);
    EXPECT_EQ(wad.find_lump("AB"), int(lumps.size()) - 1);
    EXPECT_EQ(wad.find_lump("NOPE"), -1);
    EXPECT_EQ(wad.lump_data(0), playpal_lump());
    EXPECT_EQ(wad.patch_names(), std::vector<std::string>{"PATCHA"});
    EXPECT_FALSE(sample_wad().is_iwad());
    EXPECT_EQ(sample_wad().patch_names(), (std::vector<std::string>{"PATCHA", "PATCHB", "NOPATCH"}));
}

TEST(WadFile, ReadsTheFirstPalette) {
    WadPalette pal = sample_wad().palette();
    for (int i = 0; i < 256; ++i)
        for (int c = 0; c < 3; ++c) ASSERT_EQ(pal[size_t(3 * i + c)], palette_component(i, c)) << "entry " << i << " component " << c;
    expect_error([] { Wad(build_wad({{"PNAMES", pnames_lump({})}}), "nopal.wad").palette(); }, {"nopal.wad", "no PLAYPAL"});
    expect_error([] { Wad(build_wad({{"PLAYPAL", std::string(767, '\0')}}), "short.wad").palette(); },
                 {"short.wad", "PLAYPAL", "767 bytes"});
}

TEST(WadFlat, ExtractsRawIndices) {
    const Wad wad = sample_wad();
    EXPECT_TRUE(wad.has_flat("floor1"));
    EXPECT_FALSE(wad.has_flat("F1_START"));  // nested markers are not flats
    EXPECT_FALSE(wad.has_flat("CANVAS"));
    WadImage img = wad.flat("Floor1");
    ASSERT_EQ(img.width, 64);
    ASSERT_EQ(img.height, 64);
    ASSERT_EQ(img.indices.size(), 4096u);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) ASSERT_EQ(img.at(x, y), flat_pixel(x, y)) << x << "," << y;
    EXPECT_EQ(img.palette, wad.palette());
}

TEST(WadFlat, AcceptsDoubledMarkersAndLaterFlatsWin) {
    std::string second(4096, '\x09');
    Wad wad(build_wad({{"PLAYPAL", playpal_lump()},
                       {"FF_START", ""},
                       {"FLOOR1", flat_lump()},
                       {"FF_END", ""},
                       {"F_START", ""},
                       {"FLOOR2", flat_lump()},
                       {"FLOOR1", second},
                       {"FF_END", ""}}),
            "ff.wad");
    std::vector<int> flats = wad.flat_lumps();
    ASSERT_EQ(flats.size(), 2u);
    EXPECT_EQ(wad.lumps()[size_t(flats[0])].name, "FLOOR1");
    EXPECT_EQ(flats[0], 6);
    EXPECT_EQ(wad.flat("FLOOR1").indices, std::vector<uint8_t>(4096, 9));
    EXPECT_EQ(wad.flat("FLOOR2").at(5, 7), flat_pixel(5, 7));
}

TEST(WadFlat, RejectsWrongSizesUnknownNamesAndUnclosedSections) {
    const Wad wad = sample_wad();
    expect_error([&] { wad.flat("BADFLAT"); }, {"sample.wad", "BADFLAT", "100 bytes", "4096"});
    expect_error([&] { wad.flat("NOSUCH"); }, {"sample.wad", "no flat named 'NOSUCH'"});
    expect_error([&] { wad.flat("CANVAS"); }, {"no flat named 'CANVAS'"});
    Wad unclosed(build_wad({{"PLAYPAL", playpal_lump()}, {"F_START", ""}, {"FLOOR1", flat_lump()}}), "open.wad");
    expect_error([&] { unclosed.flat("FLOOR1"); }, {"open.wad", "lump F_START (index 1)", "never ends"});
    Wad stray(build_wad({{"FLOOR1", flat_lump()}, {"F_END", ""}}), "stray.wad");
    expect_error([&] { stray.list(); }, {"stray.wad", "lump F_END (index 1)", "never started"});
}

TEST(WadTexture, DecodesTallPatches) {
    DoomPicture a = decode_doom_picture(patch_a(), "PATCHA");
    EXPECT_FALSE(a.tall);
    EXPECT_EQ(a.width, 3);
    EXPECT_EQ(a.height, 3);
    EXPECT_EQ(a.left_offset, 3);
    EXPECT_EQ(a.top_offset, 5);
    ASSERT_EQ(a.columns[1].size(), 2u);
    EXPECT_EQ(a.columns[1][1].top, 2);
    DoomPicture b = decode_doom_picture(patch_b(), "PATCHB");
    EXPECT_TRUE(b.tall);
    ASSERT_EQ(b.columns.size(), 4u);
    ASSERT_EQ(b.columns[0].size(), 3u);
    EXPECT_EQ(b.columns[0][0].top, 1);
    EXPECT_EQ(b.columns[0][1].top, 3);
    EXPECT_EQ(b.columns[0][2].top, 5);
    EXPECT_EQ(b.columns[0][2].pixels, (std::vector<uint8_t>{45, 46}));
    // Past row 254, every following post is relative: 200, 254, then 10 -> 264, 254 -> 518.
    DoomPicture tall = decode_doom_picture(build_picture(600, {{{200, {1}}, {254, {2}}, {10, {3}}, {254, {4}}}}), "TALL");
    ASSERT_EQ(tall.columns[0].size(), 4u);
    EXPECT_EQ(tall.columns[0][2].top, 264);
    EXPECT_EQ(tall.columns[0][3].top, 518);
}

TEST(WadTexture, ComposesOverlappingClippedPatches) {
    const Wad wad = sample_wad();
    EXPECT_TRUE(wad.has_texture("canvas"));
    WadImage img = wad.texture("canvas");
    ASSERT_EQ(img.width, 4);
    ASSERT_EQ(img.height, 6);
    EXPECT_EQ(img.indices, flatten(CANVAS_PIXELS));
    EXPECT_EQ(img.palette, wad.palette());
    // One patch at the origin of a texture its size: the picture itself, hole included.
    EXPECT_EQ(wad.texture("SOLO").indices, (std::vector<uint8_t>{11, 21, 31, 12, 0, 32, 13, 23, 33}));
}

TEST(WadTexture, PrefersPatchesOverFlatsOfTheSameName) {
    std::vector<Lump> lumps = sample_lumps();
    lumps.insert(lumps.end() - 1, {"PATCHA", flat_lump()});  // a flat named like the patch, last in the WAD
    Wad wad(build_wad(lumps), "shadow.wad");
    EXPECT_EQ(wad.texture("CANVAS").indices, flatten(CANVAS_PIXELS));
}

TEST(WadTexture, ReadsTexture2AndTheFirstDefinitionWins) {
    std::vector<Lump> lumps = sample_lumps();
    lumps.insert(lumps.begin() + 3, {"TEXTURE2", texture_lump({{"CANVAS", 2, 2, {}}, {"EMPTY", 2, 1, {}}})});
    Wad wad(build_wad(lumps), "two.wad");
    std::vector<WadTextureDef> defs = wad.texture_defs();
    ASSERT_EQ(defs.size(), 6u);
    EXPECT_EQ(defs[4].name, "CANVAS");
    EXPECT_EQ(defs[4].source, "TEXTURE2 entry 0");
    EXPECT_EQ(wad.texture("CANVAS").indices, flatten(CANVAS_PIXELS));
    // No patch covers anything: index 0 throughout.
    EXPECT_EQ(wad.texture("EMPTY").indices, (std::vector<uint8_t>{0, 0}));
}

TEST(WadList, ListsFlatsThenTextures) {
    std::vector<WadListEntry> list = sample_wad().list();
    struct Expected {
        WadKind kind;
        const char* name;
        int width, height;
        bool usable;
    };
    const std::vector<Expected> expected = {
        {WadKind::Flat, "FLOOR1", 64, 64, true},       {WadKind::Flat, "BADFLAT", 0, 0, false},
        {WadKind::Texture, "CANVAS", 4, 6, true},      {WadKind::Texture, "SOLO", 3, 3, true},
        {WadKind::Texture, "BADINDEX", 8, 8, true},    {WadKind::Texture, "MISSING", 8, 8, true},
    };
    ASSERT_EQ(list.size(), expected.size());
    for (size_t i = 0; i < list.size(); ++i) {
        EXPECT_EQ(list[i].kind, expected[i].kind) << i;
        EXPECT_EQ(list[i].name, expected[i].name) << i;
        EXPECT_EQ(list[i].width, expected[i].width) << i;
        EXPECT_EQ(list[i].height, expected[i].height) << i;
        EXPECT_EQ(list[i].problem.empty(), expected[i].usable) << i << ": " << list[i].problem;
    }
    EXPECT_NE(list[1].problem.find("100 bytes"), std::string::npos);
    EXPECT_STREQ(wad_kind_name(WadKind::Flat), "flat");
    EXPECT_STREQ(wad_kind_name(WadKind::Texture), "texture");
}

TEST(WadErrors, RejectsBadHeaders) {
    std::string good = build_wad(sample_lumps());
    expect_error([&] { Wad(std::string("JWAD") + good.substr(4), "bad.wad"); }, {"bad.wad", "not a WAD", "'JWAD'"});
    expect_error([&] { Wad(good.substr(0, 11), "short.wad"); }, {"short.wad", "11 bytes", "12-byte WAD header"});
    expect_error([&] { Wad("", "empty.wad"); }, {"empty.wad", "0 bytes"});
    expect_error([&] { Wad("PWAD" + i32(-1) + i32(12), "neg.wad"); }, {"neg.wad", "negative (-1)"});
}

TEST(WadErrors, RejectsADirectoryPastTheEnd) {
    std::string wad = build_wad(sample_lumps());
    std::string cut = wad.substr(0, wad.size() - 1);  // the last entry loses a byte
    expect_error([&] { Wad(cut, "cut.wad"); }, {"cut.wad", "directory", "runs past the end of the file"});
    std::string far = wad;
    far.replace(8, 4, i32(int(wad.size())));
    expect_error([&] { Wad(far, "far.wad"); }, {"far.wad", "directory"});
    std::string many = wad;
    many.replace(4, 4, i32(0x7FFFFFFF));
    expect_error([&] { Wad(many, "many.wad"); }, {"many.wad", "2147483647 entries"});
    // An empty PWAD is valid: no lumps, nothing to list.
    EXPECT_TRUE(Wad("PWAD" + i32(0) + i32(12), "none.wad").list().empty());
}

TEST(WadErrors, RejectsALumpPastTheEnd) {
    std::string wad = build_wad(sample_lumps());
    const size_t dir = u32(wad, 8);
    const size_t entry = dir + 16;  // PNAMES, index 1
    const uint32_t offset = u32(wad, entry);
    wad.replace(entry + 4, 4, i32(int(wad.size())));
    const std::string expected = "lump PNAMES (index 1) runs past the end of the file (offset " + std::to_string(offset) +
                                 " + size " + std::to_string(wad.size()) + " > " + std::to_string(wad.size()) + ")";
    expect_error([&] { Wad(wad, "lump.wad"); }, {"lump.wad: " + expected});
    wad.replace(entry + 4, 4, i32(-3));
    expect_error([&] { Wad(wad, "lump.wad"); }, {"lump PNAMES (index 1) has a negative size (-3)"});
}

TEST(WadErrors, RejectsBadPatchReferences) {
    const Wad wad = sample_wad();
    expect_error([&] { wad.texture("BADINDEX"); },
                 {"sample.wad", "texture BADINDEX (TEXTURE1 entry 2)", "patch 2 of 2", "PNAMES index 7 is out of range",
                  "PNAMES has 3 names"});
    expect_error([&] { wad.texture("MISSING"); }, {"patch NOPATCH (PNAMES index 2) is not in the WAD"});
    expect_error([&] { wad.texture("NOSUCH"); }, {"sample.wad", "no wall texture named 'NOSUCH'"});
    expect_error([&] { wad.texture("FLOOR1"); }, {"no wall texture named 'FLOOR1'"});
    std::vector<Lump> lumps = sample_lumps();
    lumps.erase(lumps.begin() + 1);
    expect_error([&] { Wad(build_wad(lumps), "nopn.wad").texture("CANVAS"); }, {"nopn.wad", "no PNAMES"});
}

TEST(WadErrors, RejectsBrokenTextureLumps) {
    auto with_texture1 = [](std::string data) {
        std::vector<Lump> lumps = sample_lumps();
        lumps[2].data = std::move(data);
        return Wad(build_wad(lumps), "tex.wad");
    };
    std::string good = texture_lump({{"CANVAS", 4, 6, {{-1, -1, 0}, {1, 0, 1}}}});
    expect_error([&] { with_texture1(good.substr(0, good.size() - 1)).texture_defs(); },
                 {"tex.wad", "lump TEXTURE1 (index 2)", "CANVAS", "2 patches", "runs past the end of the lump"});
    expect_error([&] { with_texture1(i32(5) + i32(24)).list(); }, {"lump TEXTURE1", "offsets of 5 textures"});
    expect_error([&] { with_texture1(i32(1) + i32(1000)).list(); }, {"entry 0 at offset 1000"});
    expect_error([&] { with_texture1("\x01").list(); }, {"lump TEXTURE1", "1 bytes"});
}

TEST(WadErrors, RejectsBrokenPictures) {
    const std::string b = patch_b();
    expect_error([&] { decode_doom_picture(b.substr(0, 6), "P"); }, {"P: 6 bytes", "8-byte picture header"});
    expect_error([&] { decode_doom_picture(b.substr(0, 12), "P"); }, {"P: ", "4-column picture need 24 bytes"});
    std::string far = b;
    far.replace(8, 4, i32(int(b.size())));
    expect_error([&] { decode_doom_picture(far, "P"); }, {"P: column 0", "starts past the end"});
    expect_error([&] { decode_doom_picture(b.substr(0, b.size() - 1), "P"); }, {"P: column 3", "0xFF"});
    std::string long_post = build_picture(1, {{{0, {1, 2}}}});
    long_post[8 + 4 + 1] = char(200);  // the post claims 200 pixels
    expect_error([&] { decode_doom_picture(long_post, "P"); }, {"P: column 0", "200 pixels"});
    // Through a texture, the error names the WAD and the patch lump.
    std::vector<Lump> lumps = sample_lumps();
    lumps[5].data = b.substr(0, b.size() - 1);
    expect_error([&] { Wad(build_wad(lumps), "pic.wad").texture("CANVAS"); }, {"pic.wad: patch lump PATCHB (index 5)"});
}

TEST(WadBmp, WritesAnIndexedBottomUpPaddedFile) {
    const std::vector<uint8_t> pixels = {1, 2, 3,  //
                                         4, 5, 6};
    WadPalette pal;
    for (size_t i = 0; i < pal.size(); ++i) pal[i] = uint8_t(i * 5 + 1);
    const std::string path = temp_dir() + "/3x2.bmp";
    std::filesystem::remove(path);
    write_bmp8(path, 3, 2, pixels.data(), pal.data());
    const std::string b = read_bytes(path);
    ASSERT_EQ(b.size(), 14u + 40 + 1024 + 2 * 4);
    EXPECT_EQ(b.substr(0, 2), "BM");
    EXPECT_EQ(u32(b, 2), b.size());
    EXPECT_EQ(u32(b, 6), 0u);
    EXPECT_EQ(u32(b, 10), 1078u);
    EXPECT_EQ(u32(b, 14), 40u);
    EXPECT_EQ(u32(b, 18), 3u);  // width
    EXPECT_EQ(u32(b, 22), 2u);  // height, positive: bottom-up
    EXPECT_EQ(u16(b, 26), 1u);  // planes
    EXPECT_EQ(u16(b, 28), 8u);  // bits a pixel
    EXPECT_EQ(u32(b, 30), 0u);  // BI_RGB
    EXPECT_EQ(u32(b, 34), 8u);  // image bytes
    EXPECT_EQ(u32(b, 46), 256u);
    for (size_t i = 0; i < 256; ++i) {
        ASSERT_EQ(uint8_t(b[54 + 4 * i + 0]), pal[3 * i + 2]) << "blue " << i;
        ASSERT_EQ(uint8_t(b[54 + 4 * i + 1]), pal[3 * i + 1]) << "green " << i;
        ASSERT_EQ(uint8_t(b[54 + 4 * i + 2]), pal[3 * i + 0]) << "red " << i;
        ASSERT_EQ(uint8_t(b[54 + 4 * i + 3]), 0) << "reserved " << i;
    }
    EXPECT_EQ(b.substr(1078), std::string("\x04\x05\x06\x00\x01\x02\x03\x00", 8));  // bottom row first, each padded to 4
}

TEST(WadBmp, WritesAWadImage) {
    const Wad wad = sample_wad();
    const std::string path = temp_dir() + "/floor1.bmp";
    write_bmp8(path, wad.flat("FLOOR1"));
    const std::string b = read_bytes(path);
    ASSERT_EQ(b.size(), 1078u + 4096);
    EXPECT_EQ(uint8_t(b[1078]), flat_pixel(0, 63));     // the first row stored is the bottom one
    EXPECT_EQ(uint8_t(b[1078 + 64]), flat_pixel(0, 62));
    EXPECT_EQ(uint8_t(b[54 + 4 * 200 + 2]), palette_component(200, 0));
}

TEST(WadBmp, RejectsWhatItCannotWrite) {
    const std::vector<uint8_t> pixels(4, 0);
    WadPalette pal{};
    expect_error([&] { write_bmp8(temp_dir() + "/no/such/dir/x.bmp", 2, 2, pixels.data(), pal.data()); },
                 {temp_dir() + "/no/such/dir/x.bmp", "cannot write"});
    expect_error([&] { write_bmp8(temp_dir() + "/zero.bmp", 0, 2, pixels.data(), pal.data()); }, {"0x2"});
    WadImage wrong;
    wrong.width = 3;
    wrong.height = 3;
    wrong.indices.assign(4, 0);
    expect_error([&] { write_bmp8(temp_dir() + "/wrong.bmp", wrong); }, {"3x3", "4 pixels"});
    EXPECT_FALSE(std::filesystem::exists(temp_dir() + "/wrong.bmp"));
}

TEST(WadFreedoom, ExtractsAFlatAndAWallTexture) {
    if (!std::filesystem::exists(FREEDOOM1)) GTEST_SKIP() << FREEDOOM1 << " is not installed (Debian package freedoom)";
    const Wad wad = Wad::load(FREEDOOM1);
    EXPECT_EQ(wad.label(), "freedoom1.wad");
    EXPECT_TRUE(wad.is_iwad());
    const WadPalette pal = wad.palette();
    EXPECT_EQ(pal[0] + pal[1] + pal[2], 0);  // index 0, our uncovered-pixel colour, is black
    const WadImage floor = wad.flat("FLOOR0_1");
    EXPECT_EQ(floor.width, 64);
    EXPECT_EQ(floor.height, 64);
    const WadImage wall = wad.texture("STARTAN3");
    EXPECT_EQ(wall.width, 128);
    EXPECT_EQ(wall.height, 128);
    ASSERT_EQ(wall.indices.size(), 128u * 128u);
    // Real pictures, not blank canvases: many colours, and every pixel of this solid wall covered.
    std::vector<bool> used(256, false);
    for (uint8_t v : wall.indices) used[v] = true;
    EXPECT_GT(std::count(used.begin(), used.end(), true), 16);
    EXPECT_EQ(std::count(wall.indices.begin(), wall.indices.end(), uint8_t(0)), 0);
    bool listed_floor = false, listed_wall = false;
    for (const WadListEntry& e : wad.list()) {
        listed_floor |= e.kind == WadKind::Flat && e.name == "FLOOR0_1" && e.width == 64 && e.height == 64;
        listed_wall |= e.kind == WadKind::Texture && e.name == "STARTAN3" && e.width == 128 && e.height == 128;
    }
    EXPECT_TRUE(listed_floor);
    EXPECT_TRUE(listed_wall);
}

}  // namespace
