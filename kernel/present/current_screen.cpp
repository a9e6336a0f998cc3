// The current screen-space scene (a version 1 scene file) and drawing it.
#include "kernel/present/current_screen.h"

#include "kernel/core/choice.h"
#include "kernel/platform/guard.h"
#include "kernel/lib/mem.h"

namespace current_screen {

namespace {

raster::Scene& g_parsed = *guard::take_object<raster::Scene>("scene being parsed");  // parsed into here first, so a bad upload leaves the current scene alone
bool g_loaded = false;
raster::Texture g_texture;

// What the mappers read and write, each between guard pages (guard.h): the scene's vertices, its
// texture and the texture's copies (each placed to end where its buffer ends).
constexpr size_t TEXELS_BYTES = size_t(raster::MAX_TEXTURE_SIZE) * raster::MAX_TEXTURE_SIZE;
constexpr size_t BORDERED_BYTES = size_t(raster::MAX_TEXTURE_SIZE + 2) * (raster::MAX_TEXTURE_SIZE + 2);
constexpr size_t DOUBLED_BYTES = size_t(raster::doubled_bytes(raster::MAX_TEXTURE_SIZE, raster::MAX_TEXTURE_SIZE));
struct Buffers {
    raster::Scene* scene = guard::take_object<raster::Scene>("screen-space scene");
    uint8_t* texels = guard::take(TEXELS_BYTES, "screen-space texture");
    uint8_t* bordered = guard::take(BORDERED_BYTES, "screen-space texture (bordered copy)");
    uint8_t* aligned = guard::take(raster::ALIGNED256_BYTES, "screen-space texture (aligned copy)");
    uint8_t* doubled = guard::take(DOUBLED_BYTES, "screen-space texture (doubled copy)");
};
// Taken when the kernel starts (a global constructor), not on first use: the first drawing then
// costs what every other does (icount: the same frame, the same instructions).
Buffers g_buffers;
Buffers& buffers() { return g_buffers; }

}  // namespace

bool load(const char* text, size_t length, raster::ParseError* error) {
    if (!raster::parse_scene(text, length, &g_parsed, error)) return false;
    Buffers& b = buffers();
    memcpy(b.scene, &g_parsed, sizeof(raster::Scene));
    const raster::Scene& sc = *b.scene;
    const size_t texels = size_t(sc.texture_width) * size_t(sc.texture_height);
    uint8_t* at = b.texels + TEXELS_BYTES - texels;  // its last texel against the guard page
    raster::generate_texture(sc.texture_kind, sc.texture_width, sc.texture_height, at);
    g_texture = raster::Texture{at, sc.texture_width, sc.texture_height, sc.wrap};
    raster::prepare_texture(&g_texture, b.bordered + BORDERED_BYTES - size_t(raster::bordered_bytes(sc.texture_width, sc.texture_height)),
                            b.aligned, b.doubled + DOUBLED_BYTES - size_t(raster::doubled_bytes(sc.texture_width, sc.texture_height)));
    raster::prepare_choice(raster::DEFAULT_BUDGET, g_texture);  // auto's candidates, before any render
    g_loaded = true;
    return true;
}

bool loaded() { return g_loaded; }
const raster::Texture& texture() { return g_texture; }

const raster::Scene& scene() { return *buffers().scene; }

present::RenderResult render(const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant,
                             const raster::Watch* watch) {
    present::Canvas c = present::begin(mapper, surface, page, variant);
    return present::finish(c, raster::render_scene(*buffers().scene, g_texture, mapper, c.axis, c.target, variant, nullptr, watch));
}

}  // namespace current_screen
