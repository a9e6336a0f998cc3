// The named palettes, built at compile time.
#include "kernel/scene/palette.h"

namespace raster {

namespace {

constexpr Rgb6 EGA[16] = {
    {0, 0, 0},    {0, 0, 42},   {0, 42, 0},   {0, 42, 42},  {42, 0, 0},   {42, 0, 42},
    {42, 21, 0},  {42, 42, 42}, {21, 21, 21}, {21, 21, 63}, {21, 63, 21}, {21, 63, 63},
    {63, 21, 21}, {63, 21, 63}, {63, 63, 21}, {63, 63, 63},
};

constexpr uint8_t CUBE_R[6] = {0, 12, 25, 38, 51, 63};
constexpr uint8_t CUBE_G[8] = {0, 9, 18, 27, 36, 45, 54, 63};
constexpr uint8_t CUBE_B[5] = {4, 18, 32, 46, 60};  // none of 0, 21, 42, 63: no clash with EGA

constexpr Palette make_default() {
    Palette p{};
    for (int i = 0; i < 16; ++i) p.entry[i] = EGA[i];
    int i = 16;
    for (int r = 0; r < 6; ++r)
        for (int g = 0; g < 8; ++g)
            for (int b = 0; b < 5; ++b) p.entry[i++] = Rgb6{CUBE_R[r], CUBE_G[g], CUBE_B[b]};
    return p;
}

constexpr Palette make_gray() {
    Palette p{};
    for (int i = 0; i < 256; ++i) {
        auto v = uint8_t(i >> 2);
        p.entry[i] = Rgb6{v, v, v};
    }
    return p;
}

constexpr Palette DEFAULT_PALETTE = make_default();
constexpr Palette GRAY_PALETTE = make_gray();

}  // namespace

const Palette& palette(PaletteId id) { return id == PaletteId::Gray ? GRAY_PALETTE : DEFAULT_PALETTE; }

constexpr const char* NAMES[PALETTE_COUNT] = {"default", "gray"};  // in PaletteId's order

const char* palette_name(PaletteId id) { return NAMES[int(id)]; }

bool palette_from_name(lib::StrView name, PaletteId* out) {
    int i = lib::find_name(name, NAMES, PALETTE_COUNT);
    if (i >= 0) *out = PaletteId(i);
    return i >= 0;
}

uint8_t nearest_entry(const Palette& palette, Rgb6 c) {
    int32_t best = 0, best_distance = 1 << 30;
    for (int32_t i = 0; i < 256; ++i) {
        int32_t dr = int32_t(palette.entry[i].r) - c.r, dg = int32_t(palette.entry[i].g) - c.g, db = int32_t(palette.entry[i].b) - c.b;
        int32_t d = dr * dr + dg * dg + db * db;
        if (d < best_distance) best = i, best_distance = d;
    }
    return uint8_t(best);
}

}  // namespace raster
