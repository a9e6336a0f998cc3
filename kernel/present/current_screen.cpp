// The current screen-space scene (a version 1 scene file) and drawing it.
#include "kernel/present/current_screen.h"

#include "kernel/mappers/auto/choice.h"
#include "kernel/platform/guard.h"
#include "kernel/present/parts.h"
#include "kernel/lib/fmt.h"
#include "kernel/lib/mem.h"
#include "kernel/scene/scene_text.h"

namespace current_screen {

namespace {

raster::Scene& g_parsed = *guard::take_object<raster::Scene>("scene being parsed");  // parsed into here first, so a bad upload leaves the current scene alone
bool g_loaded = false;
uint32_t g_generation = 0;  // guard's transient generation its buffers belong to
raster::Scene* g_scene = nullptr;
raster::Texture g_texture;

// What the mappers read and write, each in a buffer of its own between guard pages, sized to the
// scene and taken at its load (parts.h; transient: the 3D scene's load gives them back): the scene's
// vertices, its texture and the texture's copies. Returns what they take of the pool.
size_t scene_parts(const raster::Scene& parsed, bool take) {
    static constexpr present::TextureNames NAMES{"screen-space texture", "screen-space texture (bordered copy)",
                                                 "screen-space texture (aligned copy)", "screen-space texture (doubled copy)"};
    present::Parts p{take ? present::Take::Transient : present::Take::Count};
    raster::Scene* scene = p.of<raster::Scene>(1, "screen-space scene");
    const raster::Texture t = present::texture_parts(p, raster::Texture{nullptr, parsed.texture_width, parsed.texture_height, parsed.wrap}, true,
                                                     NAMES, nullptr, &parsed.texture_kind);
    if (take) {
        memcpy(scene, &parsed, sizeof(raster::Scene));
        g_scene = scene;
        g_texture = t;
    }
    return p.bytes;
}

// A screen scene's budget: the default (no budget line), with the kernel's candidate lists.
raster::Budget budget() {
    raster::Budget b = raster::DEFAULT_BUDGET;
    b.lists = present::choice_lists();
    return b;
}

}  // namespace

bool load(const char* text, size_t length, raster::ParseError* error) {
    if (!raster::parse_scene(text, length, &g_parsed, error)) return false;
    const size_t need = scene_parts(g_parsed, false);
    if (need > guard::room_after_release()) return present::no_room(error, "its vertices and texture", need);
    guard::release_transient();
    g_generation = guard::transient_generation();
    scene_parts(g_parsed, true);
    raster::prepare_choice(budget(), g_texture);  // auto's candidates, before any render
    g_loaded = true;
    return true;
}

bool loaded() { return g_loaded && g_generation == guard::transient_generation(); }
const raster::Texture& texture() { return g_texture; }

const raster::Scene& scene() { return *g_scene; }

present::RenderResult render(const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant,
                             const raster::Watch* watch) {
    present::Canvas c = present::begin(mapper, surface, page, variant);
    return present::finish(c, raster::render_scene(*g_scene, g_texture, mapper, c.axis, c.target, variant, nullptr, watch, budget()));
}

}  // namespace current_screen
