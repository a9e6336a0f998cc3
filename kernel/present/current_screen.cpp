// The current screen-space scene (a version 1 scene file) and drawing it.
#include "kernel/present/current_screen.h"

#include "kernel/core/choice.h"
#include "kernel/platform/guard.h"
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

// What the mappers read and write, each in a buffer of its own between guard pages (guard.h),
// sized to the scene and taken at its load (transient: the 3D scene's load gives them back): the
// scene's vertices, its texture and the texture's copies.
size_t buffers_bytes(const raster::Texture& t) {
    size_t n = guard::footprint(sizeof(raster::Scene)) + guard::footprint(size_t(t.width) * size_t(t.height)) +
               guard::footprint(size_t(raster::bordered_bytes(t.width, t.height)));
    if (raster::wants_aligned256(t)) n += guard::footprint(raster::ALIGNED256_BYTES);
    if (raster::wants_doubled(t)) n += guard::footprint(size_t(raster::doubled_bytes(t.width, t.height)));
    return n;
}

}  // namespace

bool load(const char* text, size_t length, raster::ParseError* error) {
    if (!raster::parse_scene(text, length, &g_parsed, error)) return false;
    const raster::Scene& parsed = g_parsed;
    raster::Texture t{nullptr, parsed.texture_width, parsed.texture_height, parsed.wrap};
    const size_t need = buffers_bytes(t);
    if (need > guard::room_after_release()) {
        lib::Fmt m;
        m.s("not enough memory for this scene: its vertices and texture need ").u(uint32_t(need >> 10)).s(" KiB, ");
        m.u(uint32_t(guard::room_after_release() >> 10)).s(" KiB free (docs/platform.md, Memory)");
        return raster::scene_text::fail(error, 0, m.c_str());
    }
    guard::release_transient();
    g_generation = guard::transient_generation();
    g_scene = reinterpret_cast<raster::Scene*>(guard::take_transient(sizeof(raster::Scene), "screen-space scene"));
    memcpy(g_scene, &parsed, sizeof(raster::Scene));
    const size_t texels = size_t(t.width) * size_t(t.height);
    uint8_t* at = guard::take_transient(texels, "screen-space texture");
    raster::generate_texture(parsed.texture_kind, t.width, t.height, at);
    t.texels = at;
    uint8_t* bordered = guard::take_transient(size_t(raster::bordered_bytes(t.width, t.height)), "screen-space texture (bordered copy)");
    uint8_t* aligned = raster::wants_aligned256(t) ? guard::take_transient(raster::ALIGNED256_BYTES, "screen-space texture (aligned copy)") : nullptr;
    uint8_t* doubled = raster::wants_doubled(t)
                           ? guard::take_transient(size_t(raster::doubled_bytes(t.width, t.height)), "screen-space texture (doubled copy)")
                           : nullptr;
    raster::prepare_texture(&t, bordered, aligned, doubled);
    g_texture = t;
    raster::prepare_choice(raster::DEFAULT_BUDGET, g_texture);  // auto's candidates, before any render
    g_loaded = true;
    return true;
}

bool loaded() { return g_loaded && g_generation == guard::transient_generation(); }
const raster::Texture& texture() { return g_texture; }

const raster::Scene& scene() { return *g_scene; }

present::RenderResult render(const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant,
                             const raster::Watch* watch) {
    present::Canvas c = present::begin(mapper, surface, page, variant);
    return present::finish(c, raster::render_scene(*g_scene, g_texture, mapper, c.axis, c.target, variant, nullptr, watch));
}

}  // namespace current_screen
