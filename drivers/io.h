// x86 port I/O. Every access is also a compiler memory barrier: video memory written through plain
// pointers must reach the plane the map mask selected before the mask changes.
#pragma once

#include <stdint.h>

namespace io {

inline void outb(uint16_t port, uint8_t value) { asm volatile("outb %0, %1" : : "a"(value), "Nd"(port) : "memory"); }
inline void outw(uint16_t port, uint16_t value) { asm volatile("outw %0, %1" : : "a"(value), "Nd"(port) : "memory"); }
inline uint8_t inb(uint16_t port) {
    uint8_t v;
    asm volatile("inb %1, %0" : "=a"(v) : "Nd"(port) : "memory");
    return v;
}
inline uint16_t inw(uint16_t port) {
    uint16_t v;
    asm volatile("inw %1, %0" : "=a"(v) : "Nd"(port) : "memory");
    return v;
}
// A write to an unused port: about a microsecond on ISA, for devices that need time between accesses.
inline void wait() { outb(0x80, 0); }

}  // namespace io
