// 8259 initialisation: ICW1..ICW4 with vector bases 0x20/0x28, then every IRQ masked; unmasking, EOI.
#include "drivers/pic.h"

#include "drivers/io.h"

namespace pic {

void remap_and_mask() {
    constexpr uint16_t MASTER_CMD = 0x20, MASTER_DATA = 0x21, SLAVE_CMD = 0xA0, SLAVE_DATA = 0xA1;
    io::outb(MASTER_CMD, 0x11);  // ICW1: edge, cascade, ICW4 follows
    io::wait();
    io::outb(SLAVE_CMD, 0x11);
    io::wait();
    io::outb(MASTER_DATA, 0x20); // ICW2: IRQ0-7 -> vectors 0x20-0x27 (not 8-15: those are exceptions)
    io::wait();
    io::outb(SLAVE_DATA, 0x28);  // IRQ8-15 -> 0x28-0x2F
    io::wait();
    io::outb(MASTER_DATA, 0x04); // ICW3: slave on IRQ2
    io::wait();
    io::outb(SLAVE_DATA, 0x02);
    io::wait();
    io::outb(MASTER_DATA, 0x01); // ICW4: 8086 mode
    io::wait();
    io::outb(SLAVE_DATA, 0x01);
    io::wait();
    io::outb(MASTER_DATA, 0xFF); // mask everything
    io::outb(SLAVE_DATA, 0xFF);
}

}  // namespace pic

namespace pic {

void unmask(uint32_t irq) {
    if (irq >= 16) return;
    if (irq >= 8) unmask(2);  // the cascade
    const uint16_t port = irq < 8 ? 0x21 : 0xA1;
    io::outb(port, uint8_t(io::inb(port) & ~(1u << (irq & 7))));
}

bool in_service(uint32_t irq) {
    const uint16_t port = irq < 8 ? 0x20 : 0xA0;
    io::outb(port, 0x0B);  // OCW3: the next read is the in-service register
    const uint8_t isr = io::inb(port);
    io::outb(port, 0x0A);  // back to the interrupt request register
    return isr & (1u << (irq & 7));
}

bool requested(uint32_t irq) {
    return io::inb(irq < 8 ? 0x20 : 0xA0) & (1u << (irq & 7));  // (OCW3 left reading the IRR)
}

void end_of_interrupt(uint32_t irq) {
    if (irq >= 8) io::outb(0xA0, 0x20);
    io::outb(0x20, 0x20);
}

}  // namespace pic
