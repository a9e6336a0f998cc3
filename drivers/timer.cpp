// The clock (TSC, or PIT channel 0 with IRQ 0 counting its wraps), PIT channel 2 one-shots (gated
// through port 0x61, speaker off) and the TSC's calibration.
#include "drivers/timer.h"

#include "drivers/io.h"
#include "drivers/pic.h"

namespace timer {

namespace detail {
bool g_tsc = false;
}

namespace {

constexpr uint16_t PIT_CH0_DATA = 0x40;
constexpr uint16_t PIT_CH2_DATA = 0x42;
constexpr uint16_t PIT_COMMAND = 0x43;
constexpr uint16_t PORT_B = 0x61;              // bit 0: channel 2 gate, bit 1: speaker, bit 5: OUT2
constexpr uint8_t PIT_CH0_LOHI_MODE2 = 0x34;   // channel 0, lobyte/hibyte, mode 2 (rate generator), binary
constexpr uint8_t PIT_CH0_LATCH = 0x00;
constexpr uint8_t PIT_CH2_LOHI_MODE0 = 0xB0;   // channel 2, lobyte/hibyte, mode 0, binary
constexpr uint8_t PORT_B_GATE2 = 0x01;
constexpr uint8_t PORT_B_SPEAKER = 0x02;
constexpr uint8_t PORT_B_OUT2 = 0x20;
constexpr uint32_t PIT_PERIOD = 65536;         // channel 0's reload (written as 0)

constexpr uint16_t CALIBRATION_COUNT = 59659;  // 50.0 ms at 1193182 Hz
constexpr uint32_t PIT_TICKS_PER_MS = 1193;    // 0.99985 ms
constexpr int COST_READS = 64;

volatile uint32_t g_wraps = 0;  // channel 0's periods, counted by IRQ 0
uint64_t g_last = 0;            // the PIT clock's last value (it never goes back)
Clock g_clock = Clock::Tsc;
uint64_t g_tsc_hz = 0;
uint64_t g_cpu_hz = 0;
uint32_t g_read_cost = 0;

// Counts TSC ticks over a PIT one-shot of about 50 ms; 0 when the PIT never fired.
uint64_t calibrate_tsc_hz() {
    pit_oneshot_start(CALIBRATION_COUNT);
    uint64_t t0 = detail::rdtsc();
    // bounded: 50 ms is far below 2^26 port reads on any machine or emulator
    for (uint32_t spins = 0; !pit_oneshot_done(); ++spins)
        if (spins > (1u << 26)) return 0;
    uint64_t t1 = detail::rdtsc();
    return (t1 - t0) * PIT_HZ / CALIBRATION_COUNT;
}

// The 486's clock: 2^20 iterations of DEC and a taken JNZ (4 clocks each on a 486) timed by the
// PIT clock; 0 when the PIT did not move.
uint64_t measure_486_hz() {
    constexpr uint32_t ITERATIONS = 1u << 20, CLOCKS_EACH = 4;
    const uint64_t t0 = detail::pit_now();
    uint32_t n = ITERATIONS;
    asm volatile("1: decl %0\n\tjnz 1b" : "+r"(n));
    const uint64_t ticks = detail::pit_now() - t0;
    return ticks ? uint64_t(ITERATIONS) * CLOCKS_EACH * PIT_HZ / ticks : 0;
}

}  // namespace

namespace detail {

// Channel 0 latched with interrupts off; a wrap IRQ 0 has not yet counted is seen in the PIC's
// request register, and counts only if the latched count is past it (elapsed small).
uint64_t pit_now() {
    uint32_t flags;
    asm volatile("pushfl; popl %0; cli" : "=r"(flags) : : "memory");
    io::outb(PIT_COMMAND, PIT_CH0_LATCH);
    uint32_t count = io::inb(PIT_CH0_DATA);
    count |= uint32_t(io::inb(PIT_CH0_DATA)) << 8;
    uint32_t wraps = g_wraps;
    const uint32_t elapsed = (PIT_PERIOD - count) & (PIT_PERIOD - 1);
    if (elapsed < PIT_PERIOD / 2 && pic::requested(0)) ++wraps;
    uint64_t t = uint64_t(wraps) * PIT_PERIOD + elapsed;
    if (t < g_last) t = g_last;
    g_last = t;
    if (flags & 0x200) asm volatile("sti" : : : "memory");
    return t;
}

}  // namespace detail

void on_irq0() { g_wraps = g_wraps + 1; }

namespace {
uint64_t read_tsc() { return detail::rdtsc(); }
}  // namespace

Reader reader() { return g_clock == Clock::Tsc ? read_tsc : detail::pit_now; }

void init(bool has_tsc, bool is_486) {
    g_tsc_hz = has_tsc ? calibrate_tsc_hz() : 0;
    detail::g_tsc = g_tsc_hz != 0;
    g_clock = detail::g_tsc ? Clock::Tsc : Clock::Pit;
    if (g_clock == Clock::Pit) {
        io::outb(PIT_COMMAND, PIT_CH0_LOHI_MODE2);
        io::outb(PIT_CH0_DATA, 0);
        io::outb(PIT_CH0_DATA, 0);
        pic::unmask(0);
        asm volatile("sti" : : : "memory");
    }
    g_cpu_hz = g_clock == Clock::Tsc ? g_tsc_hz : is_486 ? measure_486_hz() : 0;
    // the least of a few runs of back-to-back reads (least: an interrupt only adds)
    uint64_t least = ~0ull;
    for (int run = 0; run < 4; ++run) {
        const uint64_t t0 = now();
        for (int i = 0; i < COST_READS - 1; ++i) (void)now();
        const uint64_t d = now() - t0;
        if (d < least) least = d;
    }
    g_read_cost = uint32_t(least / COST_READS);
}

Clock clock() { return g_clock; }
const char* clock_name(Clock c) { return c == Clock::Tsc ? "tsc" : "pit"; }
uint64_t hz() { return g_clock == Clock::Tsc ? g_tsc_hz : PIT_HZ; }
uint64_t tsc_hz() { return g_tsc_hz; }
uint64_t cpu_hz() { return g_cpu_hz; }
const char* cpu_hz_from() { return !g_cpu_hz ? "" : g_clock == Clock::Tsc ? "tsc" : "486 loop"; }
uint32_t read_cost() { return g_read_cost; }
// (a PIT tick is 838.0953 ns: 8380.953 tenths; in cycles, cpu_hz / PIT_HZ of them)
uint64_t tenths_shown(uint64_t ticks) {
    if (g_clock == Clock::Tsc) return ticks * 10;
    return g_cpu_hz ? uint64_t(double(ticks) * 10.0 * double(g_cpu_hz) / PIT_HZ) : ticks * 8380953 / 1000;
}
const char* unit_shown() { return g_clock == Clock::Tsc || g_cpu_hz ? "cycles" : "ns"; }

void pit_oneshot_start(uint16_t count) {
    uint8_t b = io::inb(PORT_B);
    io::outb(PORT_B, uint8_t((b & ~PORT_B_SPEAKER) | PORT_B_GATE2));
    io::outb(PIT_COMMAND, PIT_CH2_LOHI_MODE0);  // OUT2 goes low
    io::outb(PIT_CH2_DATA, uint8_t(count));
    io::outb(PIT_CH2_DATA, uint8_t(count >> 8)); // counting starts on the next PIT clock
}

bool pit_oneshot_done() { return io::inb(PORT_B) & PORT_B_OUT2; }

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
