// IDT set-up and the exception handler: one JSON event line on COM1, a text-mode line, then isa-debug-exit.
#include "kernel/platform/idt.h"

#include "drivers/debug_exit.h"
#include "drivers/pic.h"
#include "drivers/serial.h"
#include "drivers/vga.h"
#include "kernel/core/render.h"
#include "kernel/platform/guard.h"
#include "kernel/lib/fmt.h"
#include "kernel/lib/json.h"
#include "kernel/server/reply.h"

extern "C" const uint32_t isr_stub_table[32];
extern "C" const uint32_t irq_stub_table[16];

namespace idt {

namespace {

struct [[gnu::packed]] Gate {
    uint16_t offset_low;
    uint16_t selector;
    uint8_t zero;
    uint8_t type_attr;
    uint16_t offset_high;
};
static_assert(sizeof(Gate) == 8);

struct [[gnu::packed]] Descriptor {
    uint16_t limit;
    uint32_t base;
};

constexpr uint16_t KERNEL_CS = 0x08;
constexpr uint8_t INTERRUPT_GATE_RING0 = 0x8E;  // present, DPL 0, 32-bit interrupt gate (IF cleared)

Gate g_idt[48];  // the CPU's exceptions, then IRQs 0-15 (pic::VECTOR_BASE on)

constexpr const char* NAMES[32] = {
    "#DE", "#DB", "NMI", "#BP", "#OF", "#BR", "#UD", "#NM", "#DF", "CSO", "#TS", "#NP", "#SS", "#GP", "#PF", "#15",
    "#MF", "#AC", "#MC", "#XM", "#VE", "#CP", "#22", "#23", "#24", "#25", "#26", "#27", "#HV", "#VC", "#SX", "#31",
};

bool g_in_handler = false;
raster::DrawingNow g_drawing_now;
constexpr uint32_t PAGE_FAULT = 14;

// A page fault's address (CR2), the guarded buffer it hit, and what was being drawn.
void describe_page_fault(lib::JsonLine& r, uint32_t error_code) {
    uint32_t cr2;
    asm volatile("mov %%cr2, %0" : "=r"(cr2));
    r.hex32("cr2", cr2);
    guard::Hit hit;
    if (guard::find(cr2, &hit)) {
        lib::Fmt m;
        m.s(error_code & 2 ? "a write " : "a read ").u(hit.offset).s(hit.offset == 1 ? " byte" : " bytes");
        m.s(hit.after ? " past the end of " : " before the start of ").s(hit.what);
        if (hit.name) m.s(" ").s(hit.name);
        r.str("buffer", m.c_str());
    }
    const raster::DrawingNow& now = drawing_now();
    if (now.mapper) r.str("mapper", now.mapper).u32("polygon", now.polygon);
}

}  // namespace

raster::DrawingNow& drawing_now() { return g_drawing_now; }

const char* exception_name(uint32_t vector) { return vector < 32 ? NAMES[vector] : "?"; }

void init() {
    static_assert(pic::VECTOR_BASE == 32, "the IRQ gates follow the exceptions'");
    for (int v = 0; v < 48; ++v) {
        uint32_t handler = v < 32 ? isr_stub_table[v] : irq_stub_table[v - 32];
        g_idt[v] = Gate{uint16_t(handler), KERNEL_CS, 0, INTERRUPT_GATE_RING0, uint16_t(handler >> 16)};
    }
    Descriptor d{sizeof(g_idt) - 1, reinterpret_cast<uint32_t>(&g_idt)};
    asm volatile("lidt %0" : : "m"(d));
}

}  // namespace idt

extern "C" [[noreturn]] void exception_handler(const idt::ExceptionFrame* f) {
    using idt::g_in_handler;
    if (!g_in_handler) {  // a fault while reporting a fault goes straight to the exit
        g_in_handler = true;
        uint32_t fault_esp = f->esp_pushad + 5 * 4;  // above vector, error code, eip, cs, eflags
        // The fault is the reply to the command in progress (or an unsolicited line at boot).
        lib::Fmt message;
        message.s("CPU exception ").s(idt::exception_name(f->vector)).s(" (vector ").u(f->vector).s(") at eip ").hex(f->eip);
        lib::JsonLine r = reply::begin(false);
        r.str("error", message.c_str())
            .boolean("fault", true)
            .u32("vector", f->vector)
            .str("name", idt::exception_name(f->vector))
            .hex32("error_code", f->error_code)
            .hex32("eip", f->eip)
            .hex32("cs", f->cs)
            .hex32("eflags", f->eflags)
            .hex32("eax", f->eax)
            .hex32("ebx", f->ebx)
            .hex32("ecx", f->ecx)
            .hex32("edx", f->edx)
            .hex32("esi", f->esi)
            .hex32("edi", f->edi)
            .hex32("ebp", f->ebp)
            .hex32("esp", fault_esp);
        if (f->vector == idt::PAGE_FAULT) idt::describe_page_fault(r, f->error_code);
        r.end();
        serial::flush();
        vga::text_write("modexlab: CPU exception ");
        vga::text_write(idt::exception_name(f->vector));
        vga::text_write(" (details on COM1); halted\n");
    }
    debug_exit::exit(debug_exit::FAULT_BASE + (f->vector & 31));
    for (;;) asm volatile("cli; hlt");
}
