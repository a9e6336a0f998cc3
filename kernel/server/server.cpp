// Command server: line reader, dispatch table, one handler per command.
#include "kernel/server/server.h"

#include "drivers/debug_exit.h"
#include "drivers/serial.h"
#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/draw.h"
#include "kernel/idt.h"
#include "kernel/lib/encode.h"
#include "kernel/lib/fmt.h"
#include "kernel/lib/words.h"
#include "kernel/scene/pattern.h"
#include "kernel/core/mapper.h"
#include "kernel/core/selftest.h"
#include "kernel/server/reply.h"
#include "kernel/files.h"
#include "kernel/scenes.h"
#include "kernel/vga_selftest.h"
#include "kernel/worlds.h"
#include "kernel/version.h"

namespace server {

namespace {

using lib::StrView;

constexpr size_t MAX_LINE = 255;  // characters, without the newline
constexpr size_t MAX_WORDS = 8;

struct Command {
    const char* name;
    const char* usage;
    size_t min_args, max_args;
    void (*handler)(Context& ctx, const StrView* args, size_t nargs);
};

uint8_t g_readback[vga::MAX_PIXELS];

void usage_error(const Command& c) {
    lib::Fmt m;
    m.s("usage: ").s(c.usage);
    reply::error(c.name, m.c_str());
}

// Checks that a graphics mode is on and `word` names one of its pages.
bool parse_page(const char* cmd, StrView word, int* page) {
    if (vga::page_count() == 0) {
        reply::error(cmd, "no graphics mode: send 'mode modex' or 'mode 13h' first");
        return false;
    }
    uint32_t p;
    if (!lib::parse_u32(word, &p) || p >= uint32_t(vga::page_count())) {
        lib::Fmt m;
        m.s("bad page '").s(word).s("': mode ").s(vga::mode_name(vga::mode())).s(" has pages 0..").u(uint32_t(vga::page_count() - 1));
        reply::error(cmd, m.c_str());
        return false;
    }
    *page = int(p);
    return true;
}

void cmd_hello(Context& ctx, const StrView*, size_t) {
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "hello").str("version", MODEXLAB_VERSION);
    r.begin_object("cpu");
    r.str("vendor", ctx.cpu.has_cpuid ? ctx.cpu.vendor : "unknown (no CPUID)");
    r.u32("family", ctx.cpu.family).u32("model", ctx.cpu.model).u32("stepping", ctx.cpu.stepping);
    r.begin_array("features");
    for (int i = 0; i < cpu::FEATURE_COUNT; ++i)
        if (cpu::has(ctx.cpu, cpu::FEATURES[i])) r.item_str(cpu::FEATURES[i].name);
    r.end_array().end_object();
    r.u64("tsc_hz", ctx.tsc_hz);
    r.str("mode", vga::mode_name(vga::mode())).i32("page", vga::page_count() ? vga::shown_page() : -1);
    r.str("palette", raster::palette_name(ctx.palette)).str("cmdline", ctx.cmdline);
    r.end();
}

void cmd_help(Context&, const StrView*, size_t);

void cmd_mode(Context& ctx, const StrView* args, size_t) {
    uint64_t t0 = timer::rdtsc();
    if (args[0].equals("13h")) vga::set_mode_13h();
    else if (args[0].equals("modex")) vga::set_mode_x();
    else {
        lib::Fmt m;
        m.s("unknown mode '").s(args[0]).s("' (modes: 13h, modex)");
        reply::error("mode", m.c_str());
        return;
    }
    vga::load_palette(raster::palette(ctx.palette));
    uint64_t ticks = timer::rdtsc() - t0;
    reply::begin(true)
        .str("cmd", "mode")
        .str("mode", vga::mode_name(vga::mode()))
        .u32("width", vga::WIDTH)
        .u32("height", uint32_t(vga::height()))
        .u32("pages", uint32_t(vga::page_count()))
        .u64("ticks", ticks)
        .end();
}

void cmd_pattern(Context&, const StrView* args, size_t) {
    raster::Pattern p;
    if (!raster::pattern_from_name(args[0], &p)) {
        lib::Fmt m;
        m.s("unknown pattern '").s(args[0]).s("' (patterns: ramp, planes, grid, border)");
        reply::error("pattern", m.c_str());
        return;
    }
    int page;
    if (!parse_page("pattern", args[1], &page)) return;
    uint64_t t0 = timer::rdtsc();
    draw::pattern(p, page);
    uint64_t ticks = timer::rdtsc() - t0;
    reply::begin(true).str("cmd", "pattern").str("pattern", raster::pattern_name(p)).u32("page", uint32_t(page)).u64("ticks", ticks).end();
}

void cmd_clear(Context&, const StrView* args, size_t nargs) {
    int page;
    if (!parse_page("clear", args[0], &page)) return;
    uint32_t colour = 0;
    if (nargs > 1 && (!lib::parse_u32(args[1], &colour) || colour > 255)) {
        reply::error("clear", "bad colour: a palette index 0..255");
        return;
    }
    vga::clear_page(page, uint8_t(colour));
    reply::begin(true).str("cmd", "clear").u32("page", uint32_t(page)).u32("colour", colour).end();
}

void cmd_palette(Context& ctx, const StrView* args, size_t) {
    raster::PaletteId id;
    if (!raster::palette_from_name(args[0], &id)) {
        lib::Fmt m;
        m.s("unknown palette '").s(args[0]).s("' (palettes: default, gray)");
        reply::error("palette", m.c_str());
        return;
    }
    ctx.palette = id;
    vga::load_palette(raster::palette(id));
    reply::begin(true).str("cmd", "palette").str("palette", raster::palette_name(id)).end();
}

void cmd_flip(Context&, const StrView* args, size_t) {
    int page;
    if (!parse_page("flip", args[0], &page)) return;
    bool retrace = vga::flip(page);
    reply::begin(true).str("cmd", "flip").u32("page", uint32_t(page)).boolean("retrace", retrace).end();
}

void put_base64(void* encoder, uint8_t byte) { static_cast<lib::Base64Encoder*>(encoder)->put(byte); }

void cmd_readback(Context&, const StrView* args, size_t) {
    int page;
    if (!parse_page("readback", args[0], &page)) return;
    const uint32_t pixels = uint32_t(vga::WIDTH * vga::height());
    vga::read_page(page, g_readback);
    uint32_t crc = lib::crc32(0, g_readback, pixels);
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "readback").u32("page", uint32_t(page)).u32("width", vga::WIDTH).u32("height", uint32_t(vga::height()));
    r.str("encoding", "packbits+base64").hex32("crc32", crc);
    r.begin_raw_string("data");
    lib::Base64Encoder b64(r.raw_sink());
    size_t packed = lib::packbits_encode(g_readback, pixels, put_base64, &b64);
    b64.finish();
    r.end_raw_string();
    r.u32("packed_bytes", uint32_t(packed)).end();
}

void cmd_fault(Context&, const StrView* args, size_t nargs) {
    // The CPU exception's report is this command's reply (kernel/idt.cpp); triple and hang test
    // that the harness catches the failures a kernel cannot report.
    if (nargs == 0 || args[0].equals("ud")) fault_ud2();
    else if (args[0].equals("de")) fault_divide();
    else if (args[0].equals("gp")) fault_gp();
    else if (args[0].equals("triple")) fault_triple();  // no reply: QEMU ends with status 0
    else if (args[0].equals("hang")) fault_hang();      // no reply ever
    lib::Fmt m;
    m.s("unknown fault '").s(args[0]).s("' (faults: ud, de, gp, triple, hang)");
    reply::error("fault", m.c_str());
}

void cmd_exit(Context&, const StrView* args, size_t) {
    uint32_t code;
    if (!lib::parse_u32(args[0], &code) || code > debug_exit::MAX_USER_CODE) {
        reply::error("exit", "bad code: 0..63 (QEMU then exits with status 2*CODE+1)");
        return;
    }
    reply::begin(true).str("cmd", "exit").u32("code", code).end();
    serial::flush();
    debug_exit::exit(code);
    // No isa-debug-exit device (a real PC): stop here.
    vga::text_write("modexlab: exit; halted\n");
    for (;;) asm volatile("cli; hlt");
}

void cmd_vbe(Context&, const StrView* args, size_t) {
    if (!args[0].equals("on")) {
        reply::error("vbe", "usage: vbe on");
        return;
    }
    if (!vga::enable_bochs_vbe_640x480()) {
        reply::error("vbe", "no Bochs VBE adapter (ports 0x1CE/0x1CF)");
        return;
    }
    reply::begin(true).str("cmd", "vbe").str("mode", vga::mode_name(vga::mode())).u32("width", 640).u32("height", 480).u32("bpp", 8).end();
}

// --- scenes and files -----------------------------------------------------------------------

void reply_parse_error(const char* cmd, const char* file, const raster::ParseError& e) {
    lib::Fmt m;
    if (file) m.s(file).s(": ");
    if (e.line) m.s("line ").u(uint32_t(e.line)).s(": ");
    m.s(e.message);
    lib::JsonLine r = reply::begin(false);
    r.str("cmd", cmd).str("error", m.c_str()).u32("line", uint32_t(e.line));
    if (file) r.str("file", file);
    r.end();
}

// The reply fields describing a loaded screen-space scene or 3D scene.
void describe_screen_scene(lib::JsonLine& r) {
    const raster::Scene& sc = scenes::scene();
    r.u32("version", 1)
        .u32("polygons", uint32_t(sc.polygon_count))
        .u32("vertices", uint32_t(sc.vertex_count))
        .str("texture", raster::texture_kind_name(sc.texture_kind))
        .u32("texture_width", uint32_t(sc.texture_width))
        .u32("texture_height", uint32_t(sc.texture_height))
        .str("wrap", raster::wrap_name(sc.wrap));
}

void describe_world(lib::JsonLine& r) {
    const raster::World& w = worlds::world();
    r.u32("version", 2)
        .u32("textures", uint32_t(w.texture_count))
        .u32("meshes", uint32_t(w.mesh_count))
        .u32("objects", uint32_t(w.object_count))
        .u32("faces", uint32_t(w.face_count))
        .u32("positions", uint32_t(w.position_count))
        .u32("frames", uint32_t(w.frames))
        .str("palette", w.palette_texture >= 0 ? w.textures[w.palette_texture].name : "default");
    r.begin_object("budget").boolean("given", w.budget.given).i32("max_error", w.budget.max_error).boolean("exact_coverage", w.budget.exact_coverage).end_object();
}

// Loads a scene file of either version as the current scene of its kind.
void load_and_reply(const char* cmd, const files::File& f) {
    raster::ParseError e;
    const char* text = reinterpret_cast<const char*>(f.data);
    int version = raster::scene_version(text, f.size, &e);
    bool ok = version == 1 ? scenes::load(text, f.size, &e) : version == 2 ? worlds::load(f.name, f.data, f.size, &e) : false;
    if (!ok) {
        reply_parse_error(cmd, f.name, e);
        return;
    }
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", cmd).str("name", f.name).str("origin", files::origin_name(f.origin)).u32("bytes", uint32_t(f.size));
    if (version == 1) describe_screen_scene(r);
    else describe_world(r);
    r.end();
}

bool parse_upload(const char* cmd, StrView bytes, StrView crc, uint32_t* length, uint32_t* crc32) {
    if (!lib::parse_u32(bytes, length) || *length == 0 || *length > files::MAX_UPLOAD || !lib::parse_u32(crc, crc32)) {
        lib::Fmt m;
        m.s("bad length or checksum: BYTES 1..").u(uint32_t(files::MAX_UPLOAD)).s(", CRC32 decimal or 0x hex");
        reply::error(cmd, m.c_str());
        return false;
    }
    return true;
}

constexpr const char* UPLOADED_SCENE = "upload.scene";

void cmd_scene(Context&, const StrView* args, size_t) {
    uint32_t length, crc;
    if (!parse_upload("scene", args[0], args[1], &length, &crc)) return;
    lib::Fmt error;
    if (!files::upload(StrView{UPLOADED_SCENE, lib::c_length(UPLOADED_SCENE)}, length, crc, &error)) {
        reply::begin(false).str("cmd", "scene").str("error", error.c_str()).u32("line", 0).end();
        return;
    }
    load_and_reply("scene", *files::find(StrView{UPLOADED_SCENE, lib::c_length(UPLOADED_SCENE)}));
}

void cmd_file(Context&, const StrView* args, size_t) {
    uint32_t length, crc;
    if (!parse_upload("file", args[1], args[2], &length, &crc)) return;
    if (args[0].size == 0 || args[0].size >= size_t(raster::MAX_FILE_NAME)) {
        reply::error("file", "bad name: 1 to 63 characters");
        return;
    }
    lib::Fmt error;
    if (!files::upload(args[0], length, crc, &error)) {
        reply::error("file", error.c_str());
        return;
    }
    const files::File* f = files::find(args[0]);
    reply::begin(true).str("cmd", "file").str("name", f->name).u32("bytes", uint32_t(f->size)).u64("upload_space_used", files::upload_space_used()).end();
}

void cmd_files(Context&, const StrView*, size_t) {
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "files").begin_array("files");
    for (int i = 0; i < files::count(); ++i) {
        const files::File& f = files::at(i);
        r.begin_item_object().str("name", f.name).str("origin", files::origin_name(f.origin)).u32("bytes", uint32_t(f.size)).end_object();
    }
    r.end_array().u64("upload_space_used", files::upload_space_used()).u64("upload_space", files::UPLOAD_SPACE).end();
}

void cmd_load(Context&, const StrView* args, size_t) {
    const files::File* f = files::find(args[0]);
    if (!f) {
        lib::Fmt m;
        m.s("no file '").s(args[0]).s("' (see 'files')");
        reply::error("load", m.c_str());
        return;
    }
    load_and_reply("load", *f);
}

// --- drawing -------------------------------------------------------------------------------

// MAPPER PAGE [SURFACE [asm|twin]] (PAGE absent for play): what every drawing command takes.
struct DrawArgs {
    const raster::Mapper* mapper = nullptr;
    int page = 0;
    raster::Surface surface = raster::Surface::Linear;
    raster::Variant variant = raster::Variant::Asm;
    raster::Axis axis = raster::Axis::Rows;
};

bool parse_draw_args(const char* cmd, const StrView* args, size_t nargs, bool with_page, DrawArgs* d) {
    d->mapper = raster::find_mapper(args[0]);
    if (!d->mapper) {
        lib::Fmt m;
        m.s("unknown mapper '").s(args[0]).s("' (mappers:");
        for (int i = 0; i < raster::MAPPER_COUNT; ++i) m.s(" ").s(raster::MAPPERS[i].name);
        m.s(")");
        reply::error(cmd, m.c_str());
        return false;
    }
    if (vga::mode() != vga::Mode::ModeX) {
        lib::Fmt m;
        m.s(cmd).s(" draws into Mode X pages: send 'mode modex' first");
        reply::error(cmd, m.c_str());
        return false;
    }
    size_t next = 1;
    if (with_page && !parse_page(cmd, args[next++], &d->page)) return false;
    if (nargs > next && !raster::surface_from_name(args[next], &d->surface)) {
        reply::error(cmd, "unknown surface (linear: rows in RAM then blit; planar: columns in RAM then blit; vga: columns into the page)");
        return false;
    }
    ++next;
    if (nargs > next) {
        if (args[next].equals("twin")) d->variant = raster::Variant::Twin;
        else if (!args[next].equals("asm")) {
            reply::error(cmd, "unknown variant (asm: the NASM loop where there is one; twin: the C++ twin)");
            return false;
        }
    }
    const raster::Mapper& mp = *d->mapper;
    d->axis = raster::surface_axis(mp, d->surface);
    if (!raster::draws_through(mp, d->surface)) {
        lib::Fmt m;
        m.s("mapper ").s(mp.name).s(" cannot draw through surface ").s(raster::surface_name(d->surface)).s(" (it walks");
        if (mp.axes & raster::AXIS_ROWS) m.s(" rows");
        if (mp.axes & raster::AXIS_COLUMNS) m.s(" columns");
        if (mp.needs & raster::NEED_PLANAR_TARGET) m.s(" into Mode X planes: surface planar or vga");
        m.s(")");
        reply::error(cmd, m.c_str());
        return false;
    }
    return true;
}

void render_fields(lib::JsonLine& r, const DrawArgs& d, const scenes::RenderResult& res) {
    r.str("mapper", d.mapper->name)
        .u32("page", uint32_t(d.page))
        .str("surface", raster::surface_name(d.surface))
        .str("walker", d.axis == raster::Axis::Rows ? "rows" : "columns")
        .str("loop", res.used_asm ? "asm" : "twin")
        .u32("polygons", res.stats.polygons)
        .u32("skipped", res.stats.skipped)
        .u32("rejected", res.stats.rejected)
        .u32("spans", res.stats.spans)
        .u32("pixels", res.stats.pixels);
}

void cmd_render(Context&, const StrView* args, size_t nargs) {
    DrawArgs d;
    if (!parse_draw_args("render", args, nargs, true, &d)) return;
    if (!scenes::loaded()) {
        reply::error("render", "no screen-space scene: upload one with 'scene BYTES CRC32' or 'load NAME' first");
        return;
    }
    const raster::Texture& tex = scenes::texture();
    if (!raster::mapper_accepts(*d.mapper, tex)) {
        lib::Fmt m;
        m.s("mapper ").s(d.mapper->name).s(" cannot take this scene's ").u(uint32_t(tex.width)).s("x").u(uint32_t(tex.height)).s(" texture (needs");
        const char* sep = " ";
        for (int i = 0; i < raster::NEED_NAME_COUNT; ++i)
            if (d.mapper->needs & raster::NEED_NAMES[i].need) m.s(sep).s(raster::NEED_NAMES[i].words), sep = ", ";
        m.s(")");
        reply::error("render", m.c_str());
        return;
    }
    scenes::RenderResult res = scenes::render(*d.mapper, d.surface, d.page, d.variant);
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "render");
    render_fields(r, d, res);
    r.u64("ticks", res.ticks_clear + res.ticks_draw + res.ticks_blit)
        .u64("ticks_clear", res.ticks_clear)
        .u64("ticks_draw", res.ticks_draw)
        .u64("ticks_blit", res.ticks_blit)
        .end();
}

bool need_world(const char* cmd) {
    if (worlds::loaded()) return true;
    reply::error(cmd, "no 3D scene: 'load NAME' one (see 'files') or upload one with 'scene BYTES CRC32'");
    return false;
}

void frame_fields(lib::JsonLine& r, const worlds::FrameResult& f) {
    r.u32("faces", f.frame.faces)
        .u32("culled", f.frame.culled)
        .u32("outside", f.frame.outside)
        .u32("clipped", f.frame.clipped)
        .u32("overflow", f.frame.overflow)
        .u64("ticks", f.ticks_geometry + f.render.ticks_clear + f.render.ticks_draw + f.render.ticks_blit)
        .u64("ticks_geometry", f.ticks_geometry)
        .u64("ticks_clear", f.render.ticks_clear)
        .u64("ticks_draw", f.render.ticks_draw)
        .u64("ticks_blit", f.render.ticks_blit);
}

void cmd_frame(Context&, const StrView* args, size_t nargs) {
    uint32_t n;
    if (!lib::parse_u32(args[0], &n) || n >= uint32_t(raster::MAX_FRAMES)) {
        reply::error("frame", "bad frame number: 0..1048575 (frame n shows time n/30 s)");
        return;
    }
    DrawArgs d;
    if (!parse_draw_args("frame", args + 1, nargs - 1, true, &d) || !need_world("frame")) return;
    worlds::FrameResult f = worlds::render(int32_t(n), *d.mapper, d.surface, d.page, d.variant);
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "frame").str("scene", worlds::name()).u32("frame", n);
    render_fields(r, d, f.render);
    frame_fields(r, f);
    r.end();
}

constexpr uint32_t MAX_PLAY_FRAMES = 100000;
uint32_t g_play_ticks[MAX_PLAY_FRAMES];

uint32_t clamp32(uint64_t v) { return v > 0xFFFFFFFFu ? 0xFFFFFFFFu : uint32_t(v); }

// Puts the median of v[0..n) at v[n / 2] (the upper one of an even count) and returns it: a
// partial selection sort over the first half, no room needed. The order of v changes.
uint32_t median_in_place(uint32_t* v, uint32_t n) {
    for (uint32_t i = 0; i <= n / 2; ++i) {
        uint32_t m = i;
        for (uint32_t k = i + 1; k < n; ++k)
            if (v[k] < v[m]) m = k;
        uint32_t t = v[i];
        v[i] = v[m], v[m] = t;
    }
    return v[n / 2];
}

// The arguments of play and bench: FRAMES (1..most) MAPPER [surface] [variant], and a 3D scene.
bool parse_animation_args(const char* cmd, const StrView* args, size_t nargs, uint32_t most, const char* bad_count,
                          uint32_t* frames, DrawArgs* d) {
    if (!lib::parse_u32(args[0], frames) || *frames == 0 || *frames > most) {
        reply::error(cmd, bad_count);
        return false;
    }
    return parse_draw_args(cmd, args + 1, nargs - 1, false, d) && need_world(cmd);
}

void cmd_play(Context&, const StrView* args, size_t nargs) {
    uint32_t frames;
    DrawArgs d;
    if (!parse_animation_args("play", args, nargs, MAX_PLAY_FRAMES, "bad frame count: 1..100000", &frames, &d)) return;
    uint64_t pixels = 0, total = 0, t_start = timer::rdtsc();
    for (uint32_t i = 0; i < frames; ++i) {
        int32_t n = int32_t(i % uint32_t(worlds::world().frames));
        d.page = vga::shown_page() == 0 ? 1 : 0;  // draw into the hidden page, then show it
        worlds::FrameResult f = worlds::render(n, *d.mapper, d.surface, d.page, d.variant);
        uint64_t t0 = timer::rdtsc();
        bool retrace = vga::flip(d.page);
        uint64_t flip_ticks = timer::rdtsc() - t0;
        uint64_t ticks = f.ticks_geometry + f.render.ticks_clear + f.render.ticks_draw + f.render.ticks_blit;
        g_play_ticks[i] = clamp32(ticks);
        pixels += f.render.stats.pixels;
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
    uint64_t wall = timer::rdtsc() - t_start;
    uint32_t lo = 0xFFFFFFFFu, hi = 0;
    for (uint32_t i = 0; i < frames; ++i) {
        if (g_play_ticks[i] < lo) lo = g_play_ticks[i];
        if (g_play_ticks[i] > hi) hi = g_play_ticks[i];
    }
    uint32_t median = median_in_place(g_play_ticks, frames);
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "play").str("scene", worlds::name()).u32("frames", frames).str("mapper", d.mapper->name);
    r.str("surface", raster::surface_name(d.surface)).str("walker", d.axis == raster::Axis::Rows ? "rows" : "columns");
    r.u64("pixels", pixels).u64("ticks", total).u32("ticks_min", lo).u32("ticks_median", median).u32("ticks_max", hi);
    r.u64("ticks_wall", wall).end();
}

// bench: each frame drawn twice, once plainly (the totals) and once with the probe (setup and
// inner loops; walking is the rest of the plain drawing time), then flipped.
constexpr uint32_t MAX_BENCH_FRAMES = 1000;
enum BenchField : uint32_t {
    B_TICKS, B_GEOMETRY, B_CLEAR, B_DRAW, B_SETUP, B_WALK, B_INNER, B_BLIT, B_FLIP, B_FIELDS
};
const char* const BENCH_FIELD_NAMES[B_FIELDS] = {"ticks",      "ticks_geometry", "ticks_clear", "ticks_draw", "ticks_setup",
                                                 "ticks_walk", "ticks_inner",    "ticks_blit",  "ticks_flip"};
uint32_t g_bench[B_FIELDS][MAX_BENCH_FRAMES];

uint64_t bench_clock() { return timer::rdtsc(); }

void cmd_bench(Context&, const StrView* args, size_t nargs) {
    uint32_t frames;
    DrawArgs d;
    if (!parse_animation_args("bench", args, nargs, MAX_BENCH_FRAMES, "bad frame count: 1..1000 (spread evenly over the scene's animation)",
                              &frames, &d))
        return;
    raster::Probe probe;
    probe.clock = bench_clock;
    probe.calibrate();
    const uint32_t length = uint32_t(worlds::world().frames);
    uint64_t polygons = 0, rejected = 0, spans = 0, pixels = 0;
    bool used_asm = false;
    for (uint32_t i = 0; i < frames; ++i) {
        int32_t n = int32_t(uint64_t(i) * length / frames);
        d.page = vga::shown_page() == 0 ? 1 : 0;
        worlds::FrameResult f = worlds::render(n, *d.mapper, d.surface, d.page, d.variant);
        raster::Probe timed = probe;
        worlds::render(n, *d.mapper, d.surface, d.page, d.variant, &timed);
        uint64_t t0 = timer::rdtsc();
        bool retrace = vga::flip(d.page);
        uint64_t flip = timer::rdtsc() - t0;
        const scenes::RenderResult& r = f.render;
        uint64_t setup = timed.net(raster::Phase::Setup), inner = timed.net(raster::Phase::Inner);
        uint64_t walk = r.ticks_draw > setup + inner ? r.ticks_draw - setup - inner : 0;
        uint64_t figures[B_FIELDS] = {f.ticks_geometry + r.ticks_clear + r.ticks_draw + r.ticks_blit,
                                      f.ticks_geometry, r.ticks_clear, r.ticks_draw, setup, walk, inner, r.ticks_blit, flip};
        lib::JsonLine e(serial::sink());
        e.str("event", "bench").u32("n", i).u32("frame", uint32_t(n)).u32("page", uint32_t(d.page));
        e.u32("polygons", r.stats.polygons).u32("rejected", r.stats.rejected).u32("spans", r.stats.spans).u32("pixels", r.stats.pixels);
        for (uint32_t k = 0; k < B_FIELDS; ++k) {
            g_bench[k][i] = clamp32(figures[k]);
            e.u64(BENCH_FIELD_NAMES[k], figures[k]);
        }
        e.boolean("retrace", retrace).end();
        polygons += r.stats.polygons, rejected += r.stats.rejected, spans += r.stats.spans, pixels += r.stats.pixels;
        used_asm = r.used_asm;
    }
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "bench").str("scene", worlds::name()).u32("frames", frames).str("mapper", d.mapper->name);
    r.str("surface", raster::surface_name(d.surface)).str("walker", d.axis == raster::Axis::Rows ? "rows" : "columns");
    r.str("loop", used_asm ? "asm" : "twin").u64("lap_cost", probe.lap_cost);
    r.u64("polygons", polygons).u64("rejected", rejected).u64("spans", spans).u64("pixels", pixels);
    for (uint32_t k = 0; k < B_FIELDS; ++k) {
        uint64_t sum = 0;
        uint32_t lo = 0xFFFFFFFFu;
        for (uint32_t i = 0; i < frames; ++i) {
            sum += g_bench[k][i];
            if (g_bench[k][i] < lo) lo = g_bench[k][i];
        }
        r.begin_object(BENCH_FIELD_NAMES[k]).u64("sum", sum).u32("min", lo).u32("median", median_in_place(g_bench[k], frames)).end_object();
    }
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
        if (m.axes & raster::AXIS_ROWS) r.item_str("rows");
        if (m.axes & raster::AXIS_COLUMNS) r.item_str("columns");
        r.end_array().begin_array("surfaces");
        for (int k = 0; k < raster::SURFACE_COUNT; ++k)
            if (raster::draws_through(m, raster::Surface(k))) r.item_str(raster::surface_name(raster::Surface(k)));
        r.end_array().boolean("asm", m.asm_loop != nullptr).end_object();
    }
    r.end_array().end();
}

alignas(4) uint8_t g_check_a[raster::CHECK_DST_BYTES];
alignas(4) uint8_t g_check_b[raster::CHECK_DST_BYTES];
uint8_t g_check_texels[raster::CHECK_TEXEL_BYTES];

void cmd_selftest(Context&, const StrView* args, size_t nargs) {
    uint32_t cases = 2000;
    if (nargs > 0 && (!lib::parse_u32(args[0], &cases) || cases == 0 || cases > 1000000)) {
        reply::error("selftest", "usage: selftest [CASES] (1..1000000, default 2000)");
        return;
    }
    raster::CheckBuffers buffers{g_check_a, g_check_b, raster::CHECK_DST_BYTES, g_check_texels};
    raster::LoopCheck results[16];
    int n = 0;
    bool all_equal = true;
    uint64_t t0 = timer::rdtsc();
    bool vga_checked = vga::mode() == vga::Mode::ModeX;
    const raster::Mapper* loops[16];
    int count = raster::checked_loops(loops, 16);
    for (int i = 0; i < count; ++i) {
        const raster::Mapper& loop = *loops[i];
        bool vga = loop.needs & raster::NEED_VGA_FOR_ASM;
        if (!loop.asm_loop || (vga && !vga_checked)) continue;
        results[n] = vga ? vga_selftest::check(loop, 20261121, cases, g_check_texels)
                         : loop.check(loop, loop.asm_loop, 20261121, cases, buffers);
        all_equal = all_equal && results[n].mismatches == 0;
        ++n;
    }
    lib::JsonLine r = reply::begin(all_equal);
    r.str("cmd", "selftest");
    if (!all_equal) r.str("error", "a NASM loop differs from its C++ twin");
    r.u32("cases", cases).u64("ticks", timer::rdtsc() - t0);
    r.boolean("vga_loops_checked", vga_checked);  // those draw into page 2 of Mode X: 'mode modex' first
    r.begin_array("loops");
    for (int i = 0; i < n; ++i)
        r.begin_item_object()
            .str("loop", results[i].loop)
            .u32("cases", results[i].cases)
            .u32("pixels", results[i].pixels)
            .u32("mismatches", results[i].mismatches)
            .u32("first_mismatch", results[i].first_mismatch)
            .end_object();
    r.end_array().end();
}

constexpr Command COMMANDS[] = {
    {"hello", "hello", 0, 0, cmd_hello},
    {"help", "help", 0, 0, cmd_help},
    {"mode", "mode 13h|modex", 1, 1, cmd_mode},
    {"pattern", "pattern ramp|planes|grid|border PAGE", 2, 2, cmd_pattern},
    {"clear", "clear PAGE [COLOUR]", 1, 2, cmd_clear},
    {"palette", "palette default|gray", 1, 1, cmd_palette},
    {"flip", "flip PAGE", 1, 1, cmd_flip},
    {"readback", "readback PAGE", 1, 1, cmd_readback},
    {"fault", "fault [ud|de|gp|triple|hang]", 0, 1, cmd_fault},
    {"scene", "scene BYTES CRC32 (then BYTES bytes of scene text, either version)", 2, 2, cmd_scene},
    {"file", "file NAME BYTES CRC32 (then BYTES bytes: a texture or scene file)", 3, 3, cmd_file},
    {"files", "files", 0, 0, cmd_files},
    {"load", "load NAME (a scene file: built in, a module or uploaded)", 1, 1, cmd_load},
    {"render", "render MAPPER PAGE [linear|planar|vga] [asm|twin] (the screen-space scene)", 2, 4, cmd_render},
    {"frame", "frame N MAPPER PAGE [linear|planar|vga] [asm|twin] (frame N of the 3D scene)", 3, 5, cmd_frame},
    {"play", "play FRAMES MAPPER [linear|planar|vga] [asm|twin] (the 3D scene, page-flipped)", 2, 4, cmd_play},
    {"bench", "bench FRAMES MAPPER [linear|planar|vga] [asm|twin] (the 3D scene: timings per frame)", 2, 4, cmd_bench},
    {"mappers", "mappers", 0, 0, cmd_mappers},
    {"selftest", "selftest [CASES]", 0, 1, cmd_selftest},
    {"vbe", "vbe on", 1, 1, cmd_vbe},
    {"exit", "exit CODE", 1, 1, cmd_exit},
};

void cmd_help(Context&, const StrView*, size_t) {
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "help").begin_array("commands");
    for (const Command& c : COMMANDS) r.item_str(c.usage);
    r.end_array().end();
}

void dispatch(Context& ctx, const char* line) {
    StrView words[MAX_WORDS];
    size_t n = lib::split_words(line, words, MAX_WORDS);
    if (n == 0) return;  // blank line: nothing to answer
    for (const Command& c : COMMANDS) {
        if (!words[0].equals(c.name)) continue;
        size_t nargs = n - 1;
        if (nargs < c.min_args || nargs > c.max_args) usage_error(c);
        else c.handler(ctx, words + 1, nargs);
        return;
    }
    lib::Fmt m;
    m.s("unknown command '").s(words[0]).s("' (try 'help')");
    reply::error("?", m.c_str());
}

}  // namespace

void run(Context& ctx) {
    char line[MAX_LINE + 1];
    size_t len = 0;
    bool too_long = false;
    for (;;) {
        char c = char(serial::read_byte());
        if (c == '\r') continue;
        if (c == '\n') {
            line[len] = 0;
            if (too_long) reply::error("?", "line too long (at most 255 characters)");
            else dispatch(ctx, line);
            len = 0;
            too_long = false;
        } else if (c == '\b' || c == 0x7F) {  // a person at a terminal
            if (len) --len;
        } else if (len < MAX_LINE) {
            line[len++] = c;
        } else {
            too_long = true;
        }
    }
}

}  // namespace server
