// Procedural textures and the names of texture kinds and wrap modes.
#include "kernel/core/texture.h"

namespace raster {

namespace {
constexpr const char* KIND_NAMES[TEXTURE_KIND_COUNT] = {"checker", "grid", "xor", "gradient", "numbered"};
constexpr const char* WRAP_NAMES[2] = {"repeat", "clamp"};  // in Wrap's order
constexpr uint8_t WHITE = 15, BLUE = 1;
constexpr int32_t CELL = 8;
constexpr int32_t CUBE_FIRST = 16, CUBE_SIZE = 240;  // the default palette's colour cube
constexpr int32_t NUMBERED_CELL = 16;
constexpr uint8_t BLACK = 0;
// 3 x 5 digits, a row of three bits per byte (bit 2 the left column)
constexpr uint8_t DIGITS[10][5] = {
    {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
    {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 2, 2, 2}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7},
};

// A texel of the numbered texture: lines, the cell's colour, its two-digit number at (4, 5).
uint8_t numbered_texel(int32_t u, int32_t v, int32_t width) {
    if (u % NUMBERED_CELL == 0 || v % NUMBERED_CELL == 0) return WHITE;
    int32_t cu = u / NUMBERED_CELL, cv = v / NUMBERED_CELL, across = (width + NUMBERED_CELL - 1) / NUMBERED_CELL;
    int32_t number = (cv * across + cu) % 100;
    int32_t x = u % NUMBERED_CELL - 4, y = v % NUMBERED_CELL - 5;
    if (y >= 0 && y < 5 && x >= 0 && x < 7 && x != 3) {
        int32_t digit = x < 3 ? number / 10 : number % 10, column = x < 3 ? x : x - 4;
        if (DIGITS[digit][y] & (4 >> column)) return BLACK;
    }
    return uint8_t(CUBE_FIRST + (cu * 37 + cv * 11) % CUBE_SIZE);
}
}  // namespace

const char* texture_kind_name(TextureKind k) { return KIND_NAMES[int(k)]; }

bool texture_kind_from_name(lib::StrView name, TextureKind* out) {
    int i = lib::find_name(name, KIND_NAMES, TEXTURE_KIND_COUNT);
    if (i >= 0) *out = TextureKind(i);
    return i >= 0;
}

const char* wrap_name(Wrap w) { return WRAP_NAMES[int(w)]; }

bool wrap_from_name(lib::StrView name, Wrap* out) {
    int i = lib::find_name(name, WRAP_NAMES, 2);
    if (i >= 0) *out = Wrap(i);
    return i >= 0;
}

void make_bordered(const Texture& t, uint8_t* out) {
    const int32_t pitch = bordered_pitch(t);
    for (int32_t v = -1; v <= t.height; ++v)
        for (int32_t u = -1; u <= t.width; ++u) {
            int32_t cu = u < 0 ? 0 : u >= t.width ? t.width - 1 : u;
            int32_t cv = v < 0 ? 0 : v >= t.height ? t.height - 1 : v;
            out[(v + 1) * pitch + (u + 1)] = t.texels[cv * t.width + cu];
        }
}

const uint8_t* make_aligned256(const Texture& t, uint8_t* buffer) {
    constexpr int32_t BEFORE = ALIGNED256_GUARD_BEFORE * 256, AFTER = ALIGNED256_GUARD_AFTER * 256;
    uintptr_t address = (reinterpret_cast<uintptr_t>(buffer) + BEFORE + 0xFFFF) & ~uintptr_t(0xFFFF);
    uint8_t* block = reinterpret_cast<uint8_t*>(address);
    const int32_t u_mask = t.width - 1, v_mask = t.height - 1;  // (tiles256: the sides divide 256)
    for (int32_t i = -BEFORE; i < 65536 + AFTER; ++i) {
        const int32_t at = (i + 65536) & 0xFFFF;
        block[i] = t.texels[((at >> 8) & v_mask) * t.width + (at & u_mask)];
    }
    return block;
}

const uint8_t* make_doubled(const Texture& t, uint8_t* out) {
    const int32_t pitch = doubled_pitch(t.width), rows = 2 * t.height + 2 * DOUBLED_LEAD;
    for (int32_t r = 0; r < rows; ++r)
        for (int32_t c = 0; c < pitch; ++c)
            out[r * pitch + c] = t.texels[((r - DOUBLED_LEAD) & (t.height - 1)) * t.width + ((c - DOUBLED_LEAD) & (t.width - 1))];
    return out;
}

void generate_texture(TextureKind kind, int32_t width, int32_t height, uint8_t* out) {
    for (int32_t v = 0; v < height; ++v) {
        for (int32_t u = 0; u < width; ++u) {
            uint8_t c = 0;
            switch (kind) {
            case TextureKind::Checker: c = ((u / CELL + v / CELL) & 1) ? BLUE : WHITE; break;
            case TextureKind::Grid:
                c = (u % CELL == 0 || v % CELL == 0) ? WHITE : uint8_t(CUBE_FIRST + (u / CELL * 37 + v / CELL * 11) % CUBE_SIZE);
                break;
            case TextureKind::Xor: c = uint8_t((u ^ v) & 255); break;
            case TextureKind::Gradient: c = uint8_t(CUBE_FIRST + (u * 12 / width) * 20 + (v * 20 / height)); break;
            case TextureKind::Numbered: c = numbered_texel(u, v, width); break;
            }
            out[v * width + u] = c;
        }
    }
}

}  // namespace raster
