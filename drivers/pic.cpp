// 8259 initialisation: ICW1..ICW4 with vector bases 0x20/0x28, then every IRQ masked.
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
