// Named 256-entry palettes in the VGA DAC's 6-bit format. Portable: the kernel loads them, the host decodes screendumps with them.
#pragma once

#include <stdint.h>

#include "kernel/lib/words.h"

namespace raster {

struct Rgb6 {
    uint8_t r, g, b;  // 0..63 each, as written to the DAC
};

struct Palette {
    Rgb6 entry[256];
};

enum class PaletteId : uint8_t { Default, Gray };

constexpr int PALETTE_COUNT = 2;

// "default": 0..15 the 16 EGA colours; 16..255 a 6x8x5 colour cube whose blue levels avoid the
// EGA levels, so all 256 entries differ (a screendump maps back to indices unambiguously).
// "gray": entry i is the gray i>>2 (64 levels, each four times: not uniquely decodable).
const Palette& palette(PaletteId id);
const char* palette_name(PaletteId id);
bool palette_from_name(lib::StrView name, PaletteId* out);

// A 6-bit DAC value as 8 bits, its top bits repeated below (0 -> 0, 63 -> 255): the colour the
// kernel writes into a UEFI framebuffer (drivers/vga.h).
constexpr uint8_t widen6(uint8_t v) { return uint8_t(v << 2 | v >> 4); }

// The entry nearest to c (squared distance in the DAC's 6-bit units; ties to the lower index).
uint8_t nearest_entry(const Palette& palette, Rgb6 c);

}  // namespace raster
