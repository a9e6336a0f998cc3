// Time: the TSC (read, and its rate calibrated against the PIT) and PIT channel 2 one-shots for waits.
#pragma once

#include <stdint.h>

namespace timer {

constexpr uint32_t PIT_HZ = 1193182;

inline uint64_t rdtsc() {
    uint32_t lo, hi;
    asm volatile("rdtsc" : "=a"(lo), "=d"(hi));
    return (uint64_t(hi) << 32) | lo;
}

// Counts TSC ticks over a PIT one-shot of about 50 ms; 0 when the PIT never fired.
uint64_t calibrate_tsc_hz();

// PIT channel 2, mode 0: OUT2 rises `count` PIT ticks (count <= 65535) after the start.
void pit_oneshot_start(uint16_t count);
bool pit_oneshot_done();

// Waits `ms` milliseconds in 1 ms one-shots; returns early (true) as soon as stop(ctx) is true.
bool wait_ms_or(uint32_t ms, bool (*stop)(void* ctx), void* ctx);

}  // namespace timer
