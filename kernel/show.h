// The boot show: with nobody on the serial line, Mode X plays the 3D scenes the kernel has (built
// in or loaded as modules), each through its animation, scene after scene; without any, it cycles
// through the test patterns.
#pragma once

#include <stdint.h>

#include "kernel/lib/words.h"

namespace show {

// Sets Mode X and plays: every 3D scene file, or only `scene` when it is not empty, drawn with
// `mapper` (default persp-subdiv-16), into the back page, flipped on the retrace. With `patterns`
// (or without any 3D scene, or a `scene` that is not there) the test patterns instead, each for
// `interval_ms`. Returns as soon as a byte arrives on COM1 (the byte stays unread: it starts the
// first command).
void run(uint32_t interval_ms, bool patterns, lib::StrView scene, lib::StrView mapper);

}  // namespace show
