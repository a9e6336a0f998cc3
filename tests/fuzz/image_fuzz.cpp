// Fuzz target `image`: texture files, BMP (every header, RLE8) and PCX, as a scene names them.
// Promises: a decoded image has a size within 1..1024 a side that fits the buffer, which the
// decoder never writes past (the buffer is exactly `capacity` bytes: AddressSanitizer sees a
// stray write); a refusal has a message.
#include <string>
#include <vector>

#include "kernel/scene/image.h"
#include "tests/fuzz/fuzz.h"

MODEXLAB_FUZZ_TARGET(image) {
    // the capacity from the input's last byte, 64 bytes to 16 KiB (often less than the image needs),
    // or the most a texture takes
    const uint8_t last = size ? data[size - 1] : 0;
    const size_t capacity = last == 255 ? size_t(raster::MAX_IMAGE_SIZE) * raster::MAX_IMAGE_SIZE : size_t(1 + last) * 64;
    std::vector<uint8_t> pixels(capacity);
    raster::IndexedImage image;
    lib::Fmt error;
    if (!raster::decode_indexed_image(data, size, &image, pixels.data(), capacity, &error)) {
        if (!error.c_str()[0]) fuzz::fail("refused without a message");
        return 0;
    }
    if (image.width < 1 || image.height < 1 || image.width > raster::MAX_IMAGE_SIZE || image.height > raster::MAX_IMAGE_SIZE)
        fuzz::fail("decoded a " + std::to_string(image.width) + " x " + std::to_string(image.height) + " image");
    if (size_t(image.width) * size_t(image.height) > capacity)
        fuzz::fail("decoded " + std::to_string(image.width) + " x " + std::to_string(image.height) + " into " + std::to_string(capacity) + " bytes");
    if (image.palette_entries < 0 || image.palette_entries > 256) fuzz::fail("palette of " + std::to_string(image.palette_entries) + " entries");
    return 0;
}
