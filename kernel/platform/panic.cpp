// panic (panic.h).
#include "kernel/platform/panic.h"

#include "drivers/debug_exit.h"
#include "drivers/serial.h"
#include "drivers/vga.h"
#include "kernel/lib/json.h"

void panic(const char* message) {
    lib::JsonLine(serial::sink()).str("event", "panic").str("error", message).end();
    serial::flush();
    vga::text_write("modexlab panic: ");
    vga::text_write(message);
    vga::text_write("\n");
    debug_exit::exit(debug_exit::PANIC);
    for (;;) asm volatile("cli; hlt");
}
