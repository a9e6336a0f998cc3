// The current 3D scene and its frames.
#include "kernel/present/current_world.h"

#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/present/file_table.h"
#include "kernel/core/choice.h"
#include "kernel/platform/guard.h"
#include "kernel/lib/mem.h"
#include "kernel/lib/words.h"

namespace current_world {

namespace {

// The world and the frame the mappers draw from, between guard pages (guard.h); the texture set is
// built here, then each texture and its copies go to buffers of their own in the pool (place_textures).
raster::World& g_world = *guard::take_object<raster::World>("3D scene");
raster::Frame& g_frame = *guard::take_object<raster::Frame>("frame");
raster::TextureSet& g_textures = *guard::take_object<raster::TextureSet>("texture set");
raster::FrameScratch& g_scratch = *guard::take_object<raster::FrameScratch>("frame scratch");
bool g_loaded = false;
bool g_overridden = false;
raster::Budget g_override;
char g_name[raster::MAX_FILE_NAME];

// Copies each texture of the world, and its bordered, aligned and doubled copies, to buffers of their own that
// end against a guard page, and points the objects' textures at them (a texture's copies are shared
// by the objects that use it). The last world's buffers are given back first (transient: the
// buffers kept for the boot are never touched).
void place_textures() {
    guard::release_transient();
    raster::Texture placed[raster::MAX_WORLD_TEXTURES] = {};
    for (int32_t o = 0; o < g_world.object_count; ++o) {
        const int32_t i = g_world.objects[o].texture;
        raster::Texture& t = placed[i];
        const raster::Texture& built = g_textures.objects[o];
        if (!t.texels) {
            const char* name = g_world.textures[i].name;
            const size_t texels = size_t(built.width) * size_t(built.height), bordered = size_t(raster::bordered_bytes(built.width, built.height));
            uint8_t* at = guard::take_transient(texels, "world texture", name);
            memcpy(at, built.texels, texels);
            t.texels = at;
            if (built.bordered) {
                at = guard::take_transient(bordered, "world texture (bordered copy)", name);
                memcpy(at, built.bordered, bordered);
                t.bordered = at;
            }
            if (built.aligned256) t.aligned256 = raster::make_aligned256(built, guard::take_transient(raster::ALIGNED256_BYTES, "world texture (aligned copy)", name));
            if (raster::wants_doubled(built))  // (the set keeps none: built here only)
                t.doubled = raster::make_doubled(built, guard::take_transient(size_t(raster::doubled_bytes(built.width, built.height)), "world texture (doubled copy)", name));
        }
        g_textures.objects[o].texels = t.texels;
        g_textures.objects[o].bordered = t.bordered;
        g_textures.objects[o].aligned256 = t.aligned256;
        g_textures.objects[o].doubled = t.doubled;
    }
}

// auto's candidate lists for the objects' textures at the budget in force, built before any frame
// (choice.h, prepare_choice).
void prepare_choices() {
    for (int32_t o = 0; o < g_world.object_count; ++o) raster::prepare_choice(budget(), g_textures.objects[o]);
}

}  // namespace

bool load(const char* name, const uint8_t* text, size_t length, raster::ParseError* error) {
    g_loaded = false;
    g_overridden = false;
    if (!raster::parse_world(reinterpret_cast<const char*>(text), length, file_table::resolver(), &g_world, error)) return false;
    raster::build_texture_set(g_world, &g_textures);
    place_textures();
    prepare_choices();
    lib::copy_c_string(g_name, sizeof g_name, name);
    g_loaded = true;
    if (vga::mode() != vga::Mode::Text) vga::load_palette(g_world.palette);
    return true;
}

bool loaded() { return g_loaded; }

void set_budget(const raster::Budget* override) {
    g_overridden = override != nullptr;
    if (override) g_override = *override;
    prepare_choices();
}
raster::Budget budget() { return g_overridden ? g_override : g_world.budget; }
bool budget_overridden() { return g_overridden; }

const raster::World& world() { return g_world; }
const char* name() { return g_name; }

FrameResult render(int32_t n, const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant,
                   raster::Probe* probe, const raster::Watch* watch) {
    FrameResult r{};
    uint64_t t0 = timer::now();
    raster::build_frame(g_world, n, &g_frame, &g_scratch);
    if (g_overridden) g_frame.budget = g_override;
    r.ticks_geometry = timer::since(t0);
    r.frame = g_frame.stats;
    present::Canvas c = present::begin(mapper, surface, page, variant);
    if (probe) probe->start();
    r.render = present::finish(c, raster::render_frame(g_frame, g_textures, mapper, c.axis, c.target, variant, probe, watch));
    return r;
}

const char* const BENCH_FIELD_NAMES[B_FIELDS] = {"ticks",      "ticks_geometry", "ticks_clear",  "ticks_draw", "ticks_setup",
                                                 "ticks_walk", "ticks_inner",    "ticks_choose", "ticks_blit", "ticks_flip"};

raster::Probe bench_probe() {
    raster::Probe p;
    p.clock = timer::reader();
    p.calibrate();
    return p;
}

BenchFrame bench_frame(uint32_t i, uint32_t count, const raster::Mapper& mapper, raster::Surface surface, raster::Variant variant,
                       const raster::Probe& probe, const raster::Watch* watch) {
    BenchFrame b{};
    b.frame = int32_t(uint64_t(i) * uint32_t(g_world.frames) / count);
    b.page = vga::shown_page() == 0 ? 1 : 0;
    const FrameResult f = render(b.frame, mapper, surface, b.page, variant, nullptr, watch);
    raster::Probe timed = probe;
    b.cut = f.render.stats.interrupted || render(b.frame, mapper, surface, b.page, variant, &timed, watch).render.stats.interrupted;
    if (b.cut) return b;
    const uint64_t t0 = timer::now();
    b.retrace = vga::flip(b.page);
    const uint64_t flip = timer::since(t0);
    const present::RenderResult& r = f.render;
    const uint64_t setup = timed.net(raster::Phase::Setup), inner = timed.net(raster::Phase::Inner), choose = timed.net(raster::Phase::Choose);
    // walking: the untimed drawing less the timed run's other phases; on a coarse clock (the PIT)
    // those may add up to more than it, and the drawing is then their sum
    const uint64_t timed_phases = setup + inner + choose, draw = r.ticks_draw > timed_phases ? r.ticks_draw : timed_phases;
    const uint64_t walk = draw - timed_phases;
    const uint64_t figures[B_FIELDS] = {f.ticks_geometry + r.ticks_clear + draw + r.ticks_blit, f.ticks_geometry, r.ticks_clear, draw,
                                        setup, walk, inner, choose, r.ticks_blit, flip};
    for (uint32_t k = 0; k < B_FIELDS; ++k) b.figures[k] = figures[k];
    b.stats = r.stats;
    b.used_asm = r.used_asm;
    return b;
}

}  // namespace current_world
