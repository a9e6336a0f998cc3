// The code path the kernel runs: its C++ built for the 486 (every PC from the 486 on) or built for
// the P6 (CMOV, FCOMI), which runs where CPUID reports CMOV and an FPU. Both builds are in the one
// kernel (Makefile, "One kernel for every PC"); kernel_start picks one before any of it runs.
#pragma once

#include <stdint.h>

#include "drivers/cpu.h"

namespace isa {

enum class Path : uint8_t { I486, P6 };

Path in_use();
void use(Path path);  // kernel_start's choice (kernel/platform/start.cpp)
Path for_cpu(const cpu::Info& info);  // the P6 where the CPU has its instructions, else the 486's
const char* name(Path path);  // "i486", "p6"

}  // namespace isa
