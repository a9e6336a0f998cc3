// The PS/2 keyboard behind the 8042 controller (on most PCs today the firmware's USB legacy
// emulation of it): initialised with scan code translation on (so set 1 arrives whatever set the
// keyboard speaks), its bytes taken by the IRQ 1 handler into a ring the show reads.
#pragma once

#include <stdint.h>

namespace keyboard {

// What init found: whether a controller answered its self-test and a keyboard is enabled behind it.
struct Status {
    bool controller = false;  // the 8042 passed its self-test (0xAA -> 0x55)
    bool port_ok = false;     // its first port passed the interface test (0xAB -> 0x00)
    bool keyboard = false;    // the keyboard acknowledged "enable scanning" (0xF4 -> 0xFA)
    bool irq = false;         // IRQ 1 unmasked and interrupts on
};

// Sets up the controller and the keyboard (every wait bounded: a PC without an 8042 boots on),
// then unmasks IRQ 1 and enables interrupts. Call once, after the IDT and the PICs.
Status init();

// The next byte the keyboard sent, oldest first; false when none is waiting.
bool next_byte(uint8_t* out);

// IRQ 1: the byte in the controller's output buffer into the ring (irq_handler calls it).
void on_irq();

}  // namespace keyboard

// The IRQ handler (boot/isr.asm's stubs call it with the IRQ number, 0..15).
extern "C" void irq_handler(uint32_t irq);
