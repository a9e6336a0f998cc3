// The font and the text routine (text.h).
#include "kernel/scene/text.h"

#include "kernel/lib/keys.h"

namespace raster {

namespace {

// The font sheet: 96 glyphs of printable ASCII from ' ' (the last slot is empty), eight to a block
// of eight rows, each glyph five pixels wide ('#' set), drawn one pixel in from the cell's left edge.
constexpr const char* SHEET[] = {
    // ' ' '!' '"' '#' '$' '%' '&' "'"
    "..... ..#.. .#.#. .#.#. ..#.. ##... .##.. ..#..",
    "..... ..#.. .#.#. .#.#. .#### ##..# #..#. ..#..",
    "..... ..#.. ..... ##### #.#.. ...#. #.#.. .....",
    "..... ..#.. ..... .#.#. .###. ..#.. .#... .....",
    "..... ..#.. ..... ##### ..#.# .#... #.#.# .....",
    "..... ..... ..... .#.#. ####. #..## #..#. .....",
    "..... ..#.. ..... .#.#. ..#.. ...## .##.# .....",
    "..... ..... ..... ..... ..... ..... ..... .....",
    // '(' ')' '*' '+' ',' '-' '.' '/'
    "...#. .#... ..... ..... ..... ..... ..... .....",
    "..#.. ..#.. ..#.. ..#.. ..... ..... ..... ....#",
    ".#... ...#. #.#.# ..#.. ..... ..... ..... ...#.",
    ".#... ...#. .###. ##### ..... ##### ..... ..#..",
    ".#... ...#. #.#.# ..#.. ..... ..... ..... .#...",
    "..#.. ..#.. ..#.. ..#.. .##.. ..... .##.. #....",
    "...#. .#... ..... ..... ..#.. ..... .##.. .....",
    "..... ..... ..... ..... .#... ..... ..... .....",
    // '0' '1' '2' '3' '4' '5' '6' '7'
    ".###. ..#.. .###. ##### ...#. ##### ..##. #####",
    "#...# .##.. #...# ...#. ..##. #.... .#... ....#",
    "#..## ..#.. ....# ..#.. .#.#. ####. #.... ...#.",
    "#.#.# ..#.. ...#. ...#. #..#. ....# ####. ..#..",
    "##..# ..#.. ..#.. ....# ##### ....# #...# .#...",
    "#...# ..#.. .#... #...# ...#. #...# #...# .#...",
    ".###. .###. ##### .###. ...#. .###. .###. .#...",
    "..... ..... ..... ..... ..... ..... ..... .....",
    // '8' '9' ':' ';' '<' '=' '>' '?'
    ".###. .###. ..... ..... ...#. ..... .#... .###.",
    "#...# #...# .##.. .##.. ..#.. ..... ..#.. #...#",
    "#...# #...# .##.. .##.. .#... ##### ...#. ....#",
    ".###. .#### ..... ..... #.... ..... ....# ...#.",
    "#...# ....# .##.. .##.. .#... ##### ...#. ..#..",
    "#...# ...#. .##.. ..#.. ..#.. ..... ..#.. .....",
    ".###. .##.. ..... .#... ...#. ..... .#... ..#..",
    "..... ..... ..... ..... ..... ..... ..... .....",
    // '@' 'A' 'B' 'C' 'D' 'E' 'F' 'G'
    ".###. .###. ####. .###. ###.. ##### ##### .###.",
    "#...# #...# #...# #...# #..#. #.... #.... #...#",
    "....# #...# #...# #.... #...# #.... #.... #....",
    ".##.# ##### ####. #.... #...# ####. ####. #.###",
    "#.#.# #...# #...# #.... #...# #.... #.... #...#",
    "#.#.# #...# #...# #...# #..#. #.... #.... #...#",
    ".###. #...# ####. .###. ###.. ##### #.... .####",
    "..... ..... ..... ..... ..... ..... ..... .....",
    // 'H' 'I' 'J' 'K' 'L' 'M' 'N' 'O'
    "#...# .###. ..### #...# #.... #...# #...# .###.",
    "#...# ..#.. ...#. #..#. #.... ##.## #...# #...#",
    "#...# ..#.. ...#. #.#.. #.... #.#.# ##..# #...#",
    "##### ..#.. ...#. ##... #.... #.#.# #.#.# #...#",
    "#...# ..#.. ...#. #.#.. #.... #...# #..## #...#",
    "#...# ..#.. #..#. #..#. #.... #...# #...# #...#",
    "#...# .###. .##.. #...# ##### #...# #...# .###.",
    "..... ..... ..... ..... ..... ..... ..... .....",
    // 'P' 'Q' 'R' 'S' 'T' 'U' 'V' 'W'
    "####. .###. ####. .#### ##### #...# #...# #...#",
    "#...# #...# #...# #.... ..#.. #...# #...# #...#",
    "#...# #...# #...# #.... ..#.. #...# #...# #...#",
    "####. #...# ####. .###. ..#.. #...# #...# #.#.#",
    "#.... #.#.# #.#.. ....# ..#.. #...# #...# #.#.#",
    "#.... #..#. #..#. ....# ..#.. #...# .#.#. #.#.#",
    "#.... .##.# #...# ####. ..#.. .###. ..#.. .#.#.",
    "..... ..... ..... ..... ..... ..... ..... .....",
    // 'X' 'Y' 'Z' '[' '\\' ']' '^' '_'
    "#...# #...# ##### .###. ..... .###. ..#.. .....",
    "#...# #...# ....# .#... #.... ...#. .#.#. .....",
    ".#.#. #...# ...#. .#... .#... ...#. #...# .....",
    "..#.. .#.#. ..#.. .#... ..#.. ...#. ..... .....",
    ".#.#. ..#.. .#... .#... ...#. ...#. ..... .....",
    "#...# ..#.. #.... .#... ....# ...#. ..... .....",
    "#...# ..#.. ##### .###. ..... .###. ..... #####",
    "..... ..... ..... ..... ..... ..... ..... .....",
    // '`' 'a' 'b' 'c' 'd' 'e' 'f' 'g'
    ".#... ..... #.... ..... ....# ..... ..##. .....",
    "..#.. ..... #.... ..... ....# ..... .#..# .....",
    "..... .###. #.##. .###. .##.# .###. .#... .####",
    "..... ....# ##..# #.... #..## #...# ###.. #...#",
    "..... .#### #...# #.... #...# ##### .#... #...#",
    "..... #...# #...# #...# #...# #.... .#... .####",
    "..... .#### ####. .###. .#### .###. .#... ....#",
    "..... ..... ..... ..... ..... ..... ..... .###.",
    // 'h' 'i' 'j' 'k' 'l' 'm' 'n' 'o'
    "#.... ..#.. ...#. #.... .##.. ..... ..... .....",
    "#.... ..... ..... #.... ..#.. ..... ..... .....",
    "#.##. .##.. ..##. #..#. ..#.. ##.#. #.##. .###.",
    "##..# ..#.. ...#. #.#.. ..#.. #.#.# ##..# #...#",
    "#...# ..#.. ...#. ##... ..#.. #.#.# #...# #...#",
    "#...# ..#.. ...#. #.#.. ..#.. #...# #...# #...#",
    "#...# .###. #..#. #..#. .###. #...# #...# .###.",
    "..... ..... .##.. ..... ..... ..... ..... .....",
    // 'p' 'q' 'r' 's' 't' 'u' 'v' 'w'
    "..... ..... ..... ..... .#... ..... ..... .....",
    "..... ..... ..... ..... .#... ..... ..... .....",
    "####. .#### #.##. .#### ###.. #...# #...# #...#",
    "#...# #...# ##..# #.... .#... #...# #...# #...#",
    "#...# #...# #.... .###. .#... #...# #...# #.#.#",
    "####. .#### #.... ....# .#..# #..## .#.#. #.#.#",
    "#.... ....# #.... ####. ..##. .##.# ..#.. .#.#.",
    "#.... ....# ..... ..... ..... ..... ..... .....",
    // 'x' 'y' 'z' '{' '|' '}' '~' (none)
    "..... ..... ..... ...#. ..#.. .#... ..... .....",
    "..... ..... ..... ..#.. ..#.. ..#.. ..... .....",
    "#...# #...# ##### ..#.. ..#.. ..#.. .#... .....",
    ".#.#. #...# ...#. .#... ..#.. ...#. #.#.# .....",
    "..#.. #...# ..#.. ..#.. ..#.. ..#.. ...#. .....",
    ".#.#. .#### .#... ..#.. ..#.. ..#.. ..... .....",
    "#...# ....# ##### ...#. ..#.. .#... ..... .....",
    "..... .###. ..... ..... ..... ..... ..... .....",
};
constexpr int FIRST = 32, GLYPHS = 96, ART_WIDTH = 5;

struct Font {
    uint8_t rows[GLYPHS][GLYPH_SIZE];
};

constexpr Font build_font() {
    Font f{};
    for (int g = 0; g < GLYPHS; ++g)
        for (int r = 0; r < GLYPH_SIZE; ++r) {
            const char* row = SHEET[(g / 8) * GLYPH_SIZE + r] + (g % 8) * (ART_WIDTH + 1);
            uint8_t bits = 0;
            for (int x = 0; x < ART_WIDTH; ++x)
                if (row[x] == '#') bits = uint8_t(bits | (0x40 >> x));
            f.rows[g][r] = bits;
        }
    return f;
}
constexpr Font FONT = build_font();
static_assert(sizeof(SHEET) / sizeof(SHEET[0]) == GLYPHS, "twelve blocks of eight rows");

}  // namespace

const uint8_t* glyph(char c) {
    const int code = int(uint8_t(c));
    return FONT.rows[code >= FIRST && code < FIRST + GLYPHS - 1 ? code - FIRST : '?' - FIRST];
}

TextColours text_colours(const Palette& p) {
    TextColours c{0, 0};
    int light = -1, dark = 1 << 30;
    for (int i = 0; i < 256; ++i) {
        const Rgb6& e = p.entry[i];
        const int luma = 2 * e.r + 5 * e.g + e.b;
        if (luma > light) light = luma, c.ink = uint8_t(i);
        if (luma < dark) dark = luma, c.paper = uint8_t(i);
    }
    return c;
}

namespace {

// Every pixel of the text whose x is `plane` modulo 4 (all of them: plane < 0), clipped.
void draw_pixels(Target& t, int32_t x, int32_t y, lib::StrView text, TextColours c, int plane) {
    const ClipRect& clip = t.clip;
    for (size_t i = 0; i < text.size; ++i) {
        const uint8_t* rows = glyph(text.data[i]);
        const int32_t left = x + int32_t(i) * GLYPH_SIZE;
        for (int32_t r = 0; r < GLYPH_SIZE; ++r) {
            const int32_t py = y + r;
            if (py < clip.y0 || py >= clip.y1) continue;
            int32_t col = plane < 0 ? 0 : ((plane - left) & 3);
            for (; col < GLYPH_SIZE; col += plane < 0 ? 1 : 4) {
                const int32_t px = left + col;
                if (px < clip.x0 || px >= clip.x1) continue;
                const uint8_t colour = (rows[r] << col) & 0x80 ? c.ink : c.paper;
                if (t.planar) t.base[plane * t.plane_bytes + py * t.row_bytes + (px >> 2)] = colour;
                else t.base[py * t.pitch + px] = colour;
            }
        }
    }
}

// The box's paper: its rectangle, clipped.
void fill_pixels(Target& t, int32_t x0, int32_t y0, int32_t x1, int32_t y1, uint8_t colour, int plane) {
    const ClipRect& clip = t.clip;
    x0 = x0 < clip.x0 ? clip.x0 : x0, y0 = y0 < clip.y0 ? clip.y0 : y0;
    x1 = x1 > clip.x1 ? clip.x1 : x1, y1 = y1 > clip.y1 ? clip.y1 : y1;
    for (int32_t y = y0; y < y1; ++y)
        for (int32_t x = plane < 0 ? x0 : x0 + ((plane - x0) & 3); x < x1; x += plane < 0 ? 1 : 4) {
            if (t.planar) t.base[plane * t.plane_bytes + y * t.row_bytes + (x >> 2)] = colour;
            else t.base[y * t.pitch + x] = colour;
        }
}

// Runs draw(plane) once for a linear target (plane -1), once a plane for a planar one, each
// plane selected once.
template <typename Draw>
void by_planes(Target& t, Draw&& draw) {
    if (!t.planar) return draw(-1);
    for (int plane = 0; plane < 4; ++plane) {
        if (t.select_plane) t.select_plane(t.ctx, plane);
        draw(plane);
    }
}

}  // namespace

void draw_text(Target& t, int32_t x, int32_t y, lib::StrView text, TextColours c) {
    by_planes(t, [&](int plane) { draw_pixels(t, x, y, text, c, plane); });
}

int32_t draw_text_box(Target& t, int32_t x, int32_t y, const lib::StrView* lines, int count, TextColours c) {
    size_t longest = 0;
    for (int i = 0; i < count; ++i) longest = lines[i].size > longest ? lines[i].size : longest;
    const int32_t width = int32_t(longest) * GLYPH_SIZE + 2, height = count * GLYPH_SIZE + 2;
    by_planes(t, [&](int plane) {
        fill_pixels(t, x, y, x + width, y + height, c.paper, plane);
        for (int i = 0; i < count; ++i) draw_pixels(t, x + 1, y + 1 + i * GLYPH_SIZE, lines[i], c, plane);
    });
    return height;
}

void draw_help(Target& t, TextColours c) {
    constexpr int MAX_LINES = 24;
    lib::StrView lines[MAX_LINES];
    int count = 0;
    for (; count < lib::help_line_count() && count < MAX_LINES; ++count) {
        const char* line = lib::help_line(count);
        lines[count] = lib::StrView{line, lib::c_length(line)};
    }
    fill_target(t, c.paper);
    draw_text_box(t, HELP_X, HELP_Y, lines, count, c);
}

void fill_target(Target& t, uint8_t colour) {
    by_planes(t, [&](int plane) { fill_pixels(t, t.clip.x0, t.clip.y0, t.clip.x1, t.clip.y1, colour, plane); });
}

void draw_qr(Target& t, const lib::QrCode& q, TextColours c) {
    const int32_t modules = q.size + 8, width = t.clip.x1 - t.clip.x0, height = t.clip.y1 - t.clip.y0 - QR_TOP;
    int32_t scale = (width < height ? width : height) / modules;
    if (scale < 1) scale = 1;
    const int32_t x0 = t.clip.x0 + (width - modules * scale) / 2, y0 = t.clip.y0 + QR_TOP + (height - modules * scale) / 2;
    by_planes(t, [&](int plane) {
        fill_pixels(t, x0, y0, x0 + modules * scale, y0 + modules * scale, c.ink, plane);
        for (int32_t y = 0; y < q.size; ++y)
            for (int32_t x = 0; x < q.size; ++x)
                if (q.at(x, y)) {
                    const int32_t px = x0 + (x + 4) * scale, py = y0 + (y + 4) * scale;
                    fill_pixels(t, px, py, px + scale, py + scale, c.paper, plane);
                }
    });
}

}  // namespace raster
