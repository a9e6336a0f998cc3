// The boot show: with nobody on the serial line, Mode X plays the 3D scenes the kernel has (built
// in or loaded as modules), each through its animation, scene after scene; without any, it cycles
// through the test patterns. A person at the PC drives it from the keyboard (lib/keys.h: scene,
// mapper, budget, pause and single frames, the surface, the HUD of figures, the help) and reads
// the figures on the screen; each key is reported on COM1 as a `key` event (docs/protocol.md).
#pragma once

#include <stdint.h>

#include "drivers/cpu.h"
#include "kernel/lib/words.h"

namespace show {

struct Options {
    uint32_t interval_ms = 2000;  // the patterns': each shown this long
    bool patterns = false;        // the test patterns, not the scenes
    lib::StrView scene;           // start with this scene file (and stay on it)
    lib::StrView mapper;          // draw with this mapper (default: auto)
    const cpu::Info* cpu = nullptr;  // for the on-screen bench's machine page
    uint32_t bench_frames = 0;    // run the on-screen bench first, this many frames a row (0: not)
};

// Sets Mode X and plays (after the on-screen bench, kernel/show/onscreen.h, when `bench_frames` asks;
// over the scene given, else every 3D scene): every 3D scene file, or only `scene` when it is given (until a key picks
// another), drawn into the back page, flipped on the retrace, the HUD over it. With `patterns` (or
// without any 3D scene, or a `scene` that is not there) the test patterns instead. Returns as soon as
// a byte arrives on COM1 (the byte stays unread: it starts the first command).
void run(const Options& o);

}  // namespace show
