// Reply lines on COM1: every reply is one JSON line that starts with "seq" (counting from 1) and "ok".
#pragma once

#include "kernel/lib/json.h"

namespace reply {

// Starts the next reply: {"seq":N,"ok":ok  -- the caller adds fields and calls end().
lib::JsonLine begin(bool ok);

// A complete error reply for command `cmd`.
void error(const char* cmd, const char* message);

// Whether pool buffers whose footprints add up to `footprints` can still be taken
// (kernel/platform/guard.h); false, with `cmd`'s error reply naming `what` and the room, where
// they cannot. For what a command takes at its first use and keeps: the scene loaded may have the room.
bool room_for(size_t footprints, const char* cmd, const char* what);

}  // namespace reply
