// Under test: kernel/scene/image.h.
// BMP and PCX texture files: every variant the decoder takes, against images built here byte by
// byte, and every way a file can be wrong, each refused with the byte it is about.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "kernel/scene/image.h"
#include "tests/unit/kernel/scene/texture_files.h"

namespace {

using namespace raster;
using namespace texfiles;

struct Decoded {
    bool ok;
    IndexedImage image;
    std::vector<uint8_t> pixels;
    std::string error;
};

Decoded decode(const std::vector<uint8_t>& bytes, size_t capacity = 1 << 20) {
    Decoded d;
    d.pixels.assign(capacity, 0xEE);
    lib::Fmt e;
    d.ok = decode_indexed_image(bytes.data(), bytes.size(), &d.image, d.pixels.data(), capacity, &e);
    d.error = e.c_str();
    if (d.ok) d.pixels.resize(size_t(d.image.width) * size_t(d.image.height));
    return d;
}

TEST(TextureFile, BmpVariantsDecodeToThePicture) {
    Picture p = random_picture(37, 21, 1);
    for (BmpKind kind : {BmpKind::Plain, BmpKind::TopDown, BmpKind::Rle8, BmpKind::Os2, BmpKind::V5Header, BmpKind::FewColours}) {
        Picture q = p;
        if (kind == BmpKind::FewColours)
            for (uint8_t& px : q.pixels) px %= 16;
        Decoded d = decode(encode_bmp(q, kind));
        ASSERT_TRUE(d.ok) << int(kind) << ": " << d.error;
        EXPECT_EQ(d.image.width, 37);
        EXPECT_EQ(d.image.height, 21);
        EXPECT_EQ(d.pixels, q.pixels) << int(kind);
        int entries = kind == BmpKind::FewColours ? 16 : 256;
        EXPECT_EQ(d.image.palette_entries, entries);
        for (int i = 0; i < entries; ++i)
            for (int k = 0; k < 3; ++k) ASSERT_EQ(d.image.palette[i][k], q.palette[i][k]) << int(kind) << " entry " << i;
        for (int i = entries; i < 256; ++i) EXPECT_EQ(d.image.palette[i][0] | d.image.palette[i][1] | d.image.palette[i][2], 0);
    }
}

TEST(TextureFile, PcxDecodesToThePictureAndRowPaddingIsDropped) {
    for (int width : {1, 2, 63, 64, 65, 200}) {
        Picture p = random_picture(width, 9, uint32_t(width));
        Decoded d = decode(encode_pcx(p));
        ASSERT_TRUE(d.ok) << d.error;
        EXPECT_EQ(d.pixels, p.pixels) << width;
        EXPECT_EQ(d.image.palette[255][2], p.palette[255][2]);
    }
}

TEST(TextureFile, RleRunsAndMovesLeaveSkippedPixelsZero) {
    // a 4 x 3 RLE8 image: row 0 (the bottom): 2 x 5, then end of row; a move of (1, 1); 1 x 9; end
    Picture p = random_picture(4, 3, 2);
    std::vector<uint8_t> bytes = encode_bmp(p, BmpKind::Rle8);
    std::vector<uint8_t> rle = {2, 5, 0, 0, 0, 2, 1, 1, 1, 9, 0, 1};
    bytes.resize(bmp_pixel_offset(bytes));
    bytes.insert(bytes.end(), rle.begin(), rle.end());
    Decoded d = decode(bytes);
    ASSERT_TRUE(d.ok) << d.error;
    // stored rows are bottom-up: stored row 0 is picture row 2; the move lands on stored row 2, x 1
    std::vector<uint8_t> want = {0, 9, 0, 0, /**/ 0, 0, 0, 0, /**/ 5, 5, 0, 0};
    EXPECT_EQ(d.pixels, want);
}

TEST(TextureFile, BadFilesAreRefusedWithTheByteTheyAreAbout) {
    Picture p = random_picture(8, 8, 3);
    std::vector<uint8_t> bmp = encode_bmp(p, BmpKind::Plain), pcx = encode_pcx(p);
    auto with = [](std::vector<uint8_t> b, size_t at, std::vector<uint8_t> bytes) {
        for (size_t i = 0; i < bytes.size(); ++i) b[at + i] = bytes[i];
        return b;
    };
    auto cut = [](std::vector<uint8_t> b, size_t n) {
        b.resize(n);
        return b;
    };
    const std::pair<std::vector<uint8_t>, std::string> cases[] = {
        {{}, "byte 0: not a BMP or PCX file"},
        {{'G', 'I', 'F', '8'}, "byte 0: not a BMP or PCX file"},
        {cut(bmp, 10), "truncated BMP header"},
        {with(bmp, 14, {200, 0, 0, 0}), "byte 14: unknown BMP header size"},
        {with(bmp, 28, {24, 0}), "byte 28: not an 8-bit indexed BMP: 24 bits a pixel, 8 wanted (save it with a palette of at most 256 colours: "
                                 "ImageMagick's convert IN -colors 256 -type Palette BMP3:OUT.bmp"},
        {with(bmp, 26, {2, 0}), "byte 26: BMP planes must be 1"},
        {with(bmp, 30, {3, 0, 0, 0}), "byte 30: BMP compression not supported"},
        {with(bmp, 18, {0, 0, 0, 0}), "byte 18: image size 0 x 8 out of range"},
        {with(bmp, 18, {1, 4, 0, 0}), "byte 18: image size 1025 x 8 out of range"},
        {with(bmp, 22, {0, 0, 0, 0x80}), "byte 18: image size 8 x -2147483648 out of range"},  // top-down, the sign kept
        {with(bmp, 22, {0xFB, 0xFB, 0xFF, 0xFF}), "byte 18: image size 8 x -1029 out of range"},
        {with(bmp, 46, {1, 1, 0, 0}), "byte 46: more than 256 colours"},
        {cut(bmp, 100), "colour table runs past the end"},
        {cut(bmp, bmp.size() - 1), "BMP pixel rows run past the end"},
        {with(bmp, 10, {0, 0, 0, 0}), "byte 10: BMP pixel data overlaps the headers"},
        {cut(pcx, 100), "truncated PCX header"},
        {with(pcx, 1, {3}), "byte 1: PCX version must be 5"},
        {with(pcx, 3, {4}), "byte 3: not an 8-bit PCX"},
        {with(pcx, 65, {3}), "byte 65: not an 8-bit indexed PCX"},
        {with(pcx, 66, {7, 0}), "byte 66: PCX bytes per line"},
        {with(pcx, pcx.size() - 769, {0x0B}), "no 256-colour palette"},
        {with(pcx, 8, {0, 4}), "image size 1025 x 8 out of range"},
    };
    for (const auto& [bytes, want] : cases) {
        Decoded d = decode(bytes);
        EXPECT_FALSE(d.ok) << want;
        EXPECT_NE(d.error.find(want), std::string::npos) << "got '" << d.error << "', want '" << want << "'";
    }
    // RLE8 streams that leave the image or the file
    std::vector<uint8_t> rle = encode_bmp(p, BmpKind::Rle8);
    size_t at = bmp_pixel_offset(rle);
    auto rle_with = [&](std::vector<uint8_t> stream) {
        std::vector<uint8_t> b(rle.begin(), rle.begin() + long(at));
        b.insert(b.end(), stream.begin(), stream.end());
        return b;
    };
    const std::pair<std::vector<uint8_t>, std::string> streams[] = {
        {rle_with({9, 1, 0, 1}), "RLE8 run outside the image"},
        {rle_with({0, 2, 9, 0, 0, 1}), "RLE8 move outside the image"},
        {rle_with({0, 4, 1, 2}), "RLE8 literal run past the end of the file"},
        {rle_with({0, 9, 1, 2, 3, 4, 5, 6, 7, 8, 9, 0, 0, 1}), "RLE8 literal run outside the image"},
        {rle_with({2, 5}), "no end-of-bitmap mark"},
    };
    for (const auto& [bytes, want] : streams) {
        Decoded d = decode(bytes);
        EXPECT_FALSE(d.ok) << want;
        EXPECT_NE(d.error.find(want), std::string::npos) << "got '" << d.error << "', want '" << want << "'";
    }
    // a picture larger than the room it may take
    Decoded small = decode(bmp, 63);
    EXPECT_FALSE(small.ok);
    EXPECT_NE(small.error.find("larger than the room left"), std::string::npos) << small.error;
}

// Random bytes and random damage to good files: refused or decoded, never a read or write out of
// bounds (the sanitizer build runs this too), and a decoded image stays within its buffer.
TEST(TextureFile, FuzzedFilesNeverCrash) {
    std::mt19937 rng(11);
    std::vector<std::vector<uint8_t>> seeds = {encode_bmp(random_picture(13, 7, 4), BmpKind::Plain), encode_bmp(random_picture(13, 7, 5), BmpKind::Rle8),
                                               encode_pcx(random_picture(13, 7, 6)), encode_bmp(random_picture(5, 5, 7), BmpKind::Os2)};
    int decoded = 0, refused = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        std::vector<uint8_t> b = seeds[size_t(trial) % seeds.size()];
        int edits = 1 + int(rng() % 8);
        for (int e = 0; e < edits; ++e) {
            switch (rng() % 3) {
            case 0: b[rng() % b.size()] = uint8_t(rng()); break;
            case 1: b.resize(rng() % (b.size() + 1)); break;
            default: b.insert(b.begin() + long(rng() % (b.size() + 1)), uint8_t(rng())); break;
            }
            if (b.empty()) b.push_back(0x0A);
        }
        std::vector<uint8_t> buffer(4096 + 64, 0xA5);
        IndexedImage image;
        lib::Fmt error;
        bool ok = decode_indexed_image(b.data(), b.size(), &image, buffer.data(), 4096, &error);
        for (size_t i = 4096; i < buffer.size(); ++i) ASSERT_EQ(buffer[i], 0xA5) << "wrote past its room, trial " << trial;
        if (ok) {
            ++decoded;
            EXPECT_LE(size_t(image.width) * size_t(image.height), 4096u);
        } else {
            ++refused;
            EXPECT_STRNE(error.c_str(), "");
        }
    }
    EXPECT_GT(decoded, 100);
    EXPECT_GT(refused, 1000);
}

}  // namespace
