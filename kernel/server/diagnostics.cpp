// The diagnostic commands: CPU faults on purpose (the harness's failure reports), the NASM loops
// checked against their C++ twins (selftest), and leaving QEMU with a status (exit).
#include "drivers/debug_exit.h"
#include "drivers/serial.h"
#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/core/selftest.h"
#include "kernel/idt.h"
#include "kernel/server/commands.h"
#include "kernel/server/reply.h"
#include "kernel/vga_selftest.h"

namespace server {

namespace {

// The CPU exception's report is fault's reply (kernel/idt.cpp); triple and hang test that the
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
};
constexpr int FAULT_COUNT = sizeof(FAULTS) / sizeof(FAULTS[0]);

constexpr uint32_t SELFTEST_SEED = 20261121;
constexpr uint32_t DEFAULT_CASES = 2000, MAX_CASES = 1000000;
constexpr int MAX_CHECKED_LOOPS = 16;
// Static: the loops' destinations and texels, over a megabyte, far beyond the 64 KiB kernel stack.
alignas(4) uint8_t g_check_a[raster::CHECK_DST_BYTES];
alignas(4) uint8_t g_check_b[raster::CHECK_DST_BYTES];
uint8_t g_check_texels[raster::CHECK_TEXEL_BYTES];

}  // namespace

void cmd_fault(Context&, const StrView* args, size_t nargs) {
    for (const Fault& f : FAULTS)
        if (nargs == 0 || args[0].equals(f.name)) f.raise();
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
    raster::CheckBuffers buffers{g_check_a, g_check_b, raster::CHECK_DST_BYTES, g_check_texels};
    raster::LoopCheck results[MAX_CHECKED_LOOPS];
    int n = 0;
    bool all_equal = true;
    uint64_t t0 = timer::rdtsc();
    bool vga_checked = vga::mode() == vga::Mode::ModeX;
    const raster::Mapper* loops[MAX_CHECKED_LOOPS];
    int count = raster::checked_loops(loops, MAX_CHECKED_LOOPS);
    bool stopped = false;
    for (int i = 0; i < count && !(stopped = interrupted(uint32_t(n))); ++i) {
        const raster::Mapper& loop = *loops[i];
        bool vga = loop.needs & raster::NEED_VGA_FOR_ASM;
        if (!loop.asm_loop || (vga && !vga_checked)) continue;
        results[n] = vga ? vga_selftest::check(loop, SELFTEST_SEED, cases, g_check_texels)
                         : loop.check(loop, loop.asm_loop, SELFTEST_SEED, cases, buffers);
        all_equal = all_equal && results[n].mismatches == 0;
        ++n;
    }
    lib::JsonLine r = reply::begin(all_equal);
    r.str("cmd", "selftest");
    if (!all_equal) r.str("error", "a NASM loop differs from its C++ twin");
    r.u32("cases", cases).u64("ticks", timer::rdtsc() - t0).boolean("interrupted", stopped);
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

}  // namespace server
