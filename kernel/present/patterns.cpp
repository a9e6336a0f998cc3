// Pattern drawing through the VGA driver.
#include "kernel/present/patterns.h"

#include "drivers/vga.h"

namespace patterns {

void draw(raster::Pattern p, int page) {
    volatile uint8_t* base = vga::page_base(page);
    const int h = vga::height();
    const int w = vga::WIDTH;
    if (vga::mode() != vga::Mode::ModeX) {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) base[y * w + x] = raster::pattern_pixel(p, x, y, w, h);
        return;
    }
    raster::Target t = vga::page_target(page);  // (the VGA's page, or the framebuffer backend's RAM)
    for (int plane = 0; plane < 4; ++plane) {
        if (t.select_plane) t.select_plane(t.ctx, plane);
        volatile uint8_t* plane_base = t.base + plane * t.plane_bytes;
        for (int y = 0; y < h; ++y) {
            volatile uint8_t* row = plane_base + y * vga::MODEX_ROW_BYTES;
            for (int x4 = 0; x4 < vga::MODEX_ROW_BYTES; ++x4)
                row[x4] = raster::pattern_pixel(p, 4 * x4 + plane, y, w, h);
        }
    }
}

}  // namespace patterns
