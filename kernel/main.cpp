// kernel_main (from kernel_start, which checked the loader and placed the pool): bring up COM1, the
// IDT and the timers, read the boot options, then show and serve.
#include <stdint.h>

#include "drivers/cpu.h"
#include "drivers/debug_exit.h"
#include "drivers/keyboard.h"
#include "drivers/pic.h"
#include "drivers/serial.h"
#include "drivers/timer.h"
#include "drivers/vga.h"
#include "kernel/present/file_table.h"
#include "kernel/platform/guard.h"
#include "kernel/platform/idt.h"
#include "kernel/platform/isa.h"
#include "kernel/lib/fmt.h"
#include "kernel/lib/json.h"
#include "kernel/lib/words.h"
#include "kernel/platform/multiboot.h"
#include "kernel/platform/panic.h"
#include "kernel/core/mapper.h"
#include "kernel/server/server.h"
#include "kernel/show/show.h"
#include "kernel/version.h"

namespace {

enum class BootAction : uint8_t { Demo, Serve };

struct BootOptions {
    BootAction action = BootAction::Demo;
    uint32_t interval_ms = 2000;
    lib::StrView scene;   // the demo shows only this scene file
    lib::StrView mapper;  // and draws with this mapper
    bool patterns = false;  // the demo shows the test patterns, not scenes
    uint32_t bench_frames = 0;  // the demo starts with the on-screen bench, this many frames a row
    bool pit_clock = false;     // clock=pit: time with the PIT even where the CPU has a TSC
    lib::StrView rejected[4];  // words we did not understand, reported in the boot line
    size_t rejected_count = 0;
};

constexpr uint32_t MAX_INTERVAL_MS = 60000;
constexpr uint32_t MAX_BENCH_FRAMES = 1000;

// Set by a global constructor (a value the compiler cannot fold into static initialisation), so
// kernel_main can tell that boot/entry.asm ran .init_array.
constexpr uint32_t CONSTRUCTED = 0xC7057ED;
volatile uint32_t g_constructor_input = CONSTRUCTED;
struct ConstructorCheck {
    uint32_t value;
    ConstructorCheck() : value(g_constructor_input) {}
};
ConstructorCheck g_constructor_check;

bool has_equals(lib::StrView w) {
    for (size_t i = 0; i < w.size; ++i)
        if (w.data[i] == '=') return true;
    return false;
}

// Options are key=value words (docs/protocol.md, "Boot options"). QEMU's -kernel puts the kernel's
// path first and GRUB does not, so a first word without '=' is skipped as that path.
BootOptions parse_options(const char* cmdline) {
    BootOptions o;
    lib::StrView words[16];
    size_t n = lib::split_words(cmdline, words, 16);
    if (n > 16) n = 16;
    for (size_t i = (n > 0 && !has_equals(words[0])) ? 1 : 0; i < n; ++i) {
        lib::StrView w = words[i];
        uint32_t v;
        if (w.equals("boot=demo")) o.action = BootAction::Demo;
        else if (w.equals("boot=serve")) o.action = BootAction::Serve;
        else if (w.starts_with("interval=") && lib::parse_u32(w.drop(9), &v) && v >= 1 && v <= MAX_INTERVAL_MS)
            o.interval_ms = v;
        else if (w.starts_with("scene=") && w.size > 6) o.scene = w.drop(6);
        else if (w.equals("show=patterns") || w.equals("show=scenes")) o.patterns = w.equals("show=patterns");
        else if (w.starts_with("mapper=") && raster::find_mapper(w.drop(7))) o.mapper = w.drop(7);
        else if (w.starts_with("bench=") && lib::parse_u32(w.drop(6), &v) && v >= 1 && v <= MAX_BENCH_FRAMES) o.bench_frames = v;
        else if (w.equals("clock=pit") || w.equals("clock=tsc")) o.pit_clock = w.equals("clock=pit");
        else if (w.equals("isa=i486")) continue;  // (kernel_start's: kernel/platform/isa.h)
        else if (o.rejected_count < 4) o.rejected[o.rejected_count++] = w;
    }
    return o;
}

}  // namespace

extern "C" [[noreturn]] void kernel_main(uint32_t /*magic: kernel_start checked it*/, const multiboot::Info* info) {
    serial::init();
    pic::remap_and_mask();
    idt::init();

    if (g_constructor_check.value != CONSTRUCTED) panic("C++ global constructors did not run");

    server::Context ctx;
    if (info->flags & multiboot::INFO_CMDLINE) ctx.cmdline = reinterpret_cast<const char*>(info->cmdline);
    BootOptions options = parse_options(ctx.cmdline);
    ctx.cpu = cpu::detect();
    const bool guard_pages = guard::init(ctx.cpu.features_edx);
    timer::init(cpu::has_tsc(ctx.cpu) && !options.pit_clock, !ctx.cpu.has_cpuid || ctx.cpu.family == 4);  // (the PIT clock turns interrupts on: IRQ 0 counts its wraps)
    const keyboard::Status keys = keyboard::init();  // (interrupts on from here: IRQ 1 unmasked)
    serial::enable_wakeup();                         // (and IRQ 4, which the UART raises only while a reader waits)
    // a UEFI loader's framebuffer (RGB, by the Multiboot header's video fields): drawn into, the VGA
    // left alone; under BIOS GRUB hands over text mode, and the kernel programs the VGA itself
    bool framebuffer = false;
    if (info->flags & multiboot::INFO_FRAMEBUFFER) {
        const multiboot::FramebufferInfo* f = multiboot::framebuffer(info);
        vga::Framebuffer fb;
        const uint64_t end = f->addr + uint64_t(f->pitch) * f->height;  // (all of it below 4 GiB: identity-mapped, guard.h)
        fb.base = end <= 0x100000000ull ? reinterpret_cast<uint8_t*>(uintptr_t(f->addr)) : nullptr;
        fb.pitch = f->pitch, fb.width = f->width, fb.height = f->height, fb.bpp = f->bpp;
        fb.red_position = f->red_position, fb.red_size = f->red_size, fb.green_position = f->green_position;
        fb.green_size = f->green_size, fb.blue_position = f->blue_position, fb.blue_size = f->blue_size;
        framebuffer = f->type == 1 && vga::use_framebuffer(fb);
    }
    bool vbe_found = vga::disable_bochs_vbe();
    uint32_t skipped_modules = 0;
    file_table::init(info, &skipped_modules);
    uint32_t modules = 0;
    for (int i = 0; i < file_table::count(); ++i) modules += file_table::at(i).origin == file_table::Origin::Module;

    lib::JsonLine boot(serial::sink());
    boot.str("event", "boot").str("version", MODEXLAB_VERSION).str("cmdline", ctx.cmdline);
    boot.str("boot", options.action == BootAction::Demo ? "demo" : "serve").u32("interval_ms", options.interval_ms);
    boot.boolean("bochs_vbe_cleared", vbe_found).u64("tsc_hz", timer::tsc_hz());
    boot.str("clock", timer::clock_name(timer::clock())).u64("clock_hz", timer::hz()).u32("clock_read_cost", timer::read_cost());
    boot.u64("cpu_hz", timer::cpu_hz()).str("cpu_hz_from", timer::cpu_hz_from());
    boot.str("cpu_class", cpu::class_name(ctx.cpu)).str("isa", isa::name(isa::in_use())).str("cpu_isa", isa::name(isa::for_cpu(ctx.cpu)));
    boot.u32("files", uint32_t(file_table::count())).u32("modules", modules).u32("modules_skipped", skipped_modules);
    boot.u32("memory_kib", (info->flags & multiboot::INFO_MEMORY) ? info->mem_upper + 1024 : 0);
    boot.begin_object("pool").hex32("start", guard::pool_start()).u32("kib", uint32_t(guard::pool_bytes() >> 10));
    boot.u32("taken_kib", uint32_t(guard::taken_bytes() >> 10)).end_object();
    boot.boolean("guard_pages", guard_pages).boolean("serial_wakeup", serial::wakes());
    if (framebuffer) {
        const vga::Framebuffer& fb = vga::framebuffer();
        boot.begin_object("framebuffer").hex32("address", uint32_t(reinterpret_cast<uintptr_t>(fb.base))).u32("width", fb.width);
        boot.u32("height", fb.height).u32("pitch", fb.pitch).u32("bpp", fb.bpp).end_object();
    } else {
        boot.boolean("framebuffer", false);
    }
    boot.begin_object("keyboard").boolean("controller", keys.controller).boolean("port", keys.port_ok).boolean("keyboard", keys.keyboard);
    boot.boolean("irq", keys.irq).end_object();
    boot.begin_array("ignored_options");
    for (size_t i = 0; i < options.rejected_count; ++i) {
        lib::Fmt w;
        w.s(options.rejected[i]);
        boot.item_str(w.c_str());
    }
    boot.end_array().end();

    vga::text_write("modexlab " MODEXLAB_VERSION ": serving commands on COM1 (115200 8N1)\n");
    if (options.action == BootAction::Demo) {
        vga::set_mode_x();
        vga::load_palette(raster::palette(ctx.palette));
        show::Options o;
        o.interval_ms = options.interval_ms, o.patterns = options.patterns, o.scene = options.scene, o.mapper = options.mapper;
        o.cpu = &ctx.cpu, o.bench_frames = options.bench_frames;
        show::run(o);
        vga::load_palette(raster::palette(ctx.palette));
    }
    server::run(ctx);
}
