// The command server on COM1: one ASCII command per line in, one JSON reply line out (docs/protocol.md).
#pragma once

#include <stdint.h>

#include "drivers/cpu.h"
#include "kernel/scene/palette.h"

namespace server {

struct Context {
    const char* cmdline = "";
    cpu::Info cpu;
    raster::PaletteId palette = raster::PaletteId::Default;
};

[[noreturn]] void run(Context& ctx);

// Whether a line has begun on COM1 (or Ctrl-C came): what stops long work, the boot show and the
// on-screen bench. The bytes waiting are taken into the line run() reads next, but for the LF that
// ends a CR LF, which stops nothing.
bool line_arrived();

}  // namespace server
