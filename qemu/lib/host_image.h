// Images on the host: PNG/PPM in and out, 8-bit BMP out, QEMU screendumps mapped back to palette indices,
// comparisons.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/scene/palette.h"
#include "kernel/scene/pattern.h"

namespace harness {

struct RgbImage {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;  // row-major, 3 bytes a pixel
    const uint8_t* at(int x, int y) const { return &rgb[3 * (size_t(y) * size_t(width) + size_t(x))]; }
};

struct IndexImage {
    int width = 0, height = 0;
    std::vector<uint8_t> index;  // row-major palette indices
    uint8_t at(int x, int y) const { return index[size_t(y) * size_t(width) + size_t(x)]; }
};

// A graphics mode's logical size; QEMU's screendump shows each pixel as a 2x2 block.
struct ScreenMode {
    const char* name;
    int width, height;
};
inline constexpr ScreenMode MODE_X{"modex", 320, 240};
inline constexpr ScreenMode MODE_13H{"13h", 320, 200};

// Decoders throw HarnessError naming what is wrong with the bytes.
RgbImage decode_png(std::string_view bytes);
RgbImage decode_ppm(std::string_view bytes);  // binary P6, maxval 255, comments allowed
RgbImage load_image(const std::string& path); // PNG or PPM by its signature
void save_png(const std::string& path, const RgbImage& image);

// Writes an uncompressed 8-bit BMP: 14-byte file header, 40-byte BITMAPINFOHEADER, 256 colours
// (B, G, R, 0), rows bottom-up, each padded to a multiple of 4 bytes. `indices` is row-major, top row
// first; `palette_rgb768` is 256 RGB triplets, 8 bits a component.
void write_bmp8(const std::string& path, int width, int height, const uint8_t* indices, const uint8_t* palette_rgb768);

// The 8-bit value QEMU shows for a 6-bit DAC value: (v << 2) | ((v & 1) * 3).
inline uint8_t qemu_widen(uint8_t v6) { return uint8_t((v6 << 2) | ((v6 & 1) * 3)); }

// The picture QEMU would dump for these indices (2x2 blocks, widened palette colours).
RgbImage screendump_of(const IndexImage& image, const raster::Palette& palette);
// One pixel per index, widened palette colours: for writing index images as PNGs.
RgbImage colourise(const IndexImage& image, const raster::Palette& palette);

// Maps a screendump back to palette indices. Fails (ok false, error set) when the size is not
// twice the mode's, a 2x2 block is not uniform, or a colour matches no entry or several entries.
struct DecodeResult {
    bool ok = false;
    IndexImage image;
    std::string error;
};
DecodeResult decode_screendump(const RgbImage& dump, const raster::Palette& palette, ScreenMode mode);

// The host's own rendering of a test pattern (the kernel draws it from the same code).
IndexImage render_pattern(raster::Pattern pattern, ScreenMode mode);

struct PixelDiff {
    int x, y;
    int actual, expected;
};

struct Comparison {
    size_t differing = 0;
    size_t total = 0;
    bool size_mismatch = false;
    std::vector<PixelDiff> first;  // up to 10, in row-major order
    bool equal() const { return differing == 0 && !size_mismatch; }
    std::string summary() const;
};

Comparison compare(const IndexImage& actual, const IndexImage& expected);

// The CRC-32 of a picture's indices, row-major: what `readback PAGE crc` answers for the same page.
uint32_t crc32_of(const IndexImage& image);

// Writes DIR/STEM-actual.png, -expected.png and -diff.png (differences red over a dimmed
// expected image); returns a line naming them.
std::string write_mismatch(const std::string& dir, const std::string& stem, const IndexImage& actual,
                           const IndexImage& expected, const raster::Palette& palette);

}  // namespace harness
