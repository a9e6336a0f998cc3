// Under test: qemu/tools/wad.h, qemu/lib/host_image.h.
// 8-bit BMP writing, generic and from a WAD image, and freedoom1.wad's real graphics when it is installed.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "qemu/harness/session.h"
#include "qemu/lib/host_image.h"
#include "tests/unit/qemu/tools/wad_builder.h"

namespace {

using namespace wadtest;

const char* FREEDOOM1 = "/usr/share/games/doom/freedoom1.wad";

std::string temp_dir() {
    std::string d = build_dir() + "/test-tmp/wad";
    std::filesystem::create_directories(d);
    return d;
}

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
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
