// Named test patterns as a pure function of (x, y) on a w x h page. Portable: the kernel draws
// them into VGA pages, the host renders the expected images from the same code.
#pragma once

#include <stdint.h>

#include "kernel/lib/words.h"

namespace raster {

enum class Pattern : uint8_t { Ramp, Planes, Grid, Border };

constexpr int PATTERN_COUNT = 4;

// Colours (palette indices) the patterns use.
constexpr uint8_t GRID_LINE = 15;    // white in the default palette
constexpr uint8_t GRID_FIELD = 8;    // dark gray
constexpr uint8_t BORDER_FRAME = 14; // yellow
constexpr uint8_t BORDER_FIELD = 0;  // black
constexpr int GRID_STEP = 16;

// ramp:   (x + y) mod 256 over the whole page
// planes: x mod 4, the Mode X plane holding the pixel
// grid:   GRID_LINE where x or y is a multiple of 16, GRID_FIELD elsewhere
// border: BORDER_FRAME on the outermost pixels (x = 0, x = w-1, y = 0, y = h-1), BORDER_FIELD inside
inline uint8_t pattern_pixel(Pattern p, int x, int y, int w, int h) {
    switch (p) {
    case Pattern::Ramp: return uint8_t(x + y);
    case Pattern::Planes: return uint8_t(x & 3);
    case Pattern::Grid: return (x % GRID_STEP == 0 || y % GRID_STEP == 0) ? GRID_LINE : GRID_FIELD;
    case Pattern::Border: return (x == 0 || y == 0 || x == w - 1 || y == h - 1) ? BORDER_FRAME : BORDER_FIELD;
    }
    return 0;
}

const char* pattern_name(Pattern p);
bool pattern_from_name(lib::StrView name, Pattern* out);

}  // namespace raster
