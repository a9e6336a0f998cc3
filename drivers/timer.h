// Time: the kernel's clock (the TSC where the CPU has one, its rate calibrated against the PIT; else
// the PIT's own 1.193182 MHz count, channel 0 latched, its wraps counted by IRQ 0), and PIT channel
// 2 one-shots for waits.
#pragma once

#include <stdint.h>

namespace timer {

constexpr uint32_t PIT_HZ = 1193182;

enum class Clock : uint8_t { Tsc, Pit };

// Picks the clock (the TSC only where `has_tsc`), calibrates it and measures what one read of it
// costs. The PIT clock unmasks IRQ 0 and turns interrupts on; on a 486 (`is_486`) it measures the
// CPU's clock too (cpu_hz).
void init(bool has_tsc, bool is_486);
Clock clock();
const char* clock_name(Clock c);  // "tsc", "pit"
uint64_t hz();                    // the clock's ticks a second (the TSC's measured rate, or PIT_HZ)
uint64_t tsc_hz();                // the TSC's measured rate: the CPU clock where it has one; else 0
// The CPU's clock where it is known: the TSC's rate, or on the PIT clock a 486's, measured by a loop
// of DEC and a taken JNZ (1 + 3 clocks an iteration on a 486); 0 where neither applies.
uint64_t cpu_hz();
const char* cpu_hz_from();        // "tsc", "486 loop", "" (unknown)
uint32_t read_cost();             // the ticks one read adds to an interval (the Zen timer's overhead)
// Ticks in the unit figures are shown in, in tenths: cycles where the CPU's clock is known (cpu_hz),
// else nanoseconds.
uint64_t tenths_shown(uint64_t ticks);
const char* unit_shown();         // "cycles", "ns"

namespace detail {
extern bool g_tsc;
uint64_t pit_now();
inline uint64_t rdtsc() {
    uint32_t lo, hi;
    asm volatile("rdtsc" : "=a"(lo), "=d"(hi));
    return (uint64_t(hi) << 32) | lo;
}
}  // namespace detail

// The clock's count: monotonic, in its own ticks (the TSC only where the CPU has one).
inline uint64_t now() { return __builtin_expect(detail::g_tsc, 1) ? detail::rdtsc() : detail::pit_now(); }
// The clock as a plain function, for a probe's laps (core/probe.h): rdtsc alone, or the PIT's read.
using Reader = uint64_t (*)();
Reader reader();

// Ticks from t0 to t1 (two now()), less the cost of one read; never below 0.
inline uint64_t between(uint64_t t0, uint64_t t1) {
    const uint64_t d = t1 - t0, cost = read_cost();
    return d > cost ? d - cost : 0;
}
inline uint64_t since(uint64_t t0) { return between(t0, now()); }

// IRQ 0 (the PIT clock): one wrap of channel 0's count (irq_handler calls it).
void on_irq0();

// PIT channel 2, mode 0: OUT2 rises `count` PIT ticks (count <= 65535) after the start.
void pit_oneshot_start(uint16_t count);
bool pit_oneshot_done();

// Waits `ms` milliseconds in 1 ms one-shots; returns early (true) as soon as stop(ctx) is true.
bool wait_ms_or(uint32_t ms, bool (*stop)(void* ctx), void* ctx);

}  // namespace timer
