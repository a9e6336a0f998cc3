// The current 3D scene and its frames.
#include "kernel/worlds.h"

#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/files.h"

namespace worlds {

namespace {

raster::World g_world;
raster::TextureSet g_textures;
raster::Frame g_frame;
raster::FrameScratch g_scratch;
bool g_loaded = false;
bool g_overridden = false;
raster::Budget g_override;
char g_name[raster::MAX_FILE_NAME];

}  // namespace

bool load(const char* name, const uint8_t* text, size_t length, raster::ParseError* error) {
    g_loaded = false;
    g_overridden = false;
    if (!raster::parse_world(reinterpret_cast<const char*>(text), length, files::resolver(), &g_world, error)) return false;
    raster::build_texture_set(g_world, &g_textures);
    size_t i = 0;
    for (; name[i] && i + 1 < sizeof g_name; ++i) g_name[i] = name[i];
    g_name[i] = 0;
    g_loaded = true;
    if (vga::mode() != vga::Mode::Text) vga::load_palette(g_world.palette);
    return true;
}

bool loaded() { return g_loaded; }

void set_budget(const raster::Budget* override) {
    g_overridden = override != nullptr;
    if (override) g_override = *override;
}
raster::Budget budget() { return g_overridden ? g_override : g_world.budget; }
bool budget_overridden() { return g_overridden; }

const raster::World& world() { return g_world; }
const char* name() { return g_name; }

FrameResult render(int32_t n, const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant,
                   raster::Probe* probe, const raster::Watch* watch) {
    FrameResult r{};
    uint64_t t0 = timer::rdtsc();
    raster::build_frame(g_world, n, &g_frame, &g_scratch);
    if (g_overridden) g_frame.budget = g_override;
    r.ticks_geometry = timer::rdtsc() - t0;
    r.frame = g_frame.stats;
    struct Drawing {
        const raster::Mapper* mapper;
        raster::Probe* probe;
        const raster::Watch* watch;
    } drawing{&mapper, probe, watch};
    r.render = scenes::render_with(mapper, surface, page, variant,
                                   [](void* ctx, raster::Target& target, raster::Axis axis, raster::Variant v) {
                                       auto* d = static_cast<Drawing*>(ctx);
                                       if (d->probe) d->probe->start();
                                       return raster::render_frame(g_frame, g_textures, *d->mapper, axis, target, v, d->probe, d->watch);
                                   },
                                   &drawing);
    return r;
}

}  // namespace worlds
