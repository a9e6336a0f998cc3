// VGA: mode 13h and unchained Mode X (320x240, three pages) from register tables, page flips
// through the CRTC start address, the DAC palette, plane-by-plane read-back, and a text console.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/scene/palette.h"
#include "kernel/core/surface.h"

namespace vga {

enum class Mode : uint8_t { Text, Mode13h, ModeX, BochsVbe };

constexpr int WIDTH = 320;
constexpr int MODEX_HEIGHT = 240;
constexpr int MODE13H_HEIGHT = 200;
constexpr int MODEX_PAGES = 3;
constexpr uint32_t MODEX_PAGE_BYTES = 0x4B00;  // 80 bytes x 240 lines, per plane
constexpr int MODEX_ROW_BYTES = WIDTH / 4;
constexpr int MAX_PIXELS = WIDTH * MODEX_HEIGHT;

// A linear RGB framebuffer a UEFI loader handed over (GRUB EFI through the Multiboot header): on a
// PC without legacy VGA the driver keeps the Mode X pages (and mode 13h's) in RAM, behind the same
// functions, and a flip draws the page into the framebuffer, scaled by the largest whole factor
// that fits, centred on black (raster::scaled_placement), each index through the palette (6-bit DAC
// values widened to 8 bits: raster::widen6). The VGA's ports are left alone.
struct Framebuffer {
    uint8_t* base = nullptr;
    uint32_t pitch = 0, width = 0, height = 0;  // bytes a line; pixels
    uint8_t bpp = 0;                            // 16, 24 or 32
    uint8_t red_position = 0, red_size = 0, green_position = 0, green_size = 0, blue_position = 0, blue_size = 0;
};
// Switches the driver to the framebuffer; false (and nothing changed) where it is not one the
// driver draws into (bpp 16, 24 or 32, at least 320 x 240, components of 1 to 8 bits).
bool use_framebuffer(const Framebuffer& fb);
bool framebuffer_in_use();
const Framebuffer& framebuffer();
// (where the picture goes: raster::scaled_placement; its colours: raster::widen6)

// Writes 0 to the Bochs VBE enable register if a Bochs/QEMU VBE adapter answers (a loader may have
// left a VBE mode on; VGA register writes are ignored while it is). True when it was found.
// The mode setters call it too.
bool disable_bochs_vbe();

// Switches on a 640x480x8 Bochs VBE mode, as a loader might leave it: a test aid for the above.
// False when no Bochs VBE adapter answers.
bool enable_bochs_vbe_640x480();

void set_mode_13h();
void set_mode_x();
Mode mode();
const char* mode_name(Mode m);
int height();       // of the current graphics mode; 0 in text mode
int page_count();   // 3 in Mode X, 1 in mode 13h, 0 in text mode
int shown_page();

void load_palette(const raster::Palette& p);

// Mode X plane selection: Sequencer map mask (writes) and Graphics Read Map Select (reads).
void set_map_mask(uint8_t mask);
void set_read_plane(uint8_t plane);
volatile uint8_t* page_base(int page);  // Mode X: plane offset of the page; 13h: the linear page

// Shows `page` (CRTC start address) and returns once the new start address has been latched, that
// is, once vertical retrace has begun; false if the retrace never came (bounded wait).
bool flip(int page);

// After drawing into the shown page: the framebuffer backend draws it again (a VGA shows its
// memory as it changes: nothing to do).
void refresh();

void clear_page(int page, uint8_t colour);

// The page's pixels as palette indices, row-major, width x height() bytes into `out`.
void read_page(int page, uint8_t* out);

// Mode X blits from RAM into a page: one map-mask change per plane, 32-bit stores.
// planes: four PLANE_BYTES planes (raster::planar_target's layout); linear: 320x240 bytes.
void blit_planar(const uint8_t* planes, int page);
void blit_linear(const uint8_t* linear, int page);

// A raster target that draws columns straight into a Mode X page (the map mask follows the column).
raster::Target page_target(int page);

// Text-mode console at 0xB8000 (only while in text mode): for messages a person without a serial line sees.
void text_write(const char* s);

}  // namespace vga
