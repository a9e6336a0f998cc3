// Text on the screen: an 8x8 bitmap font of our own (printable ASCII) and a routine that draws it
// into any target (a linear RAM surface, a planar one, a Mode X page: plane by plane, one plane
// selection each). Portable: the kernel draws its HUD and help with it, the host the same pixels
// to compare with a screendump.
#pragma once

#include <stdint.h>

#include "kernel/core/surface.h"
#include "kernel/lib/qr.h"
#include "kernel/lib/words.h"
#include "kernel/scene/palette.h"

namespace raster {

constexpr int32_t GLYPH_SIZE = 8;  // pixels a side; a line of text is 8 pixels high, 8 a character

// The glyph of a character: eight rows, top first, bit 7 the leftmost pixel. Characters outside
// printable ASCII (32..126) get '?'.
const uint8_t* glyph(char c);

// The palette's lightest and darkest entries (by luma: 2 R + 5 G + B; ties to the lower index): text
// and the box behind it, readable on any scene's palette.
struct TextColours {
    uint8_t ink, paper;
};
TextColours text_colours(const Palette& p);

// Draws `text` with its first glyph's top-left corner at (x, y): the glyphs' set pixels in `ink`,
// the rest of each cell in `paper`. Only pixels inside the target's clip are written.
void draw_text(Target& t, int32_t x, int32_t y, lib::StrView text, TextColours c);

// Lines of text in a box at (x, y): paper behind them, one pixel of margin all round, as wide as
// the longest line. Returns the box's height in pixels.
int32_t draw_text_box(Target& t, int32_t x, int32_t y, const lib::StrView* lines, int count, TextColours c);

// The whole clip in one colour.
void fill_target(Target& t, uint8_t colour);

// A QR code under the first line of text (QR_TOP on): as many pixels a module as fit with its quiet
// zone of four modules, centred; dark modules in paper, light ones and the quiet zone in ink.
constexpr int32_t QR_TOP = GLYPH_SIZE + 2;
void draw_qr(Target& t, const lib::QrCode& q, TextColours c);

// Where the show puts its HUD (a text box of figures over the frame) and its help.
constexpr int32_t HUD_X = 0, HUD_Y = 0, HELP_X = 8, HELP_Y = 8;

// The show's help: the whole clip in paper, the key bindings (lib::help_line) in a box at
// (HELP_X, HELP_Y).
void draw_help(Target& t, TextColours c);

}  // namespace raster
