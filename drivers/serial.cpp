// COM1 16550 driver: divisor 1 (115200 baud), 8N1, FIFOs on; polled, but a reader waiting for a byte
// halts until the UART's IRQ 4 where that interrupt is seen to arrive.
#include "drivers/serial.h"

#include "drivers/io.h"
#include "drivers/pic.h"
#include "drivers/timer.h"

namespace serial {

namespace {

constexpr uint16_t COM1 = 0x3F8;
constexpr uint16_t DATA = COM1 + 0;     // RBR/THR; DLL when DLAB=1
constexpr uint16_t IER = COM1 + 1;      // DLM when DLAB=1
constexpr uint16_t FCR = COM1 + 2;     // written; read, the same port is IIR
constexpr uint16_t IIR = COM1 + 2;
constexpr uint16_t LCR = COM1 + 3;
constexpr uint16_t MCR = COM1 + 4;
constexpr uint16_t LSR = COM1 + 5;
constexpr uint16_t SCRATCH = COM1 + 7;

constexpr uint8_t LCR_DLAB = 0x80;
constexpr uint8_t LCR_8N1 = 0x03;
// FIFOs on and cleared, the receiver's interrupt at 14 bytes or after 4 characters' time without one:
// QEMU hands the guest as many bytes at once as the trigger level (at 1, a byte at a time)
constexpr uint8_t FCR_ENABLE_CLEAR_TRIGGER14 = 0xC7;
constexpr uint8_t IER_RECEIVED_DATA = 0x01, IER_THR_EMPTY = 0x02;
constexpr uint8_t IIR_FIFOS_ON = 0xC0;  // both bits: a 16550A's working FIFOs
constexpr uint8_t MCR_DTR_RTS_OUT2 = 0x0B;
constexpr uint8_t LSR_DATA_READY = 0x01;
constexpr uint8_t LSR_THR_EMPTY = 0x20;
constexpr uint8_t LSR_TRANSMITTER_EMPTY = 0x40;

bool g_present = false;
bool g_at_line_start = true;
bool g_crlf = false;  // each LF written goes out as CR LF
bool g_stalled = false;

// How long a byte waits for the transmitter. A 16550 at 115200 baud drains its FIFO in 1.4 ms, but
// under QEMU the host's back-pressure reaches the guest: while the client is not reading, the
// socket is full, the byte waits in the transmitter and THRE stays clear, for as long as the client
// stalls. Giving up early loses a byte from the middle of a reply (docs/platform.md, "Measured in
// QEMU 7.2"). So the wait is bounded only against a UART that never drains: 2^28 polls, ~20 s under
// QEMU TCG, minutes on a PC. After such a timeout the port counts as stalled: bytes are dropped
// without waiting until THRE shows again.
constexpr uint32_t DRAIN_POLLS = 1u << 28;

bool wait_lsr(uint8_t bit) {
    if (g_stalled) {
        if (!(io::inb(LSR) & bit)) return false;
        g_stalled = false;
        return true;
    }
    for (uint32_t polls = 0; !(io::inb(LSR) & bit); ++polls)
        if (polls == DRAIN_POLLS) {
            g_stalled = true;
            return false;
        }
    return true;
}

// THRE says the transmit FIFO is empty: so many bytes may follow before THRE is asked again (16 on
// a 16550A with its FIFO on, 1 on an 8250 or a 16450). Half the port reads of a byte at a time.
uint32_t g_fifo_depth = 1;
uint32_t g_fifo_room = 0;

void put(char c) {
    if (g_fifo_room == 0) {
        if (!wait_lsr(LSR_THR_EMPTY)) return;
        g_fifo_room = g_fifo_depth;
    }
    io::outb(DATA, uint8_t(c));
    --g_fifo_room;
}

void sink_write(void*, const char* data, size_t n) { write(data, n); }

// Waiting for a byte. The UART raises IRQ 4 when bytes come (IER, only while waiting, so that
// uploads and drawing take no interrupts: 14 bytes, or 4 characters' time after the last), and the
// CPU halts until then instead of polling the line status: an idle kernel costs nothing (a QEMU
// beside its tests, a PC's power). It halts only where enable_wakeup saw an IRQ 4 arrive; where
// none comes (no PIC, OUT2 not wired to the bus, interrupts off) it polls.
constexpr uint32_t IRQ = 4;
constexpr uint32_t WAKEUP_TEST_MS = 20;
volatile uint32_t g_irqs = 0;
bool g_wakes = false;

bool interrupts_on() {
    uint32_t flags;
    asm volatile("pushfl; popl %0" : "=r"(flags));
    return flags & 0x200;
}

void wait_for_byte() {
    io::outb(IER, IER_RECEIVED_DATA);
    while (!byte_ready()) {
        if (!g_wakes || !interrupts_on()) continue;
        asm volatile("cli" ::: "memory");
        if (byte_ready()) {
            asm volatile("sti" ::: "memory");
            break;
        }
        asm volatile("sti; hlt" ::: "memory");  // (sti takes effect after hlt has begun: no IRQ slips between)
    }
    io::outb(IER, 0);
}

}  // namespace

bool init() {
    io::outb(SCRATCH, 0x5A);
    if (io::inb(SCRATCH) != 0x5A) return g_present = false;
    io::outb(SCRATCH, 0xA5);
    if (io::inb(SCRATCH) != 0xA5) return g_present = false;

    io::outb(IER, 0x00);                // polled: no UART interrupts
    io::outb(LCR, LCR_DLAB);
    io::outb(DATA, 1);                  // divisor 1: 115200 baud
    io::outb(IER, 0);
    io::outb(LCR, LCR_8N1);
    io::outb(FCR, FCR_ENABLE_CLEAR_TRIGGER14);
    g_fifo_depth = (io::inb(IIR) & IIR_FIFOS_ON) == IIR_FIFOS_ON ? 16 : 1;
    g_fifo_room = 0;
    io::outb(MCR, MCR_DTR_RTS_OUT2);
    return g_present = true;
}

bool present() { return g_present; }

void write(const char* data, size_t n) {
    if (!g_present) return;
    for (size_t i = 0; i < n; ++i) {
        if (data[i] == '\n' && g_crlf) put('\r');
        put(data[i]);
    }
    if (n) g_at_line_start = data[n - 1] == '\n';
}

void end_lines_with_crlf(bool crlf) { g_crlf = crlf; }

void write(const char* s) {
    size_t n = 0;
    while (s[n]) ++n;
    write(s, n);
}

void flush() {
    if (g_present) wait_lsr(LSR_TRANSMITTER_EMPTY);
}

bool at_line_start() { return g_at_line_start; }

bool byte_ready() { return g_present && (io::inb(LSR) & LSR_DATA_READY); }

// The path from the UART to the CPU tested once: a transmitter-empty interrupt is raised at once
// where the transmitter is idle, and must arrive within WAKEUP_TEST_MS.
void enable_wakeup() {
    if (!g_present || !interrupts_on()) return;
    pic::unmask(IRQ);
    flush();
    io::outb(IER, IER_THR_EMPTY);
    timer::wait_ms_or(WAKEUP_TEST_MS, [](void*) { return g_irqs != 0; }, nullptr);
    io::outb(IER, 0);
    g_wakes = g_irqs != 0;
}

bool wakes() { return g_wakes; }

void on_irq() { g_irqs = g_irqs + 1; }

uint8_t read_byte() {
    if (!byte_ready()) wait_for_byte();
    return io::inb(DATA);
}

lib::Sink sink() { return lib::Sink{sink_write, nullptr}; }

}  // namespace serial
