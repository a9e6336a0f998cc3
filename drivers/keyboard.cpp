// 8042 set-up, IRQ 1 and the byte ring (keyboard.h).
#include "drivers/keyboard.h"

#include "drivers/io.h"
#include "drivers/serial.h"
#include "drivers/pic.h"
#include "drivers/timer.h"

namespace keyboard {

namespace {

constexpr uint16_t DATA = 0x60, STATUS = 0x64, COMMAND = 0x64;
constexpr uint8_t STATUS_OUTPUT_FULL = 0x01, STATUS_INPUT_FULL = 0x02;
constexpr uint8_t CONFIG_PORT1_IRQ = 0x01, CONFIG_PORT2_IRQ = 0x02, CONFIG_PORT1_CLOCK_OFF = 0x10, CONFIG_TRANSLATE = 0x40;
constexpr uint32_t SPINS = 1u << 20;  // status reads before a wait gives up (some 1 s on real hardware)

bool wait_input_empty() {
    for (uint32_t i = 0; i < SPINS; ++i)
        if (!(io::inb(STATUS) & STATUS_INPUT_FULL)) return true;
    return false;
}

bool wait_output_full() {
    for (uint32_t i = 0; i < SPINS; ++i)
        if (io::inb(STATUS) & STATUS_OUTPUT_FULL) return true;
    return false;
}

bool command(uint8_t c) { return wait_input_empty() && (io::outb(COMMAND, c), true); }
bool write_data(uint8_t d) { return wait_input_empty() && (io::outb(DATA, d), true); }
bool read_data(uint8_t* out) { return wait_output_full() && (*out = io::inb(DATA), true); }

void flush() {
    for (int i = 0; i < 64 && (io::inb(STATUS) & STATUS_OUTPUT_FULL); ++i) (void)io::inb(DATA);
}

// A byte to the keyboard and its acknowledgement (0xFA), resent on 0xFE up to three times.
bool to_keyboard(uint8_t byte) {
    for (int attempt = 0; attempt < 3; ++attempt) {
        uint8_t reply;
        if (!write_data(byte) || !read_data(&reply)) return false;
        if (reply == 0xFA) return true;
        if (reply != 0xFE) return false;
    }
    return false;
}

// The ring: the IRQ handler writes at head, the show reads at tail (one writer, one reader).
constexpr uint32_t RING = 64;
volatile uint8_t g_ring[RING];
volatile uint32_t g_head = 0, g_tail = 0;

}  // namespace

Status init() {
    Status s;
    if (io::inb(STATUS) == 0xFF) return s;  // nothing decodes the port: no controller
    command(0xAD);                          // both ports off while we set up
    command(0xA7);
    flush();
    uint8_t config = 0;
    if (!command(0x20) || !read_data(&config)) return s;
    config = uint8_t((config & ~(CONFIG_PORT1_IRQ | CONFIG_PORT2_IRQ)) | CONFIG_TRANSLATE);
    if (!command(0x60) || !write_data(config)) return s;
    uint8_t reply = 0;
    s.controller = command(0xAA) && read_data(&reply) && reply == 0x55;
    if (!s.controller) return s;
    // some controllers reset their configuration in the self-test: write it again
    if (!command(0x60) || !write_data(config)) return s;
    s.port_ok = command(0xAB) && read_data(&reply) && reply == 0x00;
    if (!s.port_ok) return s;
    command(0xAE);  // the first port on
    flush();
    // scan code set 2 (the one translation turns into set 1), then scanning on
    to_keyboard(0xF0) && to_keyboard(0x02);
    s.keyboard = to_keyboard(0xF4);
    flush();
    config = uint8_t((config | CONFIG_PORT1_IRQ | CONFIG_TRANSLATE) & ~CONFIG_PORT1_CLOCK_OFF);
    if (!command(0x60) || !write_data(config)) return s;
    pic::unmask(1);
    asm volatile("sti");
    s.irq = true;
    return s;
}

bool next_byte(uint8_t* out) {
    const uint32_t tail = g_tail;
    if (tail == g_head) return false;
    *out = g_ring[tail % RING];
    g_tail = tail + 1;
    return true;
}

void on_irq() {
    // the controller raised IRQ 1 with a byte in its output buffer
    const uint8_t byte = io::inb(DATA);
    const uint32_t head = g_head;
    if (head - g_tail >= RING) return;  // full: the show has not read them (the byte is lost)
    g_ring[head % RING] = byte;
    g_head = head + 1;
}

}  // namespace keyboard

extern "C" void irq_handler(uint32_t irq) {
    if (irq == 7 || irq == 15) {  // spurious unless the PIC's in-service register says otherwise
        if (!pic::in_service(irq)) {
            if (irq == 15) pic::end_of_interrupt(2);  // the cascade did see an interrupt
            return;
        }
    }
    if (irq == 0) timer::on_irq0();
    if (irq == 1) keyboard::on_irq();
    if (irq == 4) serial::on_irq();
    pic::end_of_interrupt(irq);
}
