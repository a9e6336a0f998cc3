// Command server: line reader, dispatch table, one handler per command.
#include "kernel/server.h"

#include "drivers/debug_exit.h"
#include "drivers/serial.h"
#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/draw.h"
#include "kernel/idt.h"
#include "kernel/lib/encode.h"
#include "kernel/lib/fmt.h"
#include "kernel/lib/words.h"
#include "kernel/raster/pattern.h"
#include "kernel/raster/mappers.h"
#include "kernel/raster/selftest.h"
#include "kernel/reply.h"
#include "kernel/scenes.h"
#include "kernel/vga_selftest.h"
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

void cmd_scene(Context&, const StrView* args, size_t) {
    uint32_t length, crc;
    if (!lib::parse_u32(args[0], &length) || length == 0 || length > raster::MAX_SCENE_BYTES || !lib::parse_u32(args[1], &crc)) {
        reply::error("scene", "usage: scene BYTES CRC32, then exactly BYTES bytes of scene text (1..1048576 bytes)");
        return;
    }
    raster::ParseError e;
    if (!scenes::upload(length, crc, &e)) {
        lib::Fmt m;
        if (e.line) m.s("line ").u(uint32_t(e.line)).s(": ");
        m.s(e.message);
        reply::begin(false).str("cmd", "scene").str("error", m.c_str()).u32("line", uint32_t(e.line)).end();
        return;
    }
    const raster::Scene& sc = scenes::scene();
    reply::begin(true)
        .str("cmd", "scene")
        .u32("bytes", length)
        .u32("polygons", uint32_t(sc.polygon_count))
        .u32("vertices", uint32_t(sc.vertex_count))
        .str("texture", raster::texture_kind_name(sc.texture_kind))
        .u32("texture_width", uint32_t(sc.texture_width))
        .u32("texture_height", uint32_t(sc.texture_height))
        .str("wrap", raster::wrap_name(sc.wrap))
        .end();
}

void cmd_render(Context&, const StrView* args, size_t nargs) {
    const raster::Mapper* mapper = raster::find_mapper(args[0]);
    if (!mapper) {
        lib::Fmt m;
        m.s("unknown mapper '").s(args[0]).s("' (mappers:");
        for (int i = 0; i < raster::MAPPER_COUNT; ++i) m.s(" ").s(raster::MAPPERS[i].name);
        m.s(")");
        reply::error("render", m.c_str());
        return;
    }
    if (vga::mode() != vga::Mode::ModeX) {
        reply::error("render", "render draws into Mode X pages: send 'mode modex' first");
        return;
    }
    int page;
    if (!parse_page("render", args[1], &page)) return;
    scenes::Surface surface = scenes::Surface::Linear;
    if (nargs > 2 && !scenes::surface_from_name(args[2], &surface)) {
        reply::error("render", "unknown surface (linear: rows in RAM then blit; planar: columns in RAM then blit; vga: columns into the page)");
        return;
    }
    raster::Variant variant = raster::Variant::Asm;
    if (nargs > 3) {
        if (args[3].equals("twin")) variant = raster::Variant::Twin;
        else if (!args[3].equals("asm")) {
            reply::error("render", "unknown variant (asm: the NASM loop where there is one; twin: the C++ twin)");
            return;
        }
    }
    if (!scenes::loaded()) {
        reply::error("render", "no scene: upload one with 'scene BYTES CRC32' first");
        return;
    }
    const raster::Texture& tex = scenes::texture();
    if (!raster::mapper_accepts(*mapper, tex)) {
        lib::Fmt m;
        m.s("mapper ").s(mapper->name).s(" cannot take this scene's ").u(uint32_t(tex.width)).s("x").u(uint32_t(tex.height)).s(" texture (needs:");
        if (mapper->needs & raster::NEED_POW2) m.s(" power-of-two sizes");
        if (mapper->needs & raster::NEED_WIDTH_256) m.s(" width 256");
        if (mapper->needs & raster::NEED_ALIGNED256) m.s(" 256x256, repeating");
        m.s(")");
        reply::error("render", m.c_str());
        return;
    }
    raster::Axis axis = scenes::surface_axis(*mapper, surface);
    if (!raster::mapper_walks(*mapper, axis) || !raster::mapper_targets(*mapper, scenes::probe_target(surface), axis)) {
        lib::Fmt m;
        m.s("mapper ").s(mapper->name).s(" cannot draw through surface ").s(scenes::surface_name(surface)).s(" (it walks");
        if (mapper->axes & raster::AXIS_ROWS) m.s(" rows");
        if (mapper->axes & raster::AXIS_COLUMNS) m.s(" columns");
        if (mapper->needs & raster::NEED_PLANAR_TARGET) m.s(" into Mode X planes: surface planar or vga");
        m.s(")");
        reply::error("render", m.c_str());
        return;
    }
    scenes::RenderResult r = scenes::render(*mapper, surface, page, variant);
    reply::begin(true)
        .str("cmd", "render")
        .str("mapper", mapper->name)
        .u32("page", uint32_t(page))
        .str("surface", scenes::surface_name(surface))
        .str("walker", axis == raster::Axis::Rows ? "rows" : "columns")
        .str("loop", r.used_asm ? "asm" : "twin")
        .u32("polygons", r.stats.polygons)
        .u32("skipped", r.stats.skipped)
        .u32("rejected", r.stats.rejected)
        .u32("spans", r.stats.spans)
        .u32("pixels", r.stats.pixels)
        .u64("ticks", r.ticks_clear + r.ticks_draw + r.ticks_blit)
        .u64("ticks_clear", r.ticks_clear)
        .u64("ticks_draw", r.ticks_draw)
        .u64("ticks_blit", r.ticks_blit)
        .end();
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
        if (m.needs & raster::NEED_POW2) r.item_str("pow2");
        if (m.needs & raster::NEED_WIDTH_256) r.item_str("width256");
        if (m.needs & raster::NEED_ALIGNED256) r.item_str("256x256-repeat");
        if (m.needs & raster::NEED_INSIDE) r.item_str("inside-texture");
        r.end_array().begin_array("walkers");
        if (m.axes & raster::AXIS_ROWS) r.item_str("rows");
        if (m.axes & raster::AXIS_COLUMNS) r.item_str("columns");
        r.end_array().begin_array("surfaces");
        for (int k = 0; k < 3; ++k) {
            auto surface = scenes::Surface(k);
            raster::Axis axis = scenes::surface_axis(m, surface);
            if (raster::mapper_walks(m, axis) && raster::mapper_targets(m, scenes::probe_target(surface), axis))
                r.item_str(scenes::surface_name(surface));
        }
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
    for (int i = 0; i < raster::CHECKED_LOOP_COUNT && n < 16; ++i) {
        const raster::CheckedLoop& loop = raster::CHECKED_LOOPS[i];
        if (!loop.asm_loop || (loop.vga && !vga_checked)) continue;
        results[n] = loop.vga ? vga_selftest::check(loop, 20261121, cases, g_check_texels)
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
    {"scene", "scene BYTES CRC32 (then BYTES bytes of scene text)", 2, 2, cmd_scene},
    {"render", "render MAPPER PAGE [linear|planar|vga] [asm|twin]", 2, 4, cmd_render},
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
