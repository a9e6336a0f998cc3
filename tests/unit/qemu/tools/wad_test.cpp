// Under test: qemu/tools/wad.h.
// Doom WAD reading: the directory, the palette, flats and the graphics list, and the errors of a broken
// header, directory or lump.
#include <gtest/gtest.h>

#include "tests/unit/qemu/tools/wad_builder.h"

namespace {

using namespace wadtest;

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

}  // namespace
