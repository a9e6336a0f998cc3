// QEMU's isa-debug-exit device (-device isa-debug-exit,iobase=0xf4,iosize=0x04): writing v exits
// QEMU with status (v << 1) | 1. On a real PC the port is unused and the write does nothing.
#pragma once

#include <stdint.h>

#include "drivers/io.h"

namespace debug_exit {

constexpr uint16_t PORT = 0xF4;

// Values the kernel writes (QEMU status = 2 * value + 1); docs/protocol.md has the table.
constexpr uint32_t MAX_USER_CODE = 0x3F;      // `exit CODE`: 0..63 -> status 1..127
constexpr uint32_t FAULT_BASE = 0x40;         // CPU exception v: 0x40 + v -> status 129..191
constexpr uint32_t PANIC = 0x60;              // bad multiboot magic, broken invariant -> status 193

inline void exit(uint32_t value) { io::outb(PORT, uint8_t(value)); }

}  // namespace debug_exit
