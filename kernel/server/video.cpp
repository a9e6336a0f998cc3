// The video commands: hello (with the mode and page shown), mode, test patterns, clearing,
// palettes, flipping and reading back pages, and the Bochs VBE mode.
#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/platform/isa.h"
#include "kernel/present/patterns.h"
#include "kernel/lib/encode.h"
#include "kernel/scene/pattern.h"
#include "kernel/server/commands.h"
#include "kernel/server/reply.h"
#include "kernel/version.h"

namespace server {

namespace {

// The modes `mode` sets, by their vga::mode_name.
struct ModeSetter {
    vga::Mode mode;
    void (*set)();
};
constexpr ModeSetter MODE_SETTERS[] = {{vga::Mode::Mode13h, vga::set_mode_13h}, {vga::Mode::ModeX, vga::set_mode_x}};
constexpr int MODE_SETTER_COUNT = sizeof(MODE_SETTERS) / sizeof(MODE_SETTERS[0]);

// Static: a whole Mode X page (76,800 bytes) does not fit on the 64 KiB kernel stack.
uint8_t g_readback[vga::MAX_PIXELS];

void put_base64(void* encoder, uint8_t byte) { static_cast<lib::Base64Encoder*>(encoder)->put(byte); }

}  // namespace

void cmd_hello(Context& ctx, const StrView*, size_t) {
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "hello").str("version", MODEXLAB_VERSION);
    r.begin_object("cpu");
    r.str("vendor", ctx.cpu.has_cpuid ? ctx.cpu.vendor : "unknown (no CPUID)");
    r.u32("family", ctx.cpu.family).u32("model", ctx.cpu.model).u32("stepping", ctx.cpu.stepping).str("brand", ctx.cpu.brand);
    r.begin_array("features");
    for (int i = 0; i < cpu::FEATURE_COUNT; ++i)
        if (cpu::has(ctx.cpu, cpu::FEATURES[i])) r.item_str(cpu::FEATURES[i].name);
    r.end_array().end_object();
    r.u64("tsc_hz", timer::tsc_hz()).str("cpu_class", cpu::class_name(ctx.cpu)).str("isa", isa::name(isa::in_use()));
    r.begin_object("clock").str("name", timer::clock_name(timer::clock())).u64("hz", timer::hz()).u32("read_cost", timer::read_cost()).end_object();
    r.str("mode", vga::mode_name(vga::mode())).i32("page", vga::page_count() ? vga::shown_page() : -1);
    r.str("palette", raster::palette_name(ctx.palette)).str("cmdline", ctx.cmdline);
    r.end();
}

void cmd_mode(Context& ctx, const StrView* args, size_t) {
    const ModeSetter* setter = nullptr;
    for (const ModeSetter& s : MODE_SETTERS)
        if (args[0].equals(vga::mode_name(s.mode))) setter = &s;
    if (!setter) {
        unknown_name_error("mode", "mode", args[0], [](int i) { return vga::mode_name(MODE_SETTERS[i].mode); }, MODE_SETTER_COUNT);
        return;
    }
    uint64_t t0 = timer::now();
    setter->set();
    vga::load_palette(raster::palette(ctx.palette));
    uint64_t ticks = timer::since(t0);
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
        unknown_name_error("pattern", "pattern", args[0], [](int i) { return raster::pattern_name(raster::Pattern(i)); },
                           raster::PATTERN_COUNT);
        return;
    }
    int page;
    if (!parse_page("pattern", args[1], &page)) return;
    uint64_t t0 = timer::now();
    patterns::draw(p, page);
    uint64_t ticks = timer::since(t0);
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
        unknown_name_error("palette", "palette", args[0], [](int i) { return raster::palette_name(raster::PaletteId(i)); },
                           raster::PALETTE_COUNT);
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

// `readback PAGE [crc]`: the page's indices, or with `crc` only their checksum (a picture is some
// 90 KB on the line, 8 s at 115200 baud; its CRC-32 a few bytes).
void cmd_readback(Context&, const StrView* args, size_t nargs) {
    const bool crc_only = nargs == 2;
    if (crc_only && !args[1].equals("crc")) {
        usage_error("readback");
        return;
    }
    int page;
    if (!parse_page("readback", args[0], &page)) return;
    const uint32_t pixels = uint32_t(vga::WIDTH * vga::height());
    vga::read_page(page, g_readback);
    uint32_t crc = lib::crc32(0, g_readback, pixels);
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "readback").u32("page", uint32_t(page)).u32("width", vga::WIDTH).u32("height", uint32_t(vga::height()));
    if (crc_only) {
        r.hex32("crc32", crc).end();
        return;
    }
    r.str("encoding", "packbits+base64").hex32("crc32", crc);
    r.begin_raw_string("data");
    lib::Base64Encoder b64(r.raw_sink());
    size_t packed = lib::packbits_encode(g_readback, pixels, put_base64, &b64);
    b64.finish();
    r.end_raw_string();
    r.u32("packed_bytes", uint32_t(packed)).end();
}

void cmd_vbe(Context&, const StrView* args, size_t) {
    if (!args[0].equals("on")) {
        usage_error("vbe");
        return;
    }
    if (!vga::enable_bochs_vbe_640x480()) {
        reply::error("vbe", "no Bochs VBE adapter (ports 0x1CE/0x1CF)");
        return;
    }
    reply::begin(true).str("cmd", "vbe").str("mode", vga::mode_name(vga::mode())).u32("width", 640).u32("height", 480).u32("bpp", 8).end();
}

}  // namespace server
