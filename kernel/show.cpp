// Pattern show: draw into the page after the shown one, flip, wait, repeat; the serial line interrupts.
#include "kernel/show.h"

#include "drivers/serial.h"
#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/draw.h"

namespace show {

namespace {
bool byte_waiting(void*) { return serial::byte_ready(); }
}  // namespace

void run(uint32_t interval_ms) {
    if (vga::mode() != vga::Mode::ModeX) vga::set_mode_x();
    for (uint32_t n = 0;; ++n) {
        if (serial::byte_ready()) return;
        int page = (vga::shown_page() + 1) % vga::MODEX_PAGES;
        draw::pattern(raster::Pattern(n % raster::PATTERN_COUNT), page);
        vga::flip(page);
        if (timer::wait_ms_or(interval_ms, byte_waiting, nullptr)) return;
    }
}

}  // namespace show
