// The reply sequence counter.
#include "kernel/server/reply.h"

#include "drivers/serial.h"
#include "kernel/lib/fmt.h"
#include "kernel/platform/guard.h"

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

bool room_for(size_t footprints, const char* cmd, const char* what) {
    const size_t room = guard::transient_room();
    if (footprints <= room) return true;
    lib::Fmt m;
    m.s("not enough memory for ").s(what).s(": ").u(uint32_t((footprints + 1023) >> 10)).s(" KiB needed, ");
    m.u(uint32_t(room >> 10)).s(" KiB free (load a smaller scene first; docs/platform.md, Memory)");
    error(cmd, m.c_str());
    return false;
}

}  // namespace reply
