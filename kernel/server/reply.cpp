// The reply sequence counter.
#include "kernel/server/reply.h"

#include "drivers/serial.h"

namespace reply {

namespace {
uint32_t g_seq = 0;
}

lib::JsonLine begin(bool ok) {
    if (!serial::at_line_start()) serial::write("\n");  // never glue a reply to a line cut short (a fault mid-reply)
    lib::JsonLine line(serial::sink());
    line.u32("seq", ++g_seq).boolean("ok", ok);
    return line;
}

void error(const char* cmd, const char* message) { begin(false).str("cmd", cmd).str("error", message).end(); }

}  // namespace reply
