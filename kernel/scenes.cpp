// The current screen-space scene, and rendering through the three surfaces.
#include "kernel/scenes.h"

#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/lib/mem.h"

namespace scenes {

namespace {

raster::Scene g_parsed;     // parsed into here first, so a bad upload leaves the current scene alone
raster::Scene g_scene;
bool g_loaded = false;
uint8_t g_texels[raster::MAX_TEXTURE_SIZE * raster::MAX_TEXTURE_SIZE];
uint8_t g_bordered[(raster::MAX_TEXTURE_SIZE + 2) * (raster::MAX_TEXTURE_SIZE + 2)];
uint8_t g_aligned[raster::ALIGNED256_BYTES];
raster::Texture g_texture;
alignas(4) uint8_t g_linear[raster::SCREEN_PIXELS];
alignas(4) uint8_t g_planes[raster::SCREEN_PIXELS];

}  // namespace

bool load(const char* text, size_t length, raster::ParseError* error) {
    if (!raster::parse_scene(text, length, &g_parsed, error)) return false;
    memcpy(&g_scene, &g_parsed, sizeof g_scene);
    raster::generate_texture(g_scene.texture_kind, g_scene.texture_width, g_scene.texture_height, g_texels);
    g_texture = raster::Texture{g_texels, g_scene.texture_width, g_scene.texture_height, g_scene.wrap};
    raster::prepare_texture(&g_texture, g_bordered, g_aligned);
    g_loaded = true;
    return true;
}

bool loaded() { return g_loaded; }
const raster::Texture& texture() { return g_texture; }

const raster::Scene& scene() { return g_scene; }

RenderResult render_with(const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant, DrawFn draw, void* ctx) {
    RenderResult r{};
    uint64_t t0 = timer::rdtsc();
    raster::Target target;
    raster::Axis axis = raster::surface_axis(mapper, surface);
    switch (surface) {
    case raster::Surface::Linear:
        memset(g_linear, 0, sizeof g_linear);
        target = raster::linear_target(g_linear, raster::SCREEN_WIDTH, raster::SCREEN_HEIGHT, raster::SCREEN_WIDTH);
        break;
    case raster::Surface::Planar:
        memset(g_planes, 0, sizeof g_planes);
        target = raster::planar_target(g_planes);
        break;
    case raster::Surface::Vga:
        vga::clear_page(page, 0);
        target = vga::page_target(page);
        break;
    }
    uint64_t t1 = timer::rdtsc();
    raster::LoopFn loop = raster::mapper_loop(mapper, variant, target);
    r.used_asm = loop && loop == mapper.asm_loop;
    r.stats = draw(ctx, target, axis, variant);
    uint64_t t2 = timer::rdtsc();
    if (surface == raster::Surface::Linear) vga::blit_linear(g_linear, page);
    if (surface == raster::Surface::Planar) vga::blit_planar(g_planes, page);
    uint64_t t3 = timer::rdtsc();
    r.ticks_clear = t1 - t0;
    r.ticks_draw = t2 - t1;
    r.ticks_blit = t3 - t2;
    return r;
}

RenderResult render(const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant, const raster::Watch* watch) {
    struct Drawing {
        const raster::Mapper* mapper;
        const raster::Watch* watch;
    } drawing{&mapper, watch};
    return render_with(mapper, surface, page, variant,
                       [](void* ctx, raster::Target& target, raster::Axis axis, raster::Variant v) {
                           auto* d = static_cast<Drawing*>(ctx);
                           return raster::render_scene(g_scene, g_texture, *d->mapper, axis, target, v, nullptr, d->watch);
                       },
                       &drawing);
}

}  // namespace scenes
