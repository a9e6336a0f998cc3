// The on-screen bench: every mapper on every 3D scene, timed on the machine itself with the TSC
// (calibrated against the PIT), ending in pages a person reads on the screen: the machine, the trade
// table a scene at a time (cycles a pixel for the inner loops and the whole frame, and the footprint
// error make bench measured for the same frames), then the run's CSV as QR codes, to carry away
// with a phone. The same rows go to COM1 as JSON events (docs/protocol.md).
#pragma once

#include <stdint.h>

#include "drivers/cpu.h"
#include "kernel/lib/keys.h"

namespace onscreen {

// The frames a scene and mapper when the show's key starts it: the same as make bench's, so the
// errors it measured are those of these frames.
constexpr uint32_t DEFAULT_FRAMES = 8;

struct Setup {
    const int* scenes = nullptr;  // file indices of the 3D scenes, in order
    int scene_count = 0;
    uint32_t frames = DEFAULT_FRAMES;  // a scene and mapper, spread evenly over its animation
    const cpu::Info* cpu = nullptr;
};

// The next key pressed (Key::None: none waiting).
using NextKey = lib::Key (*)(void* ctx);

// Runs the bench, then shows its pages until Escape (or B) goes back; Escape during the run stops
// it there. False when a byte on COM1 ended it (the show gives way to the server). The current 3D
// scene is whichever was benched last.
bool run(const Setup& s, NextKey next_key, void* ctx);

}  // namespace onscreen
