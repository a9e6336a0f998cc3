// Reply lines on COM1: every reply is one JSON line that starts with "seq" (counting from 1) and "ok".
#pragma once

#include "kernel/lib/json.h"

namespace reply {

// Starts the next reply: {"seq":N,"ok":ok  -- the caller adds fields and calls end().
lib::JsonLine begin(bool ok);

// A complete error reply for command `cmd`.
void error(const char* cmd, const char* message);

}  // namespace reply
