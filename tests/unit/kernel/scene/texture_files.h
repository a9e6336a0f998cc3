// Test helpers: 8-bit BMP (several header kinds, RLE8) and PCX files built byte by byte from a picture.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

namespace texfiles {

struct Picture {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;   // row-major, top row first
    uint8_t palette[256][3] = {};  // R, G, B
};

inline Picture random_picture(int width, int height, uint32_t seed) {
    std::mt19937 rng(seed);
    Picture p;
    p.width = width, p.height = height;
    for (int i = 0; i < width * height; ++i) p.pixels.push_back(uint8_t(rng() % 4 == 0 ? rng() : rng() % 3));  // runs and noise
    for (auto& e : p.palette)
        for (uint8_t& c : e) c = uint8_t(rng());
    return p;
}

enum class BmpKind { Plain, TopDown, Rle8, Os2, V5Header, FewColours };

inline void put16(std::vector<uint8_t>& b, uint32_t v) {
    b.push_back(uint8_t(v)), b.push_back(uint8_t(v >> 8));
}
inline void put32(std::vector<uint8_t>& b, uint32_t v) { put16(b, v & 0xFFFF), put16(b, v >> 16); }

// RLE8 of one stored row: runs of equal pixels, absolute runs of 3 or more others, end of row.
inline void rle8_row(std::vector<uint8_t>& b, const uint8_t* row, int width) {
    int x = 0;
    while (x < width) {
        int run = 1;
        while (x + run < width && run < 255 && row[x + run] == row[x]) ++run;
        if (run >= 2) {
            b.push_back(uint8_t(run)), b.push_back(row[x]);
            x += run;
            continue;
        }
        int literal = 1;
        while (x + literal < width && literal < 255 && !(x + literal + 1 < width && row[x + literal] == row[x + literal + 1])) ++literal;
        if (literal >= 3) {
            b.push_back(0), b.push_back(uint8_t(literal));
            for (int k = 0; k < literal; ++k) b.push_back(row[x + k]);
            if (literal & 1) b.push_back(0);
        } else {
            for (int k = 0; k < literal; ++k) b.push_back(1), b.push_back(row[x + k]);
        }
        x += literal;
    }
    b.push_back(0), b.push_back(0);
}

inline std::vector<uint8_t> encode_bmp(const Picture& p, BmpKind kind) {
    const bool os2 = kind == BmpKind::Os2;
    const uint32_t dib = os2 ? 12 : kind == BmpKind::V5Header ? 124 : 40;
    const uint32_t colours = kind == BmpKind::FewColours ? 16 : 256, entry = os2 ? 3 : 4;
    const uint32_t offset = 14 + dib + colours * entry;
    std::vector<uint8_t> b = {'B', 'M'};
    put32(b, 0);  // file size: filled in below
    put32(b, 0);
    put32(b, offset);
    put32(b, dib);
    if (os2) {
        put16(b, uint32_t(p.width)), put16(b, uint32_t(p.height)), put16(b, 1), put16(b, 8);
    } else {
        put32(b, uint32_t(p.width));
        put32(b, kind == BmpKind::TopDown ? uint32_t(-p.height) : uint32_t(p.height));
        put16(b, 1), put16(b, 8);
        put32(b, kind == BmpKind::Rle8 ? 1 : 0);
        put32(b, 0), put32(b, 2835), put32(b, 2835);
        put32(b, kind == BmpKind::FewColours ? 16 : 0), put32(b, 0);
        while (b.size() < 14 + dib) b.push_back(0);
    }
    for (uint32_t i = 0; i < colours; ++i) {
        b.push_back(p.palette[i][2]), b.push_back(p.palette[i][1]), b.push_back(p.palette[i][0]);
        if (!os2) b.push_back(0);
    }
    const int stride = (p.width + 3) & ~3;
    for (int s = 0; s < p.height; ++s) {
        int y = kind == BmpKind::TopDown ? s : p.height - 1 - s;
        const uint8_t* row = &p.pixels[size_t(y) * size_t(p.width)];
        if (kind == BmpKind::Rle8) {
            rle8_row(b, row, p.width);
        } else {
            b.insert(b.end(), row, row + p.width);
            for (int k = p.width; k < stride; ++k) b.push_back(0);
        }
    }
    if (kind == BmpKind::Rle8) b.push_back(0), b.push_back(1);
    uint32_t size = uint32_t(b.size());
    for (int k = 0; k < 4; ++k) b[2 + size_t(k)] = uint8_t(size >> (8 * k));
    return b;
}

inline size_t bmp_pixel_offset(const std::vector<uint8_t>& b) {
    return size_t(b[10]) | size_t(b[11]) << 8 | size_t(b[12]) << 16 | size_t(b[13]) << 24;
}

inline std::vector<uint8_t> encode_pcx(const Picture& p) {
    std::vector<uint8_t> b(128, 0);
    b[0] = 0x0A, b[1] = 5, b[2] = 1, b[3] = 8;
    auto set16 = [&](size_t at, uint32_t v) { b[at] = uint8_t(v), b[at + 1] = uint8_t(v >> 8); };
    set16(8, uint32_t(p.width - 1)), set16(10, uint32_t(p.height - 1)), set16(12, 72), set16(14, 72);
    const int line = (p.width + 1) & ~1;
    b[65] = 1, set16(66, uint32_t(line)), b[68] = 1;
    for (int y = 0; y < p.height; ++y) {
        std::vector<uint8_t> row(size_t(line), 0);
        for (int x = 0; x < p.width; ++x) row[size_t(x)] = p.pixels[size_t(y) * size_t(p.width) + size_t(x)];
        for (int x = 0; x < line;) {
            int run = 1;
            while (x + run < line && run < 63 && row[size_t(x + run)] == row[size_t(x)]) ++run;
            if (run > 1 || row[size_t(x)] >= 0xC0) b.push_back(uint8_t(0xC0 | run));
            b.push_back(row[size_t(x)]);
            x += run;
        }
    }
    b.push_back(0x0C);
    for (const auto& e : p.palette) b.insert(b.end(), e, e + 3);
    return b;
}

}  // namespace texfiles
