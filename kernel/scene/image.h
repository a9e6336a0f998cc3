// 8-bit indexed images from files: BMP (uncompressed or RLE8, any header from the OS/2 one to V5)
// and PCX (version 5, 8 bits, one plane, RLE, the 256-colour palette at the end), with their
// palettes. Portable: the kernel and the host read texture files with the same code and refuse a
// bad one with the same message.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/lib/fmt.h"

namespace raster {

constexpr int32_t MAX_IMAGE_SIZE = 1024;  // a side, as textures

struct IndexedImage {
    int32_t width = 0, height = 0;
    int32_t palette_entries = 0;  // the colours the file gives; the rest of `palette` is black
    uint8_t palette[256][3] = {};  // 8-bit R, G, B
};

// Decodes `size` bytes of a BMP or PCX file. The pixels go to `pixels` (row-major, the top row
// first; pixels an RLE stream skips are 0), at most `capacity` bytes. False, with `error` saying
// what is wrong and at which byte, on anything else: another format or depth, a size beyond
// 1024 x 1024 or `capacity`, data that runs past the end of the file.
bool decode_indexed_image(const uint8_t* data, size_t size, IndexedImage* out, uint8_t* pixels, size_t capacity, lib::Fmt* error);

// The width and height a BMP or PCX file's header gives (a top-down BMP's height made positive),
// each within 1..MAX_IMAGE_SIZE; false where there is no such header or a side is out of range.
bool indexed_image_size(const uint8_t* data, size_t size, int32_t* width, int32_t* height);

}  // namespace raster
