// The kernel's last word on a state it cannot go on from: a `panic` event on COM1, a text-mode
// line, and QEMU's exit with status PANIC (docs/protocol.md, "Exit statuses").
#pragma once

#include "kernel/lib/fmt.h"

[[noreturn]] void panic(const char* message);
