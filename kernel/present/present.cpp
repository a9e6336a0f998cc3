// Presenting a drawing through one of three surfaces.
#include "kernel/present/present.h"

#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/lib/mem.h"
#include "kernel/mappers/auto/choice.h"
#include "kernel/platform/guard.h"

namespace present {

namespace {

// The RAM surfaces, between guard pages (guard.h), taken when the kernel starts (a global
// constructor), not on first use: the first drawing then costs what every other does.
uint8_t* const g_linear = guard::take(raster::SCREEN_PIXELS, "RAM surface (linear)");
uint8_t* const g_planes = guard::take(raster::SCREEN_PIXELS, "RAM surface (planar)");

}  // namespace

Canvas begin(const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant) {
    Canvas c{};
    c.t0 = timer::now();
    c.surface = surface;
    c.page = page;
    c.axis = raster::surface_axis(mapper, surface);
    switch (surface) {
    case raster::Surface::Linear:
        memset(g_linear, 0, raster::SCREEN_PIXELS);
        c.target = raster::linear_target(g_linear, raster::SCREEN_WIDTH, raster::SCREEN_HEIGHT, raster::SCREEN_WIDTH);
        break;
    case raster::Surface::Planar:
        memset(g_planes, 0, raster::SCREEN_PIXELS);
        c.target = raster::planar_target(g_planes);
        break;
    case raster::Surface::Vga:
        vga::clear_page(page, 0);
        c.target = vga::page_target(page);
        break;
    }
    c.t1 = timer::now();
    const raster::LoopFn loop = raster::mapper_loop(mapper, variant, c.target);
    c.used_asm = loop && loop == mapper.asm_loop;
    return c;
}

RenderResult finish(const Canvas& c, const raster::RenderStats& stats) {
    const uint64_t t2 = timer::now();
    if (c.surface == raster::Surface::Linear) vga::blit_linear(g_linear, c.page);
    if (c.surface == raster::Surface::Planar) vga::blit_planar(g_planes, c.page);
    const uint64_t t3 = timer::now();
    RenderResult r{};
    r.stats = stats;
    r.used_asm = c.used_asm;
    r.ticks_clear = timer::between(c.t0, c.t1);
    r.ticks_draw = timer::between(c.t1, t2);
    r.ticks_blit = timer::between(t2, t3);
    return r;
}

raster::ChoiceLists* choice_lists() {
    static raster::ChoiceLists lists;
    return &lists;
}

}  // namespace present
