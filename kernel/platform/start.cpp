// kernel_start, from boot/entry.asm: COM1 up; the loader, the FPU and the RAM checked (a PC
// without enough refused on COM1 and on the screen), the pool placed in the largest stretch of RAM
// the loader reports (memory.h); then the build of the C++ for this CPU (isa.h: the boot option
// isa=i486 keeps the 486's on a P6), its constructors, its kernel_main.
#include <stdint.h>

#include "drivers/cpu.h"
#include "drivers/serial.h"
#include "kernel/lib/fmt.h"
#include "kernel/lib/words.h"
#include "kernel/platform/guard.h"
#include "kernel/platform/isa.h"
#include "kernel/platform/memory.h"
#include "kernel/platform/multiboot.h"
#include "kernel/platform/panic.h"

extern "C" {
using Constructor = void (*)();
extern Constructor __i486_init_array_start[], __i486_init_array_end[];
extern Constructor __p6_init_array_start[], __p6_init_array_end[];
extern uint8_t __kernel_start[], __kernel_end[];
extern uint8_t fpu_present;  // boot/entry.asm's probe
[[noreturn]] void kernel_main(uint32_t magic, const multiboot::Info* info);
[[noreturn]] void p6_kernel_main(uint32_t magic, const multiboot::Info* info) asm("p6.kernel_main");
}

namespace {

// The pool the kernel needs at least: the buffers its constructors take (what every 3D scene and
// screen-space scene has, the RAM surfaces, the upload space: a quarter of the pool) with room to
// spare for a small scene (docs/platform.md, "Memory"); a scene's own buffers are taken at its load.
constexpr uint32_t MIN_POOL_BYTES = 2u << 20;

// Whether the command line holds the word `word` (among its first 16, as kernel_main reads them).
bool has_word(const char* line, const char* word) {
    lib::StrView words[16];
    size_t n = line ? lib::split_words(line, words, 16) : 0;
    if (n > 16) n = 16;
    for (size_t i = 0; i < n; ++i)
        if (words[i].equals(word)) return true;
    return false;
}

uint32_t kib(uint64_t bytes) { return uint32_t(bytes >> 10); }

void place_pool(const multiboot::Info* info) {
    const uint64_t image_start = uintptr_t(__kernel_start), image_end = uintptr_t(__kernel_end);
    const uint64_t missing = multiboot::first_not_ram(info, image_start, image_end);
    if (missing < image_end) {
        lib::Fmt m;
        m.s("not enough memory: the kernel's image needs RAM from ").hex(uint32_t(image_start)).s(" to ").hex(uint32_t(image_end));
        m.s(", the loader reports none at ").hex(uint32_t(missing));
        panic(m.c_str());
    }
    // the largest stretch around the modules, or, where it is larger, the largest with the modules
    // in it gathered at its top
    memory::Range kept[memory::MAX_KEPT];
    memory::Range pool = memory::largest_free(info, kept, memory::kept(info, image_start, image_end, kept));
    const memory::Range with_modules = memory::largest_free(info, kept, memory::kept(info, image_start, image_end, kept, false));
    if (memory::gather_modules(info, with_modules, false).bytes() > pool.bytes()) pool = memory::gather_modules(info, with_modules, true);
    if (pool.bytes() < MIN_POOL_BYTES) {
        lib::Fmt m;
        m.s("not enough memory: modexlab needs ").u(kib(MIN_POOL_BYTES)).s(" KiB of free RAM for its buffers beside its ");
        m.u(kib(image_end - image_start)).s(" KiB image; the largest stretch the loader reports is ").u(kib(pool.bytes()));
        m.s(" KiB (").hex(uint32_t(pool.start)).s("..").hex(uint32_t(pool.end)).s(")");
        panic(m.c_str());
    }
    guard::place(uint32_t(pool.start), uint32_t(pool.end));
}

}  // namespace

extern "C" [[noreturn]] void kernel_start(uint32_t magic, const multiboot::Info* info) {
    serial::init();
    if (magic != multiboot::BOOTLOADER_MAGIC) {
        lib::Fmt m;
        m.s("bad multiboot magic ").hex(magic).s(" (expected ").hex(multiboot::BOOTLOADER_MAGIC).s("): not loaded by a Multiboot loader");
        panic(m.c_str());
    }
    // every mapper's setup and spans, the geometry and the exact reference compute in doubles on
    // the x87 (docs/platform.md, "The CPU"); CPUID's FPU flag counts too, where there is CPUID
    const cpu::Info id = cpu::detect();
    if (!fpu_present || cpu::denies_fpu(id))
        panic("no FPU (a 486SX, or a 386 without a 387): modexlab's geometry, its exact reference and every mapper compute in "
              "double precision on the x87, which this PC does not have");
    place_pool(info);
    const char* cmdline = (info->flags & multiboot::INFO_CMDLINE) ? reinterpret_cast<const char*>(uintptr_t(info->cmdline)) : nullptr;
    isa::use(has_word(cmdline, "isa=i486") ? isa::Path::I486 : isa::for_cpu(id));
    const bool p6 = isa::in_use() == isa::Path::P6;
    for (Constructor* c = p6 ? __p6_init_array_start : __i486_init_array_start; c < (p6 ? __p6_init_array_end : __i486_init_array_end); ++c)
        (*c)();
    if (p6) p6_kernel_main(magic, info);
    kernel_main(magic, info);
}
