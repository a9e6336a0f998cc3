// The boot show: scenes played frame by frame, or patterns; the serial line interrupts either.
#include "kernel/show.h"

#include "drivers/serial.h"
#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/draw.h"
#include "kernel/files.h"
#include "kernel/worlds.h"

namespace show {

namespace {

bool byte_waiting(void*) { return serial::byte_ready(); }

bool is_world(const files::File& f) {
    raster::ParseError e;
    return raster::scene_version(reinterpret_cast<const char*>(f.data), f.size, &e) == 2;
}

// Plays one scene through its frames; false when a byte arrived (stop the show).
bool play(const files::File& f, const raster::Mapper& mapper) {
    raster::ParseError e;
    if (!worlds::load(f.name, f.data, f.size, &e)) return true;  // a bad module: on to the next
    for (int32_t n = 0; n < worlds::world().frames; ++n) {
        if (serial::byte_ready()) return false;
        int page = vga::shown_page() == 0 ? 1 : 0;
        worlds::render(n, mapper, raster::Surface::Linear, page, raster::Variant::Asm);
        vga::flip(page);
    }
    return true;
}

void patterns(uint32_t interval_ms) {
    for (uint32_t n = 0;; ++n) {
        if (serial::byte_ready()) return;
        int page = (vga::shown_page() + 1) % vga::MODEX_PAGES;
        draw::pattern(raster::Pattern(n % raster::PATTERN_COUNT), page);
        vga::flip(page);
        if (timer::wait_ms_or(interval_ms, byte_waiting, nullptr)) return;
    }
}

}  // namespace

void run(uint32_t interval_ms, bool show_patterns, lib::StrView scene, lib::StrView mapper_name) {
    if (vga::mode() != vga::Mode::ModeX) vga::set_mode_x();
    if (show_patterns) return patterns(interval_ms);
    const raster::Mapper* mapper = mapper_name.empty() ? nullptr : raster::find_mapper(mapper_name);
    if (!mapper) mapper = raster::find_mapper("auto");
    bool any = false;
    for (int i = 0; i < files::count(); ++i) any = any || is_world(files::at(i));
    if (!any) return patterns(interval_ms);
    for (;;) {
        for (int i = 0; i < files::count(); ++i) {
            const files::File& f = files::at(i);
            if (!scene.empty() && !scene.equals(f.name)) continue;
            if (!is_world(f)) continue;
            if (files::find(lib::StrView{f.name, lib::c_length(f.name)}) != &f) continue;  // shadowed by a module
            if (!play(f, *mapper)) return;
        }
        if (!scene.empty() && !files::find(scene)) return patterns(interval_ms);  // no such scene
    }
}

}  // namespace show
