// A lap timer for the bench: splits a drawing's time into polygon setup, edge walking, the inner
// loops and auto's choosing. The core has no clock of its own; the caller lends one (timer::now in the
// kernel, rdtsc on the host). Every lap costs a clock read and a few instructions: `calibrate`
// measures that cost and `net` takes it off again.
#pragma once

#include <stdint.h>

namespace raster {

// Choose: auto's work to choose a mapper beyond setting the polygon up (plans, tests, bounds, the
// search; choice.h); no other mapper laps it.
enum class Phase : uint8_t { Setup, Walk, Inner, Choose, Count };

struct Probe {
    uint64_t (*clock)() = nullptr;
    uint64_t last = 0;
    uint64_t ticks[int(Phase::Count)] = {};
    uint32_t laps[int(Phase::Count)] = {};
    uint64_t lap_cost = 0;  // ticks one lap adds to the interval it closes (calibrate)
    // Where the timing model's QEMU plugin watches the laps, or none: a lap writes the byte of its
    // phase, start() the byte after the phases; calibrate's probe the same five bytes on.
    volatile uint8_t* marks = nullptr;
    static constexpr int MARKS = int(Phase::Count) + 1;

    // Charges the time since the last lap to `phase`. Out of line, so that every lap costs what
    // calibrate measured, wherever it is called from.
    __attribute__((noinline)) void lap(Phase phase) {
        uint64_t now = clock();
        ticks[int(phase)] += now - last;
        ++laps[int(phase)];
        last = now;
        if (marks) marks[int(phase)] = 1;
    }
    __attribute__((noinline)) void start() {
        last = clock();
        if (marks) marks[int(Phase::Count)] = 1;
    }
    // The cost of a lap: the least interval between two back-to-back laps (least: an interrupt
    // or a cache miss only ever adds). Exact under QEMU's icount, where ticks are instructions.
    void calibrate() {
        Probe p;
        p.clock = clock;
        p.marks = marks ? marks + MARKS : nullptr;
        p.start();
        uint64_t best = ~uint64_t(0);
        for (int i = 0; i < 64; ++i) {
            uint64_t before = p.ticks[0];
            p.lap(Phase::Setup);
            if (p.ticks[0] - before < best) best = p.ticks[0] - before;
        }
        lap_cost = best;
    }
    // The phase's ticks without the laps' own cost.
    uint64_t net(Phase phase) const {
        uint64_t cost = lap_cost * laps[int(phase)];
        return ticks[int(phase)] > cost ? ticks[int(phase)] - cost : 0;
    }
};

// For the drawing code: a lap when a probe is attached.
inline void probe_lap(Probe* p, Phase phase) {
    if (p) p->lap(phase);
}

}  // namespace raster
