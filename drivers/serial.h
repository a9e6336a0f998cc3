// 16550 UART on COM1, 115200 8N1, FIFOs on, polled send and receive.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/lib/sink.h"

namespace serial {

// Programs COM1; false (and every later call a no-op) when no UART answers at 0x3F8.
bool init();
bool present();

void write(const char* data, size_t n);
void write(const char* s);
// From now on every LF written goes out as CR LF (a terminal's line end), or as LF alone.
void end_lines_with_crlf(bool crlf);

// Waits (bounded) until the transmitter has sent every byte: before an exit, so no reply is cut off.
void flush();
// True when nothing has been written yet or the last byte written was a newline.
bool at_line_start();

bool byte_ready();
uint8_t read_byte();  // waits for a byte (halted, where IRQ 4 wakes the CPU: serial.cpp)

// Lets IRQ 4 through the PIC (once the PICs are remapped and interrupts are on) and checks that it
// arrives: then read_byte waits halted (wakes()). The IRQ handler calls on_irq.
void enable_wakeup();
bool wakes();
void on_irq();

lib::Sink sink();

}  // namespace serial
