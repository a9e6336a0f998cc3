// COM1 16550 driver: divisor 1 (115200 baud), 8N1, FIFOs cleared with a 14-byte trigger, polling only.
#include "drivers/serial.h"

#include "drivers/io.h"

namespace serial {

namespace {

constexpr uint16_t COM1 = 0x3F8;
constexpr uint16_t DATA = COM1 + 0;     // RBR/THR; DLL when DLAB=1
constexpr uint16_t IER = COM1 + 1;      // DLM when DLAB=1
constexpr uint16_t FCR = COM1 + 2;
constexpr uint16_t LCR = COM1 + 3;
constexpr uint16_t MCR = COM1 + 4;
constexpr uint16_t LSR = COM1 + 5;
constexpr uint16_t SCRATCH = COM1 + 7;

constexpr uint8_t LCR_DLAB = 0x80;
constexpr uint8_t LCR_8N1 = 0x03;
constexpr uint8_t FCR_ENABLE_CLEAR_TRIGGER14 = 0xC7;
constexpr uint8_t MCR_DTR_RTS_OUT2 = 0x0B;
constexpr uint8_t LSR_DATA_READY = 0x01;
constexpr uint8_t LSR_THR_EMPTY = 0x20;
constexpr uint8_t LSR_TRANSMITTER_EMPTY = 0x40;

bool g_present = false;
bool g_at_line_start = true;

void put(char c) {
    // bounded: a UART that never drains must not hang the kernel (about 1 s of polling at ISA speed)
    for (uint32_t spins = 0; !(io::inb(LSR) & LSR_THR_EMPTY); ++spins)
        if (spins > 1000000) return;
    io::outb(DATA, uint8_t(c));
}

void sink_write(void*, const char* data, size_t n) { write(data, n); }

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
    io::outb(MCR, MCR_DTR_RTS_OUT2);
    return g_present = true;
}

bool present() { return g_present; }

void write(const char* data, size_t n) {
    if (!g_present) return;
    for (size_t i = 0; i < n; ++i) put(data[i]);
    if (n) g_at_line_start = data[n - 1] == '\n';
}

void write(const char* s) {
    size_t n = 0;
    while (s[n]) ++n;
    write(s, n);
}

void flush() {
    if (!g_present) return;
    for (uint32_t spins = 0; !(io::inb(LSR) & LSR_TRANSMITTER_EMPTY); ++spins)
        if (spins > 1000000) return;
}

bool at_line_start() { return g_at_line_start; }

bool byte_ready() { return g_present && (io::inb(LSR) & LSR_DATA_READY); }

uint8_t read_byte() {
    while (!byte_ready()) {
    }
    return io::inb(DATA);
}

lib::Sink sink() { return lib::Sink{sink_write, nullptr}; }

}  // namespace serial
