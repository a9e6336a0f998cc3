// The boot show: with nobody on the serial line, Mode X cycles through the test patterns.
#pragma once

#include <stdint.h>

namespace show {

// Sets Mode X and shows each pattern for `interval_ms`, drawing into the back page and flipping.
// Returns as soon as a byte arrives on COM1 (the byte stays unread: it starts the first command).
void run(uint32_t interval_ms);

}  // namespace show
