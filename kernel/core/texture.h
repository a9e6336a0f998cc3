// 8-bit indexed textures (1..1024 texels a side), repeat or clamp, and the procedural ones.
// Every texel read goes through texel(), which stays inside the texture for any coordinates.
#pragma once

#include <stdint.h>

#include "kernel/lib/words.h"

namespace raster {

constexpr int32_t MAX_TEXTURE_SIZE = 1024;

enum class Wrap : uint8_t { Repeat, Clamp };

struct Texture {
    const uint8_t* texels = nullptr;  // row-major, width bytes a row
    int32_t width = 0, height = 0;
    Wrap wrap = Wrap::Repeat;
    // The same texels inside a one-texel border that repeats the edge texels, (width + 2) bytes a
    // row: the classic loops, which cannot wrap, read it (X-Sharp's demo textures had such a border
    // "so that if fixed-point imprecision causes the source pointer to wander just off the bitmap,
    // appropriate pixels will be found"). Null when not built.
    const uint8_t* bordered = nullptr;
    // For textures whose sides are powers of two up to 256, the texture tiled over 256 x 256 texels
    // at an address aligned to 64 KiB (fatmap's loops and ours keep the texel's v:u in the low 16
    // bits of the pointer; a 256 x 256 texture is its one tile): texel (u, v) of the repeating
    // texture at block[(v & 255) * 256 + (u & 255)], since each side divides 256. With
    // ALIGNED256_GUARD_BEFORE rows before it and ALIGNED256_GUARD_AFTER after it that continue the
    // tiling: fatmap's table loop drifts up to a texel per 256 pixels of the triangle's longest
    // scanline, past the block's ends. Null when not built.
    const uint8_t* aligned256 = nullptr;
    // For textures whose sides are powers of two up to 1024: the repeating texture over (2 width + 2
    // DOUBLED_LEAD) x (2 height + 2 DOUBLED_LEAD) texels, doubled_pitch(width) bytes a row, at row r
    // and column c texel ((c - DOUBLED_LEAD) mod width, (r - DOUBLED_LEAD) mod height): twice the
    // texture each way from its origin, texel (0, 0) at row and column DOUBLED_LEAD (make_doubled).
    // Read by fast-table's offsets from the origin (TableBlock, every size: sums of two wholes taken
    // modulo the sides stay below 2 width and 2 height) and, above 256 a side (beyond_tile), by the
    // other fast loops' texel pointer on a window of it (fast::doubled_window). Null when not built.
    const uint8_t* doubled = nullptr;
};

constexpr int32_t ALIGNED256_GUARD_BEFORE = 96;
constexpr int32_t ALIGNED256_GUARD_AFTER = 96;
// a buffer that holds the aligned block with its guard rows (at most 65535 bytes before the block's
// 64 KiB boundary, its guard rows before it included)
constexpr int32_t ALIGNED256_BYTES = 3 * 65536;
static_assert(ALIGNED256_GUARD_BEFORE * 256 + 65535 + 65536 + ALIGNED256_GUARD_AFTER * 256 <= ALIGNED256_BYTES);
// Whether n is a power of two up to `most`.
constexpr bool pow2_up_to(int32_t n, int32_t most) { return n > 0 && n <= most && (n & (n - 1)) == 0; }
// Whether a texture's sides are powers of two up to 256 (it tiles the 64 KiB block).
inline bool tiles256(int32_t width, int32_t height) { return pow2_up_to(width, 256) && pow2_up_to(height, 256); }
// The texel of the aligned block at 16.16 coordinates u, v (their wholes taken modulo 256): what
// the 8:16 loops read through bh:bl.
inline uint8_t texel256(const uint8_t* block, uint32_t u, uint32_t v) { return block[((v >> 8) & 0xFF00) | ((u >> 16) & 0xFF)]; }
// Builds the aligned copy inside `buffer` (ALIGNED256_BYTES, any alignment) and returns the block.
const uint8_t* make_aligned256(const Texture& t, uint8_t* buffer);

// Whether a texture gets the doubled copy: its sides powers of two up to MAX_TEXTURE_SIZE.
inline bool gets_doubled(int32_t width, int32_t height) { return pow2_up_to(width, MAX_TEXTURE_SIZE) && pow2_up_to(height, MAX_TEXTURE_SIZE); }
// Whether the doubled copy is the only block our fast loops read it from: one side above 256 (it
// does not tile the 64 KiB block).
inline bool beyond_tile(int32_t width, int32_t height) { return gets_doubled(width, height) && !tiles256(width, height); }
// The doubled copy's columns and rows before its origin, and as many after twice the sides: a
// polygon whose coordinates reach a little below a multiple of the side, or a period and a little
// above one, still fits a window of it (fast::doubled_window: a face that maps the texture once,
// with its rounding).
constexpr int32_t DOUBLED_LEAD = 8;
constexpr int32_t doubled_pitch(int32_t width) { return 2 * width + 2 * DOUBLED_LEAD; }
constexpr int32_t doubled_bytes(int32_t width, int32_t height) { return doubled_pitch(width) * (2 * height + 2 * DOUBLED_LEAD); }
// The doubled copy's origin, its texel (0, 0).
inline const uint8_t* doubled_origin(const uint8_t* doubled, int32_t width) { return doubled + DOUBLED_LEAD * doubled_pitch(width) + DOUBLED_LEAD; }
// Builds the doubled copy into `out` (doubled_bytes(width, height)) and returns it.
const uint8_t* make_doubled(const Texture& t, uint8_t* out);

// Where fast-table reads a repeating texture with power-of-two sides: texel (u mod width, v mod
// height) at block + (v mod height) * pitch + (u mod width), u_mask = width - 1, v_mask = height - 1;
// the doubled copy (a table offset added to a start, each modulo the sides, stays inside it; the
// tiled block, 256 a row, would carry u's wrap into the next row), or for the fast subdivided
// loops' twin the tiled block (width, height and pitch 256: its tiles repeat the texture).
struct TableBlock {
    const uint8_t* block;
    uint32_t u_mask, v_mask;
    int32_t pitch;
    // The block's address for 16.16 coordinates u and v (their wholes taken modulo the sides).
    const uint8_t* at(uint32_t u, uint32_t v) const { return block + ((v >> 16) & v_mask) * uint32_t(pitch) + ((u >> 16) & u_mask); }
};
// The texture's doubled copy as a table block (block null: not built).
inline TableBlock table_block(const Texture& t) {
    if (!t.doubled) return TableBlock{nullptr, 0, 0, 0};
    return TableBlock{doubled_origin(t.doubled, t.width), uint32_t(t.width - 1), uint32_t(t.height - 1), doubled_pitch(t.width)};
}

inline int32_t bordered_pitch(const Texture& t) { return t.width + 2; }
inline int32_t bordered_bytes(int32_t width, int32_t height) { return (width + 2) * (height + 2); }
// Texel (0, 0) of the bordered copy: texel (u, v) is at origin[v * pitch + u] for u in -1..width.
inline const uint8_t* bordered_origin(const Texture& t) { return t.bordered + bordered_pitch(t) + 1; }
// Fills out (bordered_bytes(width, height) bytes) from t.texels.
void make_bordered(const Texture& t, uint8_t* out);

inline int32_t wrap_coord(int32_t t, int32_t size, Wrap wrap) {
    if (wrap == Wrap::Clamp) return t < 0 ? 0 : t >= size ? size - 1 : t;
    int32_t m = t % size;
    return m < 0 ? m + size : m;
}

// The texel holding texture coordinate (tu, tv) = (floor(u), floor(v)).
inline uint8_t texel(const Texture& t, int32_t tu, int32_t tv) {
    return t.texels[wrap_coord(tv, t.height, t.wrap) * t.width + wrap_coord(tu, t.width, t.wrap)];
}

enum class TextureKind : uint8_t { Checker, Grid, Xor, Gradient, Numbered };
constexpr int TEXTURE_KIND_COUNT = 5;

const char* texture_kind_name(TextureKind k);
bool texture_kind_from_name(lib::StrView name, TextureKind* out);
const char* wrap_name(Wrap w);
bool wrap_from_name(lib::StrView name, Wrap* out);

// Fills width x height texels (palette indices of the default palette):
//   checker:  8x8-texel squares, white (15) and blue (1)
//   grid:     white (15) lines on texel rows and columns that are multiples of 8; each 8x8 cell
//             inside has its own colour from the colour cube, so a wrong cell shows
//   xor:      (u xor v) mod 256;   gradient: colour-cube entries, 12 steps across u and 20 down v
//   numbered: white lines on texel rows and columns that are multiples of 16; each 16x16 cell its
//             own colour with its number (row-major from 0, two digits, mod 100) in black: the
//             cell a pixel shows can be read off a screenshot
void generate_texture(TextureKind kind, int32_t width, int32_t height, uint8_t* out);

}  // namespace raster
