// The diagnostic commands: CPU faults on purpose (the harness's failure reports), the NASM loops
// checked against their C++ twins (selftest), and leaving QEMU with a status (exit).
#include "drivers/debug_exit.h"
#include "drivers/serial.h"
#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/core/fuzz.h"
#include "kernel/core/policy.h"
#include "kernel/core/render.h"
#include "kernel/core/selftest.h"
#include "kernel/platform/guard.h"
#include "kernel/present/parts.h"
#include "kernel/platform/idt.h"
#include "kernel/lib/words.h"
#include "kernel/server/commands.h"
#include "kernel/server/reply.h"
#include "kernel/platform/vga_selftest.h"

namespace server {

namespace {

// A mapper reading past its texture or writing past its surface, caught by the guard pages
// (kernel/platform/guard.h): `exact` draws a quad over the whole screen with a texture that says it is
// 64 x 64 but whose buffer holds 32 rows (clamped, the screen's lower half reads rows 32 to 63), or
// into a linear surface that says it is 320 x 240 but whose buffer holds 120 rows. The page
// fault's report names the buffer, the mapper and the polygon.
void draw_out_of_bounds(bool short_texture) {
    constexpr int32_t SIDE = 64;
    static uint8_t *texels = nullptr, *short_texels = nullptr, *surface = nullptr, *short_surface = nullptr;
    if (!texels) {
        const size_t need = guard::footprint(size_t(SIDE) * SIDE) + guard::footprint(size_t(SIDE) * SIDE / 2) +
                            guard::footprint(raster::SCREEN_PIXELS) + guard::footprint(raster::SCREEN_PIXELS / 2);
        if (!reply::room_for(need, "fault", "the fault's texture and surface")) return;
        texels = guard::take(size_t(SIDE) * SIDE, "fault texture");
        short_texels = guard::take(size_t(SIDE) * SIDE / 2, "fault texture (32 of its 64 rows)");
        surface = guard::take(raster::SCREEN_PIXELS, "fault surface");
        short_surface = guard::take(raster::SCREEN_PIXELS / 2, "fault surface (120 of its 240 rows)");
    }
    const raster::Texture tex{short_texture ? short_texels : texels, SIDE, SIDE, raster::Wrap::Clamp};
    raster::Target target = raster::linear_target(short_texture ? surface : short_surface, raster::SCREEN_WIDTH, raster::SCREEN_HEIGHT,
                                                  raster::SCREEN_WIDTH);
    const double W = raster::SCREEN_WIDTH, H = raster::SCREEN_HEIGHT;
    const raster::Vertex quad[4] = {{raster::snap(0), raster::snap(0), 1, 0, 0},
                                    {raster::snap(W), raster::snap(0), 1, SIDE, 0},
                                    {raster::snap(W), raster::snap(H), 1, SIDE, SIDE},
                                    {raster::snap(0), raster::snap(H), 1, 0, SIDE}};
    const raster::Mapper& exact = *raster::find_mapper("exact");
    raster::RenderStats stats;
    idt::drawing_now() = raster::DrawingNow{exact.name, 0};
    raster::draw_polygon(quad, 4, tex, exact, raster::Axis::Rows, target, &stats);
    idt::drawing_now() = raster::DrawingNow{};
}
void read_past_texture() { draw_out_of_bounds(true); }
void write_past_surface() { draw_out_of_bounds(false); }

// The CPU exception's report is fault's reply (kernel/platform/idt.cpp); triple and hang test that the
// harness catches the failures a kernel cannot report. The first is the default.
struct Fault {
    const char* name;
    void (*raise)();
};
constexpr Fault FAULTS[] = {
    {"ud", fault_ud2},
    {"de", fault_divide},
    {"gp", fault_gp},
    {"triple", fault_triple},  // no reply: QEMU ends with status 0
    {"hang", fault_hang},      // no reply ever
    {"texture-read", read_past_texture},    // a page fault (#PF) naming the buffer
    {"surface-write", write_past_surface},
};
constexpr int FAULT_COUNT = sizeof(FAULTS) / sizeof(FAULTS[0]);

constexpr uint32_t SELFTEST_SEED = 20261121;
constexpr uint32_t DEFAULT_CASES = 2000, MAX_CASES = 1000000;
// Cases checked between looks at COM1 (each chunk its own seed: SELFTEST_SEED + its first case), so
// that a line stops even a long check within a fraction of a second.
constexpr uint32_t CHUNK_CASES = 1000;
constexpr int MAX_CHECKED_LOOPS = 16;
// The loops' destinations and texels, over a megabyte, far beyond the 64 KiB kernel stack: taken
// at the first selftest and kept. (4-aligned: each ends on a page, and its size is a multiple of 4)
uint8_t *g_check_a = nullptr, *g_check_b = nullptr, *g_check_texels = nullptr;
bool take_check_buffers() {
    if (g_check_a) return true;
    const size_t need = 2 * guard::footprint(raster::CHECK_DST_BYTES) + guard::footprint(raster::CHECK_TEXEL_BYTES);
    if (!reply::room_for(need, "selftest", "the selftest's buffers")) return false;
    g_check_a = guard::take(raster::CHECK_DST_BYTES, "selftest destination (twin)");
    g_check_b = guard::take(raster::CHECK_DST_BYTES, "selftest destination (NASM)");
    g_check_texels = guard::take(raster::CHECK_TEXEL_BYTES, "selftest texels");
    return true;
}
static_assert(raster::CHECK_DST_BYTES % 4 == 0);

}  // namespace

void cmd_fault(Context&, const StrView* args, size_t nargs) {
    for (const Fault& f : FAULTS)
        if (nargs == 0 || args[0].equals(f.name)) {
            f.raise();  // (returns only where it could not: its error replied)
            return;
        }
    unknown_name_error("fault", "fault", args[0], [](int i) { return FAULTS[i].name; }, FAULT_COUNT);
}

void cmd_selftest(Context&, const StrView* args, size_t nargs) {
    uint32_t cases = DEFAULT_CASES;
    if (nargs > 0 && (!lib::parse_u32(args[0], &cases) || cases == 0 || cases > MAX_CASES)) {
        lib::Fmt m;
        m.s("usage: selftest [CASES] (1..").u(MAX_CASES).s(", default ").u(DEFAULT_CASES).s(")");
        reply::error("selftest", m.c_str());
        return;
    }
    if (!take_check_buffers()) return;
    raster::CheckBuffers buffers{g_check_a, g_check_b, raster::CHECK_DST_BYTES, g_check_texels};
    raster::LoopCheck results[MAX_CHECKED_LOOPS];
    int n = 0;
    bool all_equal = true;
    uint64_t t0 = timer::now();
    bool vga_checked = vga::mode() == vga::Mode::ModeX && !vga::framebuffer_in_use();  // (RAM pages: no VGA to program)
    const raster::Mapper* loops[MAX_CHECKED_LOOPS];
    int count = raster::checked_loops(loops, MAX_CHECKED_LOOPS);
    bool stopped = false;
    uint32_t chunks = 0;  // done, over all loops: a byte on COM1 stops the check before the next
    for (int i = 0; i < count && !stopped; ++i) {
        const raster::Mapper& loop = *loops[i];
        bool vga = loop.needs & raster::NEED_VGA_FOR_ASM;
        if (!loop.asm_loop || (vga && !vga_checked)) continue;
        raster::LoopCheck& total = results[n];
        total = raster::LoopCheck{loop.name};
        for (uint32_t done = 0; done < cases && !(stopped = interrupted(chunks)); done += CHUNK_CASES, ++chunks) {
            const uint32_t k = cases - done < CHUNK_CASES ? cases - done : CHUNK_CASES;
            const raster::LoopCheck c = vga ? vga_selftest::check(loop, SELFTEST_SEED + done, k, g_check_texels)
                                            : loop.check(loop, loop.asm_loop, SELFTEST_SEED + done, k, buffers);
            total.loop = c.loop;
            if (c.mismatches && !total.mismatches) total.first_mismatch = done + c.first_mismatch;
            total.cases += c.cases, total.mismatches += c.mismatches, total.pixels += c.pixels;
        }
        if (total.cases == 0) break;
        all_equal = all_equal && total.mismatches == 0;
        ++n;
    }
    lib::JsonLine r = reply::begin(all_equal);
    r.str("cmd", "selftest");
    if (!all_equal) r.str("error", "a NASM loop differs from its C++ twin");
    r.u32("cases", cases).u64("ticks", timer::since(t0)).boolean("interrupted", stopped);
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

void cmd_exit(Context&, const StrView* args, size_t) {
    uint32_t code;
    if (!lib::parse_u32(args[0], &code) || code > debug_exit::MAX_USER_CODE) {
        lib::Fmt m;
        m.s("bad code: 0..").u(debug_exit::MAX_USER_CODE).s(" (QEMU then exits with status 2*CODE+1)");
        reply::error("exit", m.c_str());
        return;
    }
    reply::begin(true).str("cmd", "exit").u32("code", code).end();
    serial::flush();
    debug_exit::exit(code);
    // No isa-debug-exit device (a real PC): stop here.
    vga::text_write("modexlab: exit; halted\n");
    for (;;) asm volatile("cli; hlt");
}

namespace {

// fuzz's textures (kernel/core/fuzz.h), each with its copies between guard pages: made on the
// first `fuzz` and kept.
struct FuzzBank {
    raster::Texture textures[raster::FUZZ_TEXTURE_COUNT];
    char names[raster::FUZZ_TEXTURE_COUNT][24];
};

// The bank's textures made into `bank` (kept), or, where it is null, what they take of the pool.
size_t fuzz_textures(FuzzBank* bank) {
    static constexpr present::TextureNames NAMES{"fuzz texture", "fuzz texture (bordered copy)", "fuzz texture (aligned copy)",
                                                 "fuzz texture (doubled copy)"};
    static constexpr raster::TextureKind XOR = raster::TextureKind::Xor;
    present::Parts p{bank ? present::Take::Kept : present::Take::Count};
    for (int i = 0; i < raster::FUZZ_TEXTURE_COUNT; ++i) {
        const raster::FuzzTextureSize size = raster::fuzz_texture_size(i);
        const raster::Wrap wrap = raster::fuzz_texture_wrap(i);
        const char* name = nullptr;
        if (bank) {
            lib::Fmt n;
            n.u(uint32_t(size.width)).s(" x ").u(uint32_t(size.height)).s(" ").s(raster::wrap_name(wrap));
            lib::copy_c_string(bank->names[i], sizeof bank->names[i], n.c_str());
            name = bank->names[i];
        }
        const raster::Texture t = present::texture_parts(p, raster::Texture{nullptr, size.width, size.height, wrap}, true, NAMES, name, &XOR);
        if (bank) bank->textures[i] = t;
    }
    return p.bytes;
}

uint8_t* fuzz_surface(void*, bool) {
    static uint8_t* const surface = guard::take(raster::SCREEN_PIXELS, "fuzz surface");
    return surface;
}

}  // namespace

void cmd_fuzz(Context& ctx, const StrView* args, size_t nargs) {
    constexpr uint32_t MOST = 100000000;
    uint32_t count = 0, seed = 1;
    if (!lib::parse_u32(args[0], &count) || count == 0 || count > MOST || (nargs > 2 && !lib::parse_u32(args[2], &seed))) {
        usage_error("fuzz");
        return;
    }
    const raster::Mapper* mapper = raster::find_mapper(args[1]);
    if (!mapper) {
        unknown_name_error("fuzz", "mapper", args[1], [](int i) { return raster::MAPPERS[i].name; }, raster::MAPPER_COUNT);
        return;
    }
    static FuzzBank* bank = nullptr;
    if (!bank) {
        const size_t need = guard::footprint(sizeof(FuzzBank)) + fuzz_textures(nullptr) + guard::footprint(raster::SCREEN_PIXELS);
        if (!reply::room_for(need, "fuzz", "fuzz's textures")) return;
        bank = guard::take_object<FuzzBank>("fuzz's texture bank");
        fuzz_textures(bank);
        fuzz_surface(nullptr, false);
    }
    Progress p = progress("fuzz", ctx);
    const raster::Watch watch = p.watch();
    const uint64_t t0 = timer::now();
    const raster::FuzzStats f = raster::fuzz_mapper(*mapper, seed, count, bank->textures, fuzz_surface, nullptr, raster::Variant::Asm, &watch);
    const uint64_t ticks = timer::since(t0);
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "fuzz").str("mapper", mapper->name).u32("seed", seed).u32("polygons", f.tried).u32("polygons_asked", count);
    r.u32("drawn", f.by_status[0]).begin_object("refused");
    for (int s = 1; s < 7; ++s) r.u32(raster::setup_status_name(raster::SetupStatus(s)), f.by_status[s]);
    r.end_object().u64("pixels", f.pixels).u32("written_outside_clip", f.written_outside).u32("first_bad_batch", f.first_bad_batch);
    r.boolean("interrupted", f.interrupted).u64("ticks", ticks).end();
}

}  // namespace server
