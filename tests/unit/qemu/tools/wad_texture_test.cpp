// Under test: qemu/tools/wad.h.
// Doom WAD graphics: column pictures (tall patches included), wall textures composed from patches, and
// the errors of broken pictures, texture lumps and patch references.
#include <gtest/gtest.h>

#include <vector>

#include "tests/unit/qemu/tools/wad_builder.h"

namespace {

using namespace wadtest;

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

std::vector<uint8_t> flatten(const std::vector<std::vector<uint8_t>>& rows) {
    std::vector<uint8_t> out;
    for (const auto& r : rows) out.insert(out.end(), r.begin(), r.end());
    return out;
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

// A WAD of a few hundred bytes may claim a 32767 x 32767 texture: refused before a byte of it is
// allocated (no scene takes one above 1024 a side), and listed as unusable.
TEST(WadErrors, RefusesATextureNoSceneCanUse) {
    std::vector<Lump> lumps = sample_lumps();
    lumps[2].data = texture_lump({{"HUGE", 32767, 32767, {{0, 0, 0}}}, {"WIDE", 1025, 8, {{0, 0, 0}}}, {"EDGE", 1024, 8, {{0, 0, 0}}}});
    const Wad wad(build_wad(lumps), "huge.wad");
    expect_error([&] { wad.texture("HUGE"); }, {"huge.wad", "texture HUGE", "32767x32767", "no scene can use a texture above 1024 a side"});
    expect_error([&] { wad.texture("WIDE"); }, {"1025x8", "above 1024"});
    EXPECT_EQ(wad.texture("EDGE").width, 1024);
    int unusable = 0;
    for (const WadListEntry& e : wad.list())
        if (e.name == "HUGE" || e.name == "WIDE") unusable += e.problem.find("no scene can use it") != std::string::npos;
    EXPECT_EQ(unusable, 2);
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

}  // namespace
