// The current 3D scene and its frames.
#include "kernel/present/current_world.h"

#include "drivers/serial.h"
#include "drivers/timer.h"
#include "kernel/lib/json.h"
#include "drivers/vga.h"
#include "kernel/present/file_table.h"
#include "kernel/core/choice.h"
#include "kernel/platform/guard.h"
#include "kernel/lib/mem.h"
#include "kernel/lib/words.h"
#include "kernel/scene/scene_text.h"
#include "kernel/lib/fmt.h"

namespace current_world {

namespace {

// The world and the frame the mappers draw from. What is the same for every scene is kept for the
// boot; what a scene's size decides (the world's parts, the frame's polygons, the scratch, each
// texture and its copies) is taken at its load, each part a buffer of its own between guard pages
// (guard.h, transient: given back when the next scene is loaded).
raster::World& g_world = *guard::take_object<raster::World>("3D scene");
raster::Frame& g_frame = *guard::take_object<raster::Frame>("frame");
raster::TextureSet& g_textures = *guard::take_object<raster::TextureSet>("texture set");
raster::FrameScratch& g_scratch = *guard::take_object<raster::FrameScratch>("frame scratch");
bool g_loaded = false;
uint32_t g_generation = 0;  // guard's transient generation its buffers belong to
bool g_doubled = true;      // its textures have their doubled copies (else left out: memory)
bool g_overridden = false;
raster::Budget g_override;
char g_name[raster::MAX_FILE_NAME];

// `count` items of T (none: null), each part's name for fault reports.
template <typename T>
T* part(int32_t count, const char* what) {
    return count > 0 ? reinterpret_cast<T*>(guard::take_transient(size_t(count) * sizeof(T), what)) : nullptr;
}
template <typename T>
size_t part_bytes(int32_t count) {
    return count > 0 ? guard::footprint(size_t(count) * sizeof(T)) : 0;
}

size_t world_bytes(const raster::WorldRoom& r) {
    return part_bytes<uint8_t>(int32_t(r.texels)) + part_bytes<raster::Vec3>(r.positions) + part_bytes<raster::TexCoord>(r.uvs) +
           part_bytes<raster::Face>(r.faces) + part_bytes<raster::Corner>(r.corners);
}
void take_world(const raster::WorldRoom& r) {
    g_world.room = r;
    g_world.texels = part<uint8_t>(int32_t(r.texels), "3D scene's texels (as parsed)");
    g_world.positions = part<raster::Vec3>(r.positions, "3D scene's positions");
    g_world.uvs = part<raster::TexCoord>(r.uvs, "3D scene's texture coordinates");
    g_world.faces = part<raster::Face>(r.faces, "3D scene's faces");
    g_world.corners = part<raster::Corner>(r.corners, "3D scene's face corners");
}

size_t frame_bytes(const raster::FrameRoom& r) {
    using raster::FrameScratch;
    return 3 * part_bytes<uint8_t>(r.polygons) + part_bytes<raster::Vertex>(r.vertices) + part_bytes<raster::ClipPoint>(r.positions) +
           part_bytes<uint8_t>(r.positions) + 2 * part_bytes<raster::Fixed24_8>(r.positions) + part_bytes<FrameScratch::Entry>(r.polygons) +
           4 * part_bytes<uint32_t>(r.polygons) + 2 * part_bytes<int32_t>(r.polygons);
}
void take_frame(const raster::FrameRoom& r) {
    raster::Frame& f = g_frame;
    f.room = r;
    f.polygon_size = part<uint8_t>(r.polygons, "frame's polygon sizes");
    f.polygon_object = part<uint8_t>(r.polygons, "frame's polygon objects");
    f.polygon_whole = part<uint8_t>(r.polygons, "frame's polygon flags");
    f.vertices = part<raster::Vertex>(r.vertices, "frame's vertices");
    raster::FrameScratch& s = g_scratch;
    s.room = r;
    s.positions = part<raster::ClipPoint>(r.positions, "frame scratch (positions)");
    s.outcodes = part<uint8_t>(r.positions, "frame scratch (outcodes)");
    s.screen_x = part<raster::Fixed24_8>(r.positions, "frame scratch (x)");
    s.screen_y = part<raster::Fixed24_8>(r.positions, "frame scratch (y)");
    s.entries = part<raster::FrameScratch::Entry>(r.polygons, "frame scratch (faces)");
    for (int k = 0; k < 2; ++k) {
        s.key_lo[k] = part<uint32_t>(r.polygons, "frame scratch (sort keys)");
        s.key_hi[k] = part<uint32_t>(r.polygons, "frame scratch (sort keys)");
        s.order[k] = part<int32_t>(r.polygons, "frame scratch (sort order)");
    }
}

// Texture i of the world, repeated (its objects take their wraps).
raster::Texture world_texture(int32_t i) {
    const raster::WorldTexture& t = g_world.textures[i];
    return raster::Texture{g_world.texels + t.offset, t.width, t.height, raster::Wrap::Repeat};
}
size_t textures_bytes(bool doubled) {
    size_t n = 0;
    for (int32_t i = 0; i < g_world.texture_count; ++i) {
        const raster::Texture t = world_texture(i);
        n += guard::footprint(size_t(t.width) * size_t(t.height)) + guard::footprint(size_t(raster::bordered_bytes(t.width, t.height)));
        if (raster::wants_aligned256(t)) n += guard::footprint(raster::ALIGNED256_BYTES);
        if (doubled && raster::wants_doubled(t)) n += guard::footprint(size_t(raster::doubled_bytes(t.width, t.height)));
    }
    return n;
}

// Each texture of the world in a buffer of its own, with its bordered, aligned and doubled copies
// in theirs, each ending against a guard page; the objects' textures point at them (a texture's
// copies are shared by the objects that use it). Without `doubled`, no doubled copies: fast-table
// then refuses the textures that would have one, and the other fast loops those above 256.
void place_textures(bool doubled) {
    raster::Texture placed[raster::MAX_WORLD_TEXTURES] = {};
    for (int32_t i = 0; i < g_world.texture_count; ++i) {
        const raster::Texture t = world_texture(i);
        const char* name = g_world.textures[i].name;
        const size_t texels = size_t(t.width) * size_t(t.height);
        uint8_t* at = guard::take_transient(texels, "world texture", name);
        memcpy(at, t.texels, texels);
        placed[i] = raster::Texture{at, t.width, t.height, raster::Wrap::Repeat};
        uint8_t* bordered = guard::take_transient(size_t(raster::bordered_bytes(t.width, t.height)), "world texture (bordered copy)", name);
        uint8_t* aligned = raster::wants_aligned256(t) ? guard::take_transient(raster::ALIGNED256_BYTES, "world texture (aligned copy)", name) : nullptr;
        uint8_t* twice = doubled && raster::wants_doubled(t)
                             ? guard::take_transient(size_t(raster::doubled_bytes(t.width, t.height)), "world texture (doubled copy)", name)
                             : nullptr;
        raster::prepare_texture(&placed[i], bordered, aligned, twice);
    }
    for (int32_t o = 0; o < g_world.object_count; ++o) {
        raster::Texture t = placed[g_world.objects[o].texture];
        t.wrap = g_world.objects[o].wrap;
        g_textures.objects[o] = t;
    }
}

// The error for a scene the pool has no room for: what it needs, what is free.
bool no_room(raster::ParseError* error, const char* part, size_t need) {
    lib::Fmt m;
    m.s("not enough memory for this scene: ").s(part).s(" need ").u(uint32_t((need + 1023) >> 10)).s(" KiB, ");
    m.u(uint32_t(guard::room_after_release() >> 10)).s(" KiB free (docs/platform.md, Memory)");
    return raster::scene_text::fail(error, 0, m.c_str());
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
    guard::release_transient();
    g_generation = guard::transient_generation();
    const char* chars = reinterpret_cast<const char*>(text);
    const raster::WorldRoom room = raster::world_room(chars, length, file_table::resolver());
    if (world_bytes(room) > guard::transient_room()) return no_room(error, "its meshes and textures", world_bytes(room));
    take_world(room);
    if (!raster::parse_world(chars, length, file_table::resolver(), &g_world, error)) return false;
    // the frame and every copy of every texture; where they do not fit, the doubled copies left out
    // (the largest: four times the texels) before the scene is refused
    const raster::FrameRoom frame = raster::frame_room(g_world);
    const size_t all = frame_bytes(frame) + textures_bytes(true), fewer = frame_bytes(frame) + textures_bytes(false);
    if (fewer > guard::transient_room()) return no_room(error, "its frames and its textures' copies", world_bytes(room) + all);
    g_doubled = all <= guard::transient_room();
    take_frame(frame);
    place_textures(g_doubled);
    prepare_choices();
    lib::copy_c_string(g_name, sizeof g_name, name);
    g_loaded = true;
    if (vga::mode() != vga::Mode::Text) vga::load_palette(g_world.palette);
    return true;
}

bool loaded() { return g_loaded && g_generation == guard::transient_generation(); }

bool doubled_copies() { return g_doubled; }

void say_skipped(const char* name, const raster::ParseError& error) {
    lib::JsonLine(serial::sink()).str("event", "scene_skipped").str("scene", name).str("error", error.message).u32("line", uint32_t(error.line)).end();
}

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
