// BMP and PCX decoding: every field checked before it is used, every read inside the file.
#include "kernel/scene/image.h"

namespace raster {

namespace {

struct Reader {
    const uint8_t* data;
    size_t size;
    lib::Fmt* error;

    bool fail_at(size_t offset, const char* what) {
        error->s("byte ").u(uint32_t(offset)).s(": ").s(what);
        return false;
    }
    bool has(size_t offset, size_t bytes) const { return offset <= size && bytes <= size - offset; }
    uint32_t u8(size_t o) const { return data[o]; }
    uint32_t u16(size_t o) const { return uint32_t(data[o]) | uint32_t(data[o + 1]) << 8; }
    uint32_t u32(size_t o) const { return u16(o) | u16(o + 2) << 16; }
};

// The size, as the header stores it (`shown_height`: a top-down BMP's negative height), in range.
bool check_size(Reader& r, size_t offset, int64_t width, int64_t height, size_t capacity, int64_t shown_height) {
    if (width < 1 || height < 1 || width > MAX_IMAGE_SIZE || height > MAX_IMAGE_SIZE) {
        r.error->s("byte ").u(uint32_t(offset)).s(": image size ");
        if (width < 0) r.error->s("-");
        r.error->u(uint32_t(width < 0 ? -width : width)).s(" x ");
        if (shown_height < 0) r.error->s("-");
        r.error->u(uint32_t(shown_height < 0 ? -shown_height : shown_height)).s(" out of range (1..1024 a side)");
        return false;
    }
    if (size_t(width) * size_t(height) > capacity) return r.fail_at(offset, "image larger than the room left for textures");
    return true;
}

// BMP: the 14-byte file header, a DIB header of 12 (OS/2) or 40+ bytes, the colour table, the rows.
bool decode_bmp(Reader& r, IndexedImage* out, uint8_t* pixels, size_t capacity) {
    if (!r.has(0, 18)) return r.fail_at(r.size, "truncated BMP header");
    const size_t pixel_offset = r.u32(10), dib = r.u32(14);
    int64_t width, height;
    uint32_t bits, planes, compression = 0, colours = 0;
    size_t entry_bytes = 4;
    if (dib == 12) {
        if (!r.has(14, 12)) return r.fail_at(r.size, "truncated BMP header");
        width = r.u16(18), height = r.u16(20), planes = r.u16(22), bits = r.u16(24);
        entry_bytes = 3;
    } else if (dib >= 40 && dib <= 124) {
        if (!r.has(14, 40)) return r.fail_at(r.size, "truncated BMP header");
        width = int32_t(r.u32(18)), height = int32_t(r.u32(22)), planes = r.u16(26), bits = r.u16(28);
        compression = r.u32(30), colours = r.u32(46);
    } else {
        return r.fail_at(14, "unknown BMP header size (12 or 40 to 124 bytes)");
    }
    if (planes != 1) return r.fail_at(dib == 12 ? 22 : 26, "BMP planes must be 1");
    if (bits != 8) {
        r.fail_at(dib == 12 ? 24 : 28, "not an 8-bit indexed BMP: ");
        r.error->u(bits).s(" bits a pixel, 8 wanted (save it with a palette of at most 256 colours: ImageMagick's ");
        r.error->s("convert IN -colors 256 -type Palette BMP3:OUT.bmp, or GIMP's Image > Mode > Indexed)");
        return false;
    }
    if (compression != 0 && compression != 1) return r.fail_at(30, "BMP compression not supported (none or RLE8 only)");
    const int64_t stored_height = height;
    const bool top_down = height < 0;
    if (top_down) height = -height;
    if (top_down && compression == 1) return r.fail_at(22, "a top-down BMP cannot be RLE8-compressed");
    if (!check_size(r, 18, width, height, capacity, stored_height)) return false;
    if (colours == 0) colours = 256;
    if (colours > 256) return r.fail_at(46, "more than 256 colours in the colour table");
    const size_t table = 14 + dib;
    if (!r.has(table, size_t(colours) * entry_bytes)) return r.fail_at(table, "colour table runs past the end of the file");
    *out = IndexedImage{};
    out->width = int32_t(width), out->height = int32_t(height), out->palette_entries = int32_t(colours);
    for (uint32_t i = 0; i < colours; ++i) {
        size_t e = table + i * entry_bytes;  // B, G, R(, 0)
        out->palette[i][0] = uint8_t(r.u8(e + 2)), out->palette[i][1] = uint8_t(r.u8(e + 1)), out->palette[i][2] = uint8_t(r.u8(e));
    }
    const int32_t w = int32_t(width), h = int32_t(height);
    auto row_of = [&](int32_t stored) { return top_down ? stored : h - 1 - stored; };  // stored row -> picture row
    if (compression == 0) {
        const size_t stride = (size_t(w) + 3) & ~size_t(3);
        if (pixel_offset < table) return r.fail_at(10, "BMP pixel data overlaps the headers");
        if (!r.has(pixel_offset, stride * size_t(h))) return r.fail_at(pixel_offset, "BMP pixel rows run past the end of the file");
        for (int32_t y = 0; y < h; ++y)
            for (int32_t x = 0; x < w; ++x) pixels[size_t(row_of(y)) * size_t(w) + size_t(x)] = r.data[pixel_offset + size_t(y) * stride + size_t(x)];
        return true;
    }
    // RLE8: (n, c) n pixels of c; (0, 0) end of row; (0, 1) end of bitmap; (0, 2, dx, dy) move;
    // (0, n >= 3) n literal pixels, padded to an even count
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i) pixels[i] = 0;
    if (pixel_offset < table) return r.fail_at(10, "BMP pixel data overlaps the headers");
    size_t p = pixel_offset;
    int32_t x = 0, y = 0;
    for (;;) {
        if (!r.has(p, 2)) return r.fail_at(p, "RLE8 data runs past the end of the file (no end-of-bitmap mark)");
        uint32_t n = r.u8(p), c = r.u8(p + 1);
        if (n > 0) {
            if (y >= h || x + int32_t(n) > w) return r.fail_at(p, "RLE8 run outside the image");
            for (uint32_t k = 0; k < n; ++k) pixels[size_t(row_of(y)) * size_t(w) + size_t(x++)] = uint8_t(c);
            p += 2;
        } else if (c == 0) {
            x = 0, ++y, p += 2;
        } else if (c == 1) {
            return true;
        } else if (c == 2) {
            if (!r.has(p, 4)) return r.fail_at(p, "RLE8 move runs past the end of the file");
            x += int32_t(r.u8(p + 2)), y += int32_t(r.u8(p + 3)), p += 4;
            if (x > w || y > h) return r.fail_at(p - 4, "RLE8 move outside the image");
        } else {
            if (!r.has(p + 2, c)) return r.fail_at(p, "RLE8 literal run past the end of the file");
            if (y >= h || x + int32_t(c) > w) return r.fail_at(p, "RLE8 literal run outside the image");
            for (uint32_t k = 0; k < c; ++k) pixels[size_t(row_of(y)) * size_t(w) + size_t(x++)] = r.data[p + 2 + k];
            p += 2 + c + (c & 1);
        }
    }
}

// PCX: a 128-byte header, RLE rows of bytes_per_line bytes, 0x0C and 768 palette bytes at the end.
bool decode_pcx(Reader& r, IndexedImage* out, uint8_t* pixels, size_t capacity) {
    if (!r.has(0, 128)) return r.fail_at(r.size, "truncated PCX header");
    if (r.u8(1) != 5) return r.fail_at(1, "PCX version must be 5 (256 colours)");
    if (r.u8(2) != 1) return r.fail_at(2, "PCX encoding must be 1 (RLE)");
    if (r.u8(3) != 8) return r.fail_at(3, "not an 8-bit PCX (bits per pixel must be 8)");
    if (r.u8(65) != 1) return r.fail_at(65, "not an 8-bit indexed PCX (colour planes must be 1)");
    const int64_t xmin = r.u16(4), ymin = r.u16(6), xmax = r.u16(8), ymax = r.u16(10);
    const int64_t width = xmax - xmin + 1, height = ymax - ymin + 1;
    if (!check_size(r, 4, width, height, capacity, height)) return false;
    const size_t line = r.u16(66);
    if (line < size_t(width) || (line & 1)) return r.fail_at(66, "PCX bytes per line must be even and at least the width");
    if (r.size < 128 + 769 || r.u8(r.size - 769) != 0x0C) return r.fail_at(r.size >= 769 ? r.size - 769 : 0, "no 256-colour palette at the end of the PCX file (0x0C and 768 bytes)");
    *out = IndexedImage{};
    out->width = int32_t(width), out->height = int32_t(height), out->palette_entries = 256;
    for (int i = 0; i < 256; ++i)
        for (int k = 0; k < 3; ++k) out->palette[i][k] = uint8_t(r.u8(r.size - 768 + size_t(3 * i + k)));
    const size_t end = r.size - 769, total = line * size_t(height);
    size_t p = 128, produced = 0;
    while (produced < total) {  // runs may cross the end of a row
        if (p >= end) return r.fail_at(p, "PCX pixel data ends before the last row");
        uint32_t b = r.u8(p++), n = 1;
        if (b >= 0xC0) {
            n = b & 0x3F;
            if (p >= end) return r.fail_at(p - 1, "PCX run without its value");
            b = r.u8(p++);
        }
        if (produced + n > total) return r.fail_at(p - 1, "PCX run past the last row");
        for (uint32_t k = 0; k < n; ++k, ++produced) {
            size_t y = produced / line, x = produced % line;
            if (x < size_t(width)) pixels[y * size_t(width) + x] = uint8_t(b);
        }
    }
    return true;
}

}  // namespace

bool decode_indexed_image(const uint8_t* data, size_t size, IndexedImage* out, uint8_t* pixels, size_t capacity, lib::Fmt* error) {
    Reader r{data, size, error};
    if (size >= 2 && data[0] == 'B' && data[1] == 'M') return decode_bmp(r, out, pixels, capacity);
    if (size >= 1 && data[0] == 0x0A) return decode_pcx(r, out, pixels, capacity);
    return r.fail_at(0, "not a BMP or PCX file");
}

bool indexed_image_size(const uint8_t* data, size_t size, int32_t* width, int32_t* height) {
    lib::Fmt unused;
    Reader r{data, size, &unused};
    int64_t w = 0, h = 0;
    if (size >= 2 && data[0] == 'B' && data[1] == 'M' && r.has(0, 26)) {
        const bool os2 = r.u32(14) == 12;
        w = os2 ? int64_t(r.u16(18)) : int64_t(int32_t(r.u32(18)));
        h = os2 ? int64_t(r.u16(20)) : int64_t(int32_t(r.u32(22)));  // (negative: a top-down BMP)
        if (h < 0) h = -h;
    } else if (size >= 1 && data[0] == 0x0A && r.has(0, 12)) {
        w = int64_t(r.u16(8)) - r.u16(4) + 1, h = int64_t(r.u16(10)) - r.u16(6) + 1;
    }
    if (w < 1 || h < 1 || w > MAX_IMAGE_SIZE || h > MAX_IMAGE_SIZE) return false;
    *width = int32_t(w), *height = int32_t(h);
    return true;
}

}  // namespace raster
