// Synthetic WADs for the WAD tests: little-endian fields, lumps, column pictures, PNAMES/TEXTURE1,
// a sample WAD with patches, textures and flats, and an error-message matcher.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "qemu/lib/error.h"
#include "qemu/tools/wad.h"

namespace wadtest {

using namespace harness;

inline std::string le(uint32_t v, int bytes) {
    std::string out;
    for (int i = 0; i < bytes; ++i) out += char((v >> (8 * i)) & 0xFF);
    return out;
}
inline std::string i16(int v) { return le(uint32_t(v), 2); }
inline std::string i32(int v) { return le(uint32_t(v), 4); }
inline std::string name8(std::string_view n) {
    std::string s(n);
    s.resize(8, '\0');
    return s;
}

struct Lump {
    std::string name;  // written as given, so tests can use lower case or odd padding
    std::string data;
};

// Lumps after the header, the directory last, as most tools lay WADs out.
inline std::string build_wad(const std::vector<Lump>& lumps, std::string_view magic = "PWAD") {
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

inline std::string build_picture(int height, const std::vector<Column>& columns) {
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

inline std::string texture_lump(const std::vector<TextureSpec>& textures) {
    std::string head = i32(int(textures.size())), body;
    const size_t table_end = 4 + 4 * textures.size();
    for (const TextureSpec& t : textures) {
        head += i32(int(table_end + body.size()));
        body += name8(t.name) + i32(0) + i16(t.width) + i16(t.height) + i32(0) + i16(int(t.patches.size()));
        for (const Placement& p : t.patches) body += i16(p.x) + i16(p.y) + i16(p.patch) + i16(1) + i16(0);
    }
    return head + body;
}

inline std::string pnames_lump(const std::vector<std::string>& names) {
    std::string out = i32(int(names.size()));
    for (const std::string& n : names) out += name8(n);
    return out;
}

inline uint8_t palette_component(int entry, int component) {
    return uint8_t(component == 0 ? entry : component == 1 ? 255 - entry : (entry * 7) & 0xFF);
}

// Two palettes, as PLAYPAL holds several: only the first may be read.
inline std::string playpal_lump() {
    std::string out;
    for (int i = 0; i < 256; ++i)
        for (int c = 0; c < 3; ++c) out += char(palette_component(i, c));
    return out + std::string(768, char(0xAA));
}

inline uint8_t flat_pixel(int x, int y) { return uint8_t((x * 3 + y * 5 + 1) & 0xFF); }
inline std::string flat_lump() {
    std::string out;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) out += char(flat_pixel(x, y));
    return out;
}

// PATCHA: an ordinary 3x3 picture with a hole in its middle column.
inline std::string patch_a() { return build_picture(3, {{{0, {11, 12, 13}}}, {{0, {21}}, {2, {23}}}, {{0, {31, 32, 33}}}}); }
// PATCHB: a tall patch: column 0's third post has topdelta 2 <= 3, so it starts at row 3 + 2 = 5.
inline std::string patch_b() {
    return build_picture(8, {{{1, {41}}, {3, {43}}, {2, {45, 46}}}, {{0, {51, 52, 53}}}, {{4, {64, 65, 66, 67}}}, {{0, {71}}}});
}

// The sample the tests read and break: PNAMES names a patch that has no lump, two of TEXTURE1's
// textures have bad patch references, and BADFLAT is the wrong size for a flat.
inline std::vector<Lump> sample_lumps() {
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

inline Wad sample_wad() { return Wad(build_wad(sample_lumps()), "sample.wad"); }

// Expects a HarnessError whose message holds every one of `parts`.
inline void expect_error(const std::function<void()>& f, const std::vector<std::string>& parts) {
    try {
        f();
        ADD_FAILURE() << "no HarnessError thrown";
    } catch (const HarnessError& e) {
        const std::string message = e.what();
        for (const std::string& p : parts) EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
    }
}

// Reading back what a WAD or a BMP holds.
inline uint32_t u32(const std::string& b, size_t at) {
    return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 | uint32_t(uint8_t(b[at + 2])) << 16 |
           uint32_t(uint8_t(b[at + 3])) << 24;
}
inline uint32_t u16(const std::string& b, size_t at) { return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8; }

}  // namespace wadtest
