// The drawing commands: the screen-space scene (render), the 3D scene one frame at a time (frame),
// animated (play) and timed phase by phase (bench), and the mapper registry (mappers).
#include "drivers/serial.h"
#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/lib/stats.h"
#include "kernel/scene/scene_text.h"
#include "kernel/present/current_screen.h"
#include "kernel/platform/cycle_marks.h"
#include "kernel/platform/guard.h"
#include "kernel/platform/idt.h"
#include "kernel/server/commands.h"
#include "kernel/server/reply.h"
#include "kernel/present/current_world.h"

namespace server {

namespace {

constexpr uint32_t MAX_PLAY_FRAMES = 100000;
// Static: a frame's ticks for the median, 400 KB at the most, far beyond the 64 KiB kernel stack.
uint32_t* g_play_ticks = nullptr;  // taken at the first play and kept

// bench: each frame drawn twice, once plainly (the totals) and once with the probe (setup and
// inner loops; walking is the rest of the plain drawing time), then flipped.
constexpr uint32_t MAX_BENCH_FRAMES = 1000;
using current_world::B_FIELDS;
using current_world::BENCH_FIELD_NAMES;
// Static: every field of every frame for the medians, 36 KB, more than half the 64 KiB kernel stack.
uint32_t g_bench[B_FIELDS][MAX_BENCH_FRAMES];

// The polygons and pixels each mapper drew (auto draws with several), summed over frames.
struct MapperTally {
    uint64_t polygons[raster::MAPPER_LIMIT] = {}, pixels[raster::MAPPER_LIMIT] = {};
    uint64_t enveloped = 0, proven_whole = 0, proven_spans = 0;
    void add(const raster::RenderStats& s) {
        for (int i = 0; i < raster::MAPPER_COUNT; ++i) polygons[i] += s.mapper_polygons[i], pixels[i] += s.mapper_pixels[i];
        enveloped += s.enveloped, proven_whole += s.proven_whole, proven_spans += s.proven_spans;
    }
    // "drawn_by": [{"mapper": NAME, "polygons": N, "pixels": N}, ...], the mappers that drew any;
    // "enveloped", "proven_whole", "proven_spans": the polygons among them auto drew as their
    // object's envelope proved, as their whole polygon's bound did, as their spans' did (RenderStats)
    void write(lib::JsonLine& r) const {
        r.begin_array("drawn_by");
        for (int i = 0; i < raster::MAPPER_COUNT; ++i)
            if (polygons[i]) r.begin_item_object().str("mapper", raster::MAPPERS[i].name).u64("polygons", polygons[i]).u64("pixels", pixels[i]).end_object();
        r.end_array();
        r.u64("enveloped", enveloped).u64("proven_whole", proven_whole).u64("proven_spans", proven_spans);
    }
};

uint32_t clamp32(uint64_t v) { return v > 0xFFFFFFFFu ? 0xFFFFFFFFu : uint32_t(v); }

uint64_t render_ticks(const present::RenderResult& r) { return r.ticks_clear + r.ticks_draw + r.ticks_blit; }
uint64_t frame_ticks(const current_world::FrameResult& f) { return f.ticks_geometry + render_ticks(f.render); }

// Of pages 0 and 1, the one not shown: play and bench draw there, then flip.
int hidden_page() { return vga::shown_page() == 0 ? 1 : 0; }


void render_fields(lib::JsonLine& r, const DrawArgs& d, const present::RenderResult& res) {
    r.str("mapper", d.mapper->name)
        .u32("page", uint32_t(d.page))
        .str("surface", raster::surface_name(d.surface))
        .str("walker", walker_name(d.axis))
        .str("loop", res.used_asm ? "asm" : "twin")
        .u32("polygons", res.stats.polygons)
        .u32("skipped", res.stats.skipped)
        .u32("rejected", res.stats.rejected)
        .u32("spans", res.stats.spans)
        .u32("pixels", res.stats.pixels)
        .boolean("interrupted", res.stats.interrupted);
    MapperTally t;
    t.add(res.stats);
    t.write(r);
}

void frame_fields(lib::JsonLine& r, const current_world::FrameResult& f) {
    r.u32("faces", f.frame.faces)
        .u32("culled", f.frame.culled)
        .u32("outside", f.frame.outside)
        .u32("clipped", f.frame.clipped)
        .u32("overflow", f.frame.overflow)
        .u64("ticks", frame_ticks(f))
        .u64("ticks_geometry", f.ticks_geometry)
        .u64("ticks_clear", f.render.ticks_clear)
        .u64("ticks_draw", f.render.ticks_draw)
        .u64("ticks_blit", f.render.ticks_blit);
}

// The reply of play and bench begins alike: what was animated, and how.
// `frames` whole frames drawn of `asked`: fewer where the next line stopped the command (a frame it
// cut short is neither shown nor counted).
lib::JsonLine animation_reply(const char* cmd, uint32_t frames, uint32_t asked, const DrawArgs& d) {
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", cmd).str("scene", current_world::name()).u32("frames", frames).u32("frames_asked", asked).boolean("interrupted", frames < asked);
    r.str("mapper", d.mapper->name);
    r.str("surface", raster::surface_name(d.surface)).str("walker", walker_name(d.axis));
    return r;
}

}  // namespace

void cmd_render(Context& ctx, const StrView* args, size_t nargs) {
    DrawArgs d;
    if (!parse_draw_args("render", args, nargs, true, &d)) return;
    if (!current_screen::loaded()) {
        reply::error("render", "no screen-space scene: upload one with 'scene BYTES CRC32' or 'load NAME' first");
        return;
    }
    const raster::Texture& tex = current_screen::texture();
    if (!raster::mapper_accepts(*d.mapper, tex)) {
        lib::Fmt m;
        m.s("mapper ").s(d.mapper->name).s(" cannot take this scene's ").u(uint32_t(tex.width)).s("x").u(uint32_t(tex.height)).s(" texture (needs ");
        raster::describe_needs(m, d.mapper->needs & raster::SCENE_NEEDS);
        reply::error("render", m.s(")").c_str());
        return;
    }
    Progress p = progress("render", ctx);
    const raster::Watch watch = p.watch();
    present::RenderResult res = current_screen::render(*d.mapper, d.surface, d.page, d.variant, &watch);
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "render");
    render_fields(r, d, res);
    r.u64("ticks", render_ticks(res))
        .u64("ticks_clear", res.ticks_clear)
        .u64("ticks_draw", res.ticks_draw)
        .u64("ticks_blit", res.ticks_blit)
        .end();
}

void cmd_frame(Context& ctx, const StrView* args, size_t nargs) {
    uint32_t n;
    if (!lib::parse_u32(args[0], &n) || n >= uint32_t(raster::MAX_FRAMES)) {
        lib::Fmt m;
        m.s("bad frame number: 0..").u(uint32_t(raster::MAX_FRAMES - 1)).s(" (frame n shows time n/30 s)");
        reply::error("frame", m.c_str());
        return;
    }
    DrawArgs d;
    if (!parse_draw_args("frame", args + 1, nargs - 1, true, &d) || !need_world("frame")) return;
    Progress p = progress("frame", ctx);
    const raster::Watch watch = p.watch();
    current_world::FrameResult f = current_world::render(int32_t(n), *d.mapper, d.surface, d.page, d.variant, nullptr, &watch);
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "frame").str("scene", current_world::name()).u32("frame", n);
    render_fields(r, d, f.render);
    frame_fields(r, f);
    r.end();
}

void cmd_play(Context&, const StrView* args, size_t nargs) {
    uint32_t frames;
    DrawArgs d;
    if (!parse_animation_args("play", args, nargs, MAX_PLAY_FRAMES, "", &frames, &d)) return;
    if (!g_play_ticks) {
        if (!reply::room_for(guard::footprint(MAX_PLAY_FRAMES * sizeof(uint32_t)), "play", "play's frame times")) return;
        g_play_ticks = reinterpret_cast<uint32_t*>(guard::take(MAX_PLAY_FRAMES * sizeof(uint32_t), "play's frame times"));
    }
    uint64_t pixels = 0, total = 0, t_start = timer::now();
    MapperTally tally;
    uint32_t done = 0;
    Progress p{"play", 0, 0};  // stops a long frame; the frame events are the progress
    const raster::Watch watch = p.watch();
    for (uint32_t i = 0; i < frames && !interrupted(i); ++i, ++done) {
        int32_t n = int32_t(i % uint32_t(current_world::world().frames));
        d.page = hidden_page();
        current_world::FrameResult f = current_world::render(n, *d.mapper, d.surface, d.page, d.variant, nullptr, &watch);
        if (f.render.stats.interrupted) break;  // cut short by the next line: neither shown nor counted
        uint64_t t0 = timer::now();
        bool retrace = vga::flip(d.page);
        uint64_t flip_ticks = timer::since(t0);
        uint64_t ticks = frame_ticks(f);
        g_play_ticks[i] = clamp32(ticks);
        pixels += f.render.stats.pixels;
        tally.add(f.render.stats);
        total += ticks;
        lib::JsonLine(serial::sink())
            .str("event", "frame")
            .u32("n", uint32_t(i))
            .u32("frame", uint32_t(n))
            .u32("page", uint32_t(d.page))
            .u32("polygons", f.render.stats.polygons)
            .u32("pixels", f.render.stats.pixels)
            .u64("ticks", ticks)
            .u64("ticks_geometry", f.ticks_geometry)
            .u64("ticks_draw", f.render.ticks_draw)
            .u64("ticks_flip", flip_ticks)
            .boolean("retrace", retrace)
            .end();
    }
    uint64_t wall = timer::since(t_start);
    // `ticks` is the unclamped total; the summary's sum is of the clamped figures.
    lib::Summary s = lib::summarise_in_place(g_play_ticks, done);
    lib::JsonLine r = animation_reply("play", done, frames, d);
    r.u64("pixels", pixels).u64("ticks", total).u32("ticks_min", s.min).u32("ticks_median", s.median).u32("ticks_max", s.max);
    r.u64("ticks_wall", wall);
    tally.write(r);
    r.end();
}

void cmd_bench(Context&, const StrView* args, size_t nargs) {
    uint32_t frames;
    DrawArgs d;
    if (!parse_animation_args("bench", args, nargs, MAX_BENCH_FRAMES, " (spread evenly over the scene's animation)", &frames, &d)) return;
    const raster::Probe probe = current_world::bench_probe();
    current_world::start_bench_row();
    uint64_t polygons = 0, rejected = 0, spans = 0, pixels = 0;
    MapperTally tally;
    bool used_asm = false;
    uint32_t done = 0;
    Progress p{"bench", 0, 0};  // stops a long frame; the bench events are the progress
    const raster::Watch watch = p.watch();
    for (uint32_t i = 0; i < frames && !interrupted(i); ++i, ++done) {
        const current_world::BenchFrame b = current_world::bench_frame(i, frames, *d.mapper, d.surface, d.variant, probe, &watch);
        if (b.cut) break;  // cut short by the next line: no figure of it
        d.page = b.page;
        const raster::RenderStats& r = b.stats;
        lib::JsonLine e(serial::sink());
        e.str("event", "bench").u32("n", i).u32("frame", uint32_t(b.frame)).u32("page", uint32_t(b.page));
        e.u32("polygons", r.polygons).u32("rejected", r.rejected).u32("spans", r.spans).u32("pixels", r.pixels);
        for (uint32_t k = 0; k < B_FIELDS; ++k) {
            g_bench[k][i] = clamp32(b.figures[k]);
            e.u64(BENCH_FIELD_NAMES[k], b.figures[k]);
        }
        e.boolean("retrace", b.retrace).end();
        polygons += r.polygons, rejected += r.rejected, spans += r.spans, pixels += r.pixels;
        tally.add(r);
        used_asm = b.used_asm;
    }
    cycle_marks::mark(cycle_marks::RowEnd);
    lib::JsonLine r = animation_reply("bench", done, frames, d);
    r.str("loop", used_asm ? "asm" : "twin").u64("lap_cost", probe.lap_cost);
    r.u64("polygons", polygons).u64("rejected", rejected).u64("spans", spans).u64("pixels", pixels);
    for (uint32_t k = 0; k < B_FIELDS; ++k) {
        lib::Summary s = lib::summarise_in_place(g_bench[k], done);
        r.begin_object(BENCH_FIELD_NAMES[k]).u64("sum", s.sum).u32("min", s.min).u32("median", s.median).end_object();
    }
    tally.write(r);
    r.end();
}

void write_budget(lib::JsonLine& r, const char* key, const raster::Budget& b) {
    r.begin_object(key).boolean("given", b.given);
    if (b.max_error < 0) r.str("max_error", "any");
    else r.fixed("max_error", b.max_error, raster::MAX_DECIMALS);  // as given: every decimal the parser takes
    r.boolean("exact_coverage", b.exact_coverage).str("target", raster::cost_target_name(b.target)).end_object();
}

// budget: shows what auto draws the 3D scene to; `budget scene` goes back to the scene's own,
// `budget MAX-ERROR|any [exact|any [icount|486|pentium]]` sets one (coverage exact unless `any`,
// priced for icount unless a target is named) until then or the next load.
void cmd_budget(Context&, const StrView* args, size_t nargs) {
    if (nargs == 1 && args[0].equals("scene")) {
        current_world::set_budget(nullptr);
    } else if (nargs >= 1) {
        raster::Budget b;
        b.given = true;
        bool ok = args[0].equals("any") ? (b.max_error = raster::ANY_ERROR, true)
                                        : raster::scene_text::parse_decimal(args[0], &b.max_error) && b.max_error >= 0 && b.max_error <= 1e6;
        if (nargs >= 2) {
            ok = ok && (args[1].equals("exact") || args[1].equals("any"));
            b.exact_coverage = args[1].equals("exact");
        }
        if (nargs == 3) ok = ok && raster::cost_target_named(args[2].data, args[2].size, &b.target);
        if (!ok) {
            usage_error("budget");
            return;
        }
        current_world::set_budget(&b);
    }
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "budget").str("source", current_world::budget_overridden() ? "command" : current_world::loaded() ? "scene" : "default");
    write_budget(r, "budget", current_world::budget());
    r.end();
}

void cmd_mappers(Context&, const StrView*, size_t) {
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "mappers").begin_array("mappers");
    for (int i = 0; i < raster::MAPPER_COUNT; ++i) {
        const raster::Mapper& m = raster::MAPPERS[i];
        r.begin_item_object().str("name", m.name).str("family", m.family).str("origin", m.origin).str("promise", m.promise);
        r.boolean("exact_coverage", m.guarantee.exact_coverage)
            .i32("max_error", m.guarantee.max_error)
            .i32("max_error_flat", m.guarantee.max_error_flat);
        r.begin_array("needs");
        for (int k = 0; k < raster::NEED_NAME_COUNT; ++k)
            if (m.needs & raster::NEED_NAMES[k].need) r.item_str(raster::NEED_NAMES[k].name);
        r.end_array().begin_array("walkers");
        for (raster::Axis axis : WALKERS)
            if (raster::mapper_walks(m, axis)) r.item_str(walker_name(axis));
        r.end_array().begin_array("surfaces");
        for (int k = 0; k < raster::SURFACE_COUNT; ++k)
            if (raster::draws_through(m, raster::Surface(k))) r.item_str(raster::surface_name(raster::Surface(k)));
        r.end_array().boolean("asm", m.asm_loop != nullptr);
        // whose NASM loop it runs: the first row with it (selftest checks each loop under that name)
        for (int k = 0; m.asm_loop && k <= i; ++k)
            if (raster::MAPPERS[k].asm_loop == m.asm_loop) {
                r.str("asm_loop", raster::MAPPERS[k].name);
                break;
            }
        r.end_object();
    }
    r.end_array().end();
}

}  // namespace server
