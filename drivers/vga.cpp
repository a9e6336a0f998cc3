// VGA register programming as data: one table per mode, run by apply(). Values: docs/platform.md.
#include "drivers/vga.h"

#include "drivers/io.h"
#include "kernel/lib/mem.h"

namespace vga {

namespace {

constexpr uint16_t AC_INDEX = 0x3C0;       // attribute controller: index and data through one port
constexpr uint16_t MISC_WRITE = 0x3C2;
constexpr uint16_t SEQ_INDEX = 0x3C4;
constexpr uint16_t DAC_WRITE_INDEX = 0x3C8;
constexpr uint16_t DAC_DATA = 0x3C9;
constexpr uint16_t GC_INDEX = 0x3CE;
constexpr uint16_t CRTC_INDEX = 0x3D4;     // colour addressing (MISC bit 0 set)
constexpr uint16_t INPUT_STATUS_1 = 0x3DA; // reading it resets the AC flip-flop; bit 3: vertical retrace
constexpr uint8_t IS1_VRETRACE = 0x08;
constexpr uint16_t VBE_INDEX = 0x1CE;
constexpr uint16_t VBE_DATA = 0x1CF;

constexpr uint8_t SEQ_MAP_MASK = 0x02;
constexpr uint8_t GC_READ_MAP = 0x04;
constexpr uint8_t CRTC_START_HIGH = 0x0C;
constexpr uint8_t CRTC_START_LOW = 0x0D;
constexpr uint8_t AC_VIDEO_ON = 0x20;      // index write with PAS set: hand the palette back to the display

enum class Reg : uint8_t { Misc, Seq, Crtc, CrtcAnd, Gc, Attr };

struct RegWrite {
    Reg reg;
    uint8_t index;
    uint8_t value;  // for CrtcAnd: the mask ANDed into the register
};

// Mode 13h: 320x200, 256 colours, chain-4 (linear at 0xA0000).
constexpr RegWrite MODE_13H[] = {
    {Reg::Seq, 0x00, 0x01},   // sequencer reset (synchronous) while the clock changes
    {Reg::Misc, 0, 0x63},     // colour addressing, 25 MHz clock, 400-line sync polarity, RAM on
    {Reg::Seq, 0x01, 0x01},   // clocking: 8-dot characters
    {Reg::Seq, 0x02, 0x0F},   // map mask: all planes
    {Reg::Seq, 0x03, 0x00},   // character map select
    {Reg::Seq, 0x04, 0x0E},   // memory mode: extended memory, odd/even off, chain-4 on
    {Reg::Seq, 0x00, 0x03},   // end reset
    {Reg::CrtcAnd, 0x11, 0x7F}, // unlock CRTC 0-7 (vertical retrace end bit 7)
    {Reg::Crtc, 0x00, 0x5F},  // horizontal total
    {Reg::Crtc, 0x01, 0x4F},  // horizontal display end
    {Reg::Crtc, 0x02, 0x50},  // start horizontal blanking
    {Reg::Crtc, 0x03, 0x82},  // end horizontal blanking (bit 7 set: keep vertical registers readable)
    {Reg::Crtc, 0x04, 0x54},  // start horizontal retrace
    {Reg::Crtc, 0x05, 0x80},  // end horizontal retrace
    {Reg::Crtc, 0x06, 0xBF},  // vertical total
    {Reg::Crtc, 0x07, 0x1F},  // overflow
    {Reg::Crtc, 0x08, 0x00},  // preset row scan
    {Reg::Crtc, 0x09, 0x41},  // maximum scan line: double scan
    {Reg::Crtc, 0x0A, 0x00},  // cursor start
    {Reg::Crtc, 0x0B, 0x00},  // cursor end
    {Reg::Crtc, 0x0C, 0x00},  // start address high
    {Reg::Crtc, 0x0D, 0x00},  // start address low
    {Reg::Crtc, 0x0E, 0x00},  // cursor location high
    {Reg::Crtc, 0x0F, 0x00},  // cursor location low
    {Reg::Crtc, 0x10, 0x9C},  // vertical retrace start
    {Reg::Crtc, 0x11, 0x0E},  // vertical retrace end (bit 7 clear: CRTC 0-7 stay unlocked)
    {Reg::Crtc, 0x12, 0x8F},  // vertical display end
    {Reg::Crtc, 0x13, 0x28},  // offset: 40 words per line
    {Reg::Crtc, 0x14, 0x40},  // underline location: doubleword mode
    {Reg::Crtc, 0x15, 0x96},  // start vertical blanking
    {Reg::Crtc, 0x16, 0xB9},  // end vertical blanking
    {Reg::Crtc, 0x17, 0xA3},  // mode control: byte/word per chain-4
    {Reg::Crtc, 0x18, 0xFF},  // line compare: off
    {Reg::Gc, 0x00, 0x00},    // set/reset
    {Reg::Gc, 0x01, 0x00},    // enable set/reset
    {Reg::Gc, 0x02, 0x00},    // colour compare
    {Reg::Gc, 0x03, 0x00},    // data rotate / function: replace
    {Reg::Gc, 0x04, 0x00},    // read map select
    {Reg::Gc, 0x05, 0x40},    // graphics mode: 256-colour shift, read mode 0, write mode 0
    {Reg::Gc, 0x06, 0x05},    // miscellaneous: graphics, memory at 0xA0000-0xAFFFF
    {Reg::Gc, 0x07, 0x0F},    // colour don't care
    {Reg::Gc, 0x08, 0xFF},    // bit mask: all bits from the CPU
    {Reg::Attr, 0x00, 0x00}, {Reg::Attr, 0x01, 0x01}, {Reg::Attr, 0x02, 0x02}, {Reg::Attr, 0x03, 0x03},
    {Reg::Attr, 0x04, 0x04}, {Reg::Attr, 0x05, 0x05}, {Reg::Attr, 0x06, 0x06}, {Reg::Attr, 0x07, 0x07},
    {Reg::Attr, 0x08, 0x08}, {Reg::Attr, 0x09, 0x09}, {Reg::Attr, 0x0A, 0x0A}, {Reg::Attr, 0x0B, 0x0B},
    {Reg::Attr, 0x0C, 0x0C}, {Reg::Attr, 0x0D, 0x0D}, {Reg::Attr, 0x0E, 0x0E}, {Reg::Attr, 0x0F, 0x0F},
    {Reg::Attr, 0x10, 0x41},  // mode control: graphics, 8-bit colour (pixel double clock)
    {Reg::Attr, 0x11, 0x00},  // overscan colour
    {Reg::Attr, 0x12, 0x0F},  // colour plane enable
    {Reg::Attr, 0x13, 0x00},  // horizontal pel panning
    {Reg::Attr, 0x14, 0x00},  // colour select
};

// Mode X on top of 13h (Abrash, Black Book ch. 47): unchained, 480 scan lines shown double-scanned as 240.
constexpr RegWrite MODE_X_FROM_13H[] = {
    {Reg::Seq, 0x04, 0x06},   // memory mode: chain-4 off (planar)
    {Reg::Seq, 0x00, 0x01},   // sequencer reset
    {Reg::Misc, 0, 0xE3},     // 25 MHz clock, 480-line sync polarity
    {Reg::Seq, 0x00, 0x03},   // end reset
    {Reg::CrtcAnd, 0x11, 0x7F}, // unlock CRTC 0-7
    {Reg::Crtc, 0x06, 0x0D},  // vertical total
    {Reg::Crtc, 0x07, 0x3E},  // overflow
    {Reg::Crtc, 0x09, 0x41},  // maximum scan line: double scan
    {Reg::Crtc, 0x10, 0xEA},  // vertical retrace start
    {Reg::Crtc, 0x11, 0xAC},  // vertical retrace end (locks CRTC 0-7 again)
    {Reg::Crtc, 0x12, 0xDF},  // vertical display end
    {Reg::Crtc, 0x14, 0x00},  // underline location: doubleword mode off
    {Reg::Crtc, 0x15, 0xE7},  // start vertical blanking
    {Reg::Crtc, 0x16, 0x06},  // end vertical blanking
    {Reg::Crtc, 0x17, 0xE3},  // mode control: byte mode
    {Reg::Seq, SEQ_MAP_MASK, 0x0F},
};

volatile uint8_t* const VGA_MEMORY = reinterpret_cast<volatile uint8_t*>(0xA0000);
constexpr size_t VGA_WINDOW = 0x10000;

Mode g_mode = Mode::Text;
int g_shown_page = 0;

// The framebuffer backend (vga.h): the pages in RAM, four planes each as raster::planar_target lays
// them out (mode 13h: page 0, linear), the palette the flips draw with.
bool g_fb_on = false;
Framebuffer g_fb;
uint8_t g_ram_pages[MODEX_PAGES][raster::SCREEN_PIXELS];
raster::Palette g_fb_palette{};

// The shown page into the framebuffer.
void present(int page) {
    const int h = g_mode == Mode::ModeX ? MODEX_HEIGHT : MODE13H_HEIGHT;
    const raster::ScaledPlacement at = raster::scaled_placement(g_fb.width, g_fb.height, uint32_t(WIDTH), uint32_t(h));
    uint32_t colour[256];
    for (int i = 0; i < 256; ++i) {
        const raster::Rgb6& e = g_fb_palette.entry[i];
        auto put = [](uint8_t v8, uint8_t position, uint8_t size) { return uint32_t(v8 >> (8 - size)) << position; };
        colour[i] = put(raster::widen6(e.r), g_fb.red_position, g_fb.red_size) | put(raster::widen6(e.g), g_fb.green_position, g_fb.green_size) |
                    put(raster::widen6(e.b), g_fb.blue_position, g_fb.blue_size);
    }
    // (Mode X's planes as a linear picture first: one loop for both modes)
    static uint8_t linear[raster::SCREEN_PIXELS];
    const uint8_t* src = g_ram_pages[page];
    if (g_mode == Mode::ModeX) raster::linear_from_planar(src, linear), src = linear;
    const uint32_t bytes = g_fb.bpp / 8;
    for (int y = 0; y < h; ++y)
        for (uint32_t dy = 0; dy < at.scale; ++dy) {
            uint8_t* line = g_fb.base + (at.y + uint32_t(y) * at.scale + dy) * g_fb.pitch + at.x * bytes;
            for (int x = 0; x < WIDTH; ++x) {
                const uint32_t c = colour[src[y * WIDTH + x]];
                for (uint32_t dx = 0; dx < at.scale; ++dx, line += bytes) {
                    if (bytes == 4) *reinterpret_cast<volatile uint32_t*>(line) = c;
                    else if (bytes == 2) *reinterpret_cast<volatile uint16_t*>(line) = uint16_t(c);
                    else line[0] = uint8_t(c), line[1] = uint8_t(c >> 8), line[2] = uint8_t(c >> 16);
                }
            }
        }
}

void clear_framebuffer() {
    for (uint32_t y = 0; y < g_fb.height; ++y)
        for (uint32_t i = 0; i < g_fb.width * (g_fb.bpp / 8u); ++i) g_fb.base[y * g_fb.pitch + i] = 0;
}

void apply(const RegWrite* table, size_t n) {
    for (size_t i = 0; i < n; ++i) {
        const RegWrite& w = table[i];
        switch (w.reg) {
        case Reg::Misc: io::outb(MISC_WRITE, w.value); break;
        case Reg::Seq: io::outb(SEQ_INDEX, w.index); io::outb(SEQ_INDEX + 1, w.value); break;
        case Reg::Crtc: io::outb(CRTC_INDEX, w.index); io::outb(CRTC_INDEX + 1, w.value); break;
        case Reg::CrtcAnd: {
            io::outb(CRTC_INDEX, w.index);
            uint8_t v = io::inb(CRTC_INDEX + 1);
            io::outb(CRTC_INDEX + 1, uint8_t(v & w.value));
            break;
        }
        case Reg::Gc: io::outb(GC_INDEX, w.index); io::outb(GC_INDEX + 1, w.value); break;
        case Reg::Attr:
            (void)io::inb(INPUT_STATUS_1);  // flip-flop to "index"
            io::outb(AC_INDEX, w.index);    // PAS clear while programming
            io::outb(AC_INDEX, w.value);
            break;
        }
    }
}

template <size_t N>
void apply(const RegWrite (&table)[N]) {
    apply(table, N);
}

void attributes_on() {
    (void)io::inb(INPUT_STATUS_1);
    io::outb(AC_INDEX, AC_VIDEO_ON);
}

void clear_all_planes() {
    set_map_mask(0x0F);
    for (size_t i = 0; i < VGA_WINDOW; i += 4) *reinterpret_cast<volatile uint32_t*>(VGA_MEMORY + i) = 0;
}

// Bounded waits on the vertical retrace bit: at most ~2^20 port reads (about a second on real ISA timing).
constexpr uint32_t RETRACE_SPIN_LIMIT = 1u << 20;

bool wait_retrace_state(bool in_retrace) {
    for (uint32_t spins = 0; spins < RETRACE_SPIN_LIMIT; ++spins)
        if (bool(io::inb(INPUT_STATUS_1) & IS1_VRETRACE) == in_retrace) return true;
    return false;
}

// text console state
volatile uint16_t* const TEXT = reinterpret_cast<volatile uint16_t*>(0xB8000);
constexpr int TEXT_COLS = 80, TEXT_ROWS = 25;
constexpr uint16_t TEXT_ATTR = 0x0700;  // light gray on black
int g_text_row = 0, g_text_col = 0;
bool g_text_cleared = false;  // the loader's screen is cleared on the first write

void text_newline() {
    g_text_col = 0;
    if (++g_text_row < TEXT_ROWS) return;
    for (int i = 0; i < (TEXT_ROWS - 1) * TEXT_COLS; ++i) TEXT[i] = TEXT[i + TEXT_COLS];
    for (int i = 0; i < TEXT_COLS; ++i) TEXT[(TEXT_ROWS - 1) * TEXT_COLS + i] = TEXT_ATTR | ' ';
    g_text_row = TEXT_ROWS - 1;
}

}  // namespace

namespace {

constexpr uint16_t VBE_ID = 0, VBE_XRES = 1, VBE_YRES = 2, VBE_BPP = 3, VBE_ENABLE = 4;
constexpr uint16_t VBE_ENABLED = 0x01, VBE_LFB = 0x40;

void vbe_write(uint16_t index, uint16_t value) {
    io::outw(VBE_INDEX, index);
    io::outw(VBE_DATA, value);
}

bool vbe_present() {
    io::outw(VBE_INDEX, VBE_ID);
    uint16_t id = io::inw(VBE_DATA);
    return id >= 0xB0C0 && id <= 0xB0CF;
}

}  // namespace

bool use_framebuffer(const Framebuffer& fb) {
    const bool sizes = fb.red_size >= 1 && fb.red_size <= 8 && fb.green_size >= 1 && fb.green_size <= 8 && fb.blue_size >= 1 && fb.blue_size <= 8;
    if (!fb.base || !(fb.bpp == 16 || fb.bpp == 24 || fb.bpp == 32) || fb.width < uint32_t(WIDTH) || fb.height < uint32_t(MODEX_HEIGHT) ||
        fb.pitch < fb.width * (fb.bpp / 8u) || !sizes)
        return false;
    g_fb = fb;
    g_fb_on = true;
    return true;
}

bool framebuffer_in_use() { return g_fb_on; }
const Framebuffer& framebuffer() { return g_fb; }

bool disable_bochs_vbe() {
    if (g_fb_on || !vbe_present()) return false;  // (the framebuffer may be the VBE's own)
    vbe_write(VBE_ENABLE, 0);
    return true;
}

bool enable_bochs_vbe_640x480() {
    if (g_fb_on || !vbe_present()) return false;
    vbe_write(VBE_ENABLE, 0);
    vbe_write(VBE_XRES, 640);
    vbe_write(VBE_YRES, 480);
    vbe_write(VBE_BPP, 8);
    vbe_write(VBE_ENABLE, VBE_ENABLED | VBE_LFB);
    g_mode = Mode::BochsVbe;
    return true;
}

// The framebuffer backend's mode change: the pages cleared, the screen black.
void set_ram_mode(Mode m) {
    memset(g_ram_pages, 0, sizeof g_ram_pages);
    clear_framebuffer();
    g_mode = m;
    g_shown_page = 0;
}

void set_mode_13h() {
    if (g_fb_on) return set_ram_mode(Mode::Mode13h);
    disable_bochs_vbe();
    apply(MODE_13H);
    attributes_on();
    clear_all_planes();
    g_mode = Mode::Mode13h;
    g_shown_page = 0;
}

void set_mode_x() {
    if (g_fb_on) return set_ram_mode(Mode::ModeX);
    disable_bochs_vbe();
    apply(MODE_13H);
    apply(MODE_X_FROM_13H);
    attributes_on();
    clear_all_planes();
    g_mode = Mode::ModeX;
    g_shown_page = 0;
}

Mode mode() { return g_mode; }

const char* mode_name(Mode m) {
    switch (m) {
    case Mode::Text: return "text";
    case Mode::Mode13h: return "13h";
    case Mode::ModeX: return "modex";
    case Mode::BochsVbe: return "bochs-vbe";
    }
    return "?";
}

int height() {
    return g_mode == Mode::ModeX ? MODEX_HEIGHT : g_mode == Mode::Mode13h ? MODE13H_HEIGHT : 0;
}

int page_count() { return g_mode == Mode::ModeX ? MODEX_PAGES : g_mode == Mode::Mode13h ? 1 : 0; }

int shown_page() { return g_shown_page; }

void load_palette(const raster::Palette& p) {
    if (g_fb_on) {
        g_fb_palette = p;
        if (g_mode == Mode::ModeX || g_mode == Mode::Mode13h) present(g_shown_page);  // (as a DAC change shows at once)
        return;
    }
    io::outb(DAC_WRITE_INDEX, 0);
    for (const raster::Rgb6& c : p.entry) {
        io::outb(DAC_DATA, c.r);
        io::outb(DAC_DATA, c.g);
        io::outb(DAC_DATA, c.b);
    }
}

void set_map_mask(uint8_t mask) {
    if (g_fb_on) return;  // (the RAM pages are addressed plane by plane: page_target)
    io::outb(SEQ_INDEX, SEQ_MAP_MASK);
    io::outb(SEQ_INDEX + 1, mask);
}

void set_read_plane(uint8_t plane) {
    if (g_fb_on) return;
    io::outb(GC_INDEX, GC_READ_MAP);
    io::outb(GC_INDEX + 1, uint8_t(plane & 3));
}

volatile uint8_t* page_base(int page) {
    if (g_fb_on) return g_ram_pages[page];
    return g_mode == Mode::ModeX ? VGA_MEMORY + uint32_t(page) * MODEX_PAGE_BYTES : VGA_MEMORY;
}

bool flip(int page) {
    if (g_fb_on) {
        present(page);
        g_shown_page = page;
        return true;
    }
    uint32_t start = g_mode == Mode::ModeX ? uint32_t(page) * MODEX_PAGE_BYTES : 0;
    // Change the start address outside retrace; it is latched when the next retrace begins.
    bool ok = wait_retrace_state(false);
    io::outb(CRTC_INDEX, CRTC_START_HIGH);
    io::outb(CRTC_INDEX + 1, uint8_t(start >> 8));
    io::outb(CRTC_INDEX, CRTC_START_LOW);
    io::outb(CRTC_INDEX + 1, uint8_t(start));
    ok = wait_retrace_state(true) && ok;
    g_shown_page = page;
    return ok;
}

void refresh() {
    if (g_fb_on && (g_mode == Mode::ModeX || g_mode == Mode::Mode13h)) present(g_shown_page);
}

void clear_page(int page, uint8_t colour) {
    if (g_fb_on) {
        memset(g_ram_pages[page], colour, sizeof g_ram_pages[page]);
        return;
    }
    volatile uint8_t* base = page_base(page);
    if (g_mode == Mode::ModeX) {
        set_map_mask(0x0F);
        uint32_t fill = colour * 0x01010101u;
        for (uint32_t i = 0; i < MODEX_PAGE_BYTES; i += 4) *reinterpret_cast<volatile uint32_t*>(base + i) = fill;
    } else {
        for (int i = 0; i < WIDTH * MODE13H_HEIGHT; ++i) base[i] = colour;
    }
}

void read_page(int page, uint8_t* out) {
    if (g_fb_on && g_mode == Mode::ModeX) return raster::linear_from_planar(g_ram_pages[page], out);
    volatile const uint8_t* base = page_base(page);
    if (g_mode != Mode::ModeX) {
        for (int i = 0; i < WIDTH * height(); ++i) out[i] = base[i];
        return;
    }
    for (int plane = 0; plane < 4; ++plane) {
        set_read_plane(uint8_t(plane));
        for (int y = 0; y < MODEX_HEIGHT; ++y) {
            volatile const uint8_t* src = base + y * MODEX_ROW_BYTES;
            uint8_t* dst = out + y * WIDTH + plane;
            for (int x4 = 0; x4 < MODEX_ROW_BYTES; ++x4) dst[4 * x4] = src[x4];
        }
    }
}

void blit_planar(const uint8_t* planes, int page) {
    if (g_fb_on) {
        memcpy(g_ram_pages[page], planes, sizeof g_ram_pages[page]);
        return;
    }
    volatile uint8_t* base = page_base(page);
    for (int plane = 0; plane < 4; ++plane) {
        set_map_mask(uint8_t(1u << plane));
        const auto* src = reinterpret_cast<const uint32_t*>(planes + plane * raster::PLANE_BYTES);
        auto* dst = reinterpret_cast<volatile uint32_t*>(base);
        for (int32_t i = 0; i < raster::PLANE_BYTES / 4; ++i) dst[i] = src[i];
    }
}

void blit_linear(const uint8_t* linear, int page) {
    if (g_fb_on) return raster::planar_from_linear(linear, g_ram_pages[page]);
    volatile uint8_t* base = page_base(page);
    for (int plane = 0; plane < 4; ++plane) {
        set_map_mask(uint8_t(1u << plane));
        auto* dst = reinterpret_cast<volatile uint32_t*>(base);
        // four pixels of the plane, 4 apart in the linear picture, make one dword
        for (int32_t i = 0; i < raster::PLANE_BYTES / 4; ++i) {
            const uint8_t* p = linear + 16 * i + plane;
            dst[i] = uint32_t(p[0]) | uint32_t(p[4]) << 8 | uint32_t(p[8]) << 16 | uint32_t(p[12]) << 24;
        }
    }
}

namespace {

struct PlaneSelector {
    int current = -1;
};
PlaneSelector g_plane_selector;

void select_plane(void* ctx, int plane) {
    auto* s = static_cast<PlaneSelector*>(ctx);
    if (plane == s->current) return;
    set_map_mask(uint8_t(1u << plane));
    s->current = plane;
}

}  // namespace

raster::Target page_target(int page) {
    if (g_fb_on) return raster::planar_target(g_ram_pages[page]);  // (a RAM target: no loop programs the VGA)
    raster::Target t = raster::planar_target(const_cast<uint8_t*>(page_base(page)));
    t.plane_bytes = 0;  // every plane at the same address: the map mask picks the plane
    g_plane_selector.current = -1;
    t.select_plane = select_plane;
    t.ctx = &g_plane_selector;
    t.vga = true;
    return t;
}

void text_write(const char* s) {
    if (g_mode != Mode::Text || g_fb_on) return;  // (no text memory behind a loader's framebuffer)
    if (!g_text_cleared) {
        for (int i = 0; i < TEXT_ROWS * TEXT_COLS; ++i) TEXT[i] = TEXT_ATTR | ' ';
        g_text_cleared = true;
    }
    for (; *s; ++s) {
        if (*s == '\n') {
            text_newline();
            continue;
        }
        TEXT[g_text_row * TEXT_COLS + g_text_col] = uint16_t(TEXT_ATTR | uint8_t(*s));
        if (++g_text_col == TEXT_COLS) text_newline();
    }
}

}  // namespace vga
