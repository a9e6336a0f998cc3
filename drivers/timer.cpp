// PIT channel 2 one-shots (gated through port 0x61, speaker off) and TSC calibration.
#include "drivers/timer.h"

#include "drivers/io.h"

namespace timer {

namespace {

constexpr uint16_t PIT_CH2_DATA = 0x42;
constexpr uint16_t PIT_COMMAND = 0x43;
constexpr uint16_t PORT_B = 0x61;              // bit 0: channel 2 gate, bit 1: speaker, bit 5: OUT2
constexpr uint8_t PIT_CH2_LOHI_MODE0 = 0xB0;   // channel 2, lobyte/hibyte, mode 0, binary
constexpr uint8_t PORT_B_GATE2 = 0x01;
constexpr uint8_t PORT_B_SPEAKER = 0x02;
constexpr uint8_t PORT_B_OUT2 = 0x20;

constexpr uint16_t CALIBRATION_COUNT = 59659;  // 50.0 ms at 1193182 Hz
constexpr uint32_t PIT_TICKS_PER_MS = 1193;    // 0.99985 ms

}  // namespace

void pit_oneshot_start(uint16_t count) {
    uint8_t b = io::inb(PORT_B);
    io::outb(PORT_B, uint8_t((b & ~PORT_B_SPEAKER) | PORT_B_GATE2));
    io::outb(PIT_COMMAND, PIT_CH2_LOHI_MODE0);  // OUT2 goes low
    io::outb(PIT_CH2_DATA, uint8_t(count));
    io::outb(PIT_CH2_DATA, uint8_t(count >> 8)); // counting starts on the next PIT clock
}

bool pit_oneshot_done() { return io::inb(PORT_B) & PORT_B_OUT2; }

uint64_t calibrate_tsc_hz() {
    pit_oneshot_start(CALIBRATION_COUNT);
    uint64_t t0 = rdtsc();
    // bounded: 50 ms is far below 2^26 port reads on any machine or emulator
    for (uint32_t spins = 0; !pit_oneshot_done(); ++spins)
        if (spins > (1u << 26)) return 0;
    uint64_t t1 = rdtsc();
    return (t1 - t0) * PIT_HZ / CALIBRATION_COUNT;
}

bool wait_ms_or(uint32_t ms, bool (*stop)(void* ctx), void* ctx) {
    for (uint32_t i = 0; i < ms; ++i) {
        pit_oneshot_start(PIT_TICKS_PER_MS);
        for (uint32_t spins = 0; !pit_oneshot_done(); ++spins) {
            if (stop(ctx)) return true;
            if (spins > (1u << 22)) break;  // a PIT that never fires must not hang the kernel
        }
    }
    return stop(ctx);
}

}  // namespace timer
