// The current 3D scene and its frames.
#include "kernel/present/current_world.h"

#include "drivers/serial.h"
#include "drivers/timer.h"
#include "kernel/lib/json.h"
#include "drivers/vga.h"
#include "kernel/present/file_table.h"
#include "kernel/present/parts.h"
#include "kernel/mappers/auto/choice.h"
#include "kernel/platform/cycle_marks.h"
#include "kernel/platform/guard.h"
#include "kernel/lib/mem.h"
#include "kernel/lib/words.h"
#include "kernel/scene/scene_text.h"
#include "kernel/scene/text.h"
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

using present::Parts;

// The world's parts, as world_room counts them.
size_t world_parts(const raster::WorldRoom& r, bool take) {
    Parts p{take ? present::Take::Transient : present::Take::Count};
    uint8_t* texels = p.of<uint8_t>(int32_t(r.texels), "3D scene's texels (as parsed)");
    raster::Vec3* positions = p.of<raster::Vec3>(r.positions, "3D scene's positions");
    raster::TexCoord* uvs = p.of<raster::TexCoord>(r.uvs, "3D scene's texture coordinates");
    raster::Face* faces = p.of<raster::Face>(r.faces, "3D scene's faces");
    raster::Corner* corners = p.of<raster::Corner>(r.corners, "3D scene's face corners");
    if (take) {
        raster::World& w = g_world;
        w.room = r;
        w.texels = texels, w.positions = positions, w.uvs = uvs, w.faces = faces, w.corners = corners;
    }
    return p.bytes;
}

// The frame's polygons and the frame scratch, as frame_room counts them.
size_t frame_parts(const raster::FrameRoom& r, bool take) {
    Parts p{take ? present::Take::Transient : present::Take::Count};
    uint8_t* polygon[3];  // sizes, objects, flags
    for (uint8_t*& at : polygon) at = p.of<uint8_t>(r.polygons, "frame's polygons");
    raster::Vertex* vertices = p.of<raster::Vertex>(r.vertices, "frame's vertices");
    raster::ClipPoint* positions = p.of<raster::ClipPoint>(r.positions, "frame scratch (positions)");
    uint8_t* outcodes = p.of<uint8_t>(r.positions, "frame scratch (outcodes)");
    raster::Fixed24_8* screen_x = p.of<raster::Fixed24_8>(r.positions, "frame scratch (x)");
    raster::Fixed24_8* screen_y = p.of<raster::Fixed24_8>(r.positions, "frame scratch (y)");
    raster::FrameScratch::Entry* entries = p.of<raster::FrameScratch::Entry>(r.polygons, "frame scratch (faces)");
    uint32_t* keys[4];
    int32_t* order[2];
    for (uint32_t*& at : keys) at = p.of<uint32_t>(r.polygons, "frame scratch (sort keys)");
    for (int32_t*& at : order) at = p.of<int32_t>(r.polygons, "frame scratch (sort order)");
    if (take) {
        raster::Frame& f = g_frame;
        f.room = r;
        f.polygon_size = polygon[0], f.polygon_object = polygon[1], f.polygon_whole = polygon[2], f.vertices = vertices;
        raster::FrameScratch& h = g_scratch;
        h.room = r;
        h.positions = positions, h.outcodes = outcodes, h.screen_x = screen_x, h.screen_y = screen_y, h.entries = entries;
        for (int k = 0; k < 2; ++k) h.key_lo[k] = keys[k], h.key_hi[k] = keys[2 + k], h.order[k] = order[k];
    }
    return p.bytes;
}

// Each texture of the world in a buffer of its own, with its bordered, aligned and doubled copies
// in theirs, each ending against a guard page; the objects' textures point at them (a texture's
// copies are shared by the objects that use it). Without `doubled`, no doubled copies: fast-table
// then refuses the textures that would have one, and the other fast loops those above 256.
size_t texture_parts(bool doubled, bool take) {
    static constexpr present::TextureNames NAMES{"world texture", "world texture (bordered copy)", "world texture (aligned copy)",
                                                 "world texture (doubled copy)"};
    Parts p{take ? present::Take::Transient : present::Take::Count};
    raster::Texture placed[raster::MAX_WORLD_TEXTURES] = {};
    for (int32_t i = 0; i < g_world.texture_count; ++i) {
        const raster::WorldTexture& w = g_world.textures[i];
        placed[i] = present::texture_parts(p, raster::Texture{g_world.texels + w.offset, w.width, w.height, raster::Wrap::Repeat}, doubled, NAMES, w.name);
    }
    for (int32_t o = 0; take && o < g_world.object_count; ++o) {
        raster::Texture t = placed[g_world.objects[o].texture];
        t.wrap = g_world.objects[o].wrap;
        g_textures.objects[o] = t;
    }
    return p.bytes;
}

// auto's candidate lists for the objects' textures at the budget in force, built before any frame
// (mappers/auto/choice.h, prepare_choice).
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
    const size_t world = world_parts(room, false);
    if (world > guard::transient_room()) return present::no_room(error, "its meshes and textures", world);
    world_parts(room, true);
    if (!raster::parse_world(chars, length, file_table::resolver(), &g_world, error)) return false;
    // the frame and every copy of every texture; where they do not fit, the doubled copies left out
    // (the largest: four times the texels) before the scene is refused
    const raster::FrameRoom frame = raster::frame_room(g_world);
    const size_t all = frame_parts(frame, false) + texture_parts(true, false), fewer = frame_parts(frame, false) + texture_parts(false, false);
    if (fewer > guard::transient_room()) return present::no_room(error, "its frames and its textures' copies", world + all);
    g_doubled = all <= guard::transient_room();
    frame_parts(frame, true);
    texture_parts(g_doubled, true);
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
raster::Budget budget() {
    raster::Budget b = g_overridden ? g_override : g_world.budget;
    b.lists = present::choice_lists();
    return b;
}
bool budget_overridden() { return g_overridden; }

const raster::World& world() { return g_world; }
const char* name() { return g_name; }

FrameResult render(int32_t n, const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant,
                   raster::Probe* probe, const raster::Watch* watch) {
    FrameResult r{};
    uint64_t t0 = timer::now();
    raster::build_frame(g_world, n, &g_frame, &g_scratch);
    g_frame.budget = budget();
    r.ticks_geometry = timer::since(t0);
    r.frame = g_frame.stats;
    present::Canvas c = present::begin(mapper, surface, page, variant);
    if (probe) probe->start();
    r.render = present::finish(c, raster::render_frame(g_frame, g_textures, mapper, c.axis, c.target, variant, probe, watch));
    return r;
}

const char* const BENCH_FIELD_NAMES[B_FIELDS] = {"ticks",      "ticks_geometry", "ticks_clear",  "ticks_draw", "ticks_setup",
                                                 "ticks_walk", "ticks_inner",    "ticks_choose", "ticks_blit", "ticks_flip"};

void start_bench_row() { raster::forget_objects(present::choice_lists()); }

raster::Probe bench_probe() {
    raster::Probe p;
    p.clock = timer::reader();
    p.marks = modexlab_cycle_marks;
    p.calibrate();
    return p;
}

BenchFrame bench_frame(uint32_t i, uint32_t count, const raster::Mapper& mapper, raster::Surface surface, raster::Variant variant,
                       const raster::Probe& probe, const raster::Watch* watch, const char* caption) {
    BenchFrame b{};
    b.frame = int32_t(uint64_t(i) * uint32_t(g_world.frames) / count);
    b.page = vga::shown_page() == 0 ? 1 : 0;
    cycle_marks::mark(cycle_marks::FrameStart);
    const FrameResult f = render(b.frame, mapper, surface, b.page, variant, nullptr, watch);
    cycle_marks::mark(cycle_marks::FrameEnd);
    raster::Probe timed = probe;
    b.cut = f.render.stats.interrupted || render(b.frame, mapper, surface, b.page, variant, &timed, watch).render.stats.interrupted;
    if (b.cut) return b;
    if (caption) {
        const lib::StrView line{caption, lib::c_length(caption)};
        raster::Target t = vga::page_target(b.page);
        raster::draw_text_box(t, 0, 0, &line, 1, raster::text_colours(g_world.palette));
    }
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
