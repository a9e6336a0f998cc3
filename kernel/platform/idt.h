// The IDT: CPU exceptions 0-31 go to a handler that reports them on COM1 and ends the run; IRQs
// 0-15 (vectors 0x20-0x2F) to irq_handler (drivers/keyboard.h), which serves the keyboard.
#pragma once

#include <stdint.h>

#include "kernel/core/render.h"

namespace idt {

// Register state pushed by the stubs in boot/isr.asm (pushad, then what the stub and the CPU pushed).
struct ExceptionFrame {
    uint32_t edi, esi, ebp, esp_pushad, ebx, edx, ecx, eax;
    uint32_t vector, error_code;
    uint32_t eip, cs, eflags;
};
// isr_common pushes: CPU eflags/cs/eip, stub error code and vector, then pushad (eax first, edi last).
static_assert(__builtin_offsetof(ExceptionFrame, eax) == 28);
static_assert(__builtin_offsetof(ExceptionFrame, vector) == 32);
static_assert(__builtin_offsetof(ExceptionFrame, error_code) == 36);
static_assert(__builtin_offsetof(ExceptionFrame, eip) == 40);
static_assert(sizeof(ExceptionFrame) == 52);

void init();

// What is being drawn, for a page fault's report: the drawing commands' watches point here.
raster::DrawingNow& drawing_now();

// Human name of an exception vector ("#UD", ...).
const char* exception_name(uint32_t vector);

}  // namespace idt

// Deliberate fault sites in boot/isr.asm, for the `fault` command.
extern "C" [[noreturn]] void fault_ud2();
extern "C" [[noreturn]] void fault_divide();
extern "C" [[noreturn]] void fault_gp();
extern "C" [[noreturn]] void fault_triple();
extern "C" [[noreturn]] void fault_hang();
