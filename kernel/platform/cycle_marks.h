// Where the bench marks its laps, its frames and its rows for the timing model's QEMU plugin
// (docs/cycles.md, "Whole frames"). The plugin sees which byte is written, not the value: each
// byte is an event (timing::Machine::Mark names them). Writing one costs a store; nothing reads it.
#pragma once

#include <stdint.h>

namespace cycle_marks {

// The bench probe's laps and start (kernel/core/probe.h) are the first bytes; then these.
enum Event : uint8_t { FrameStart = 10, FrameEnd = 11, RowEnd = 12, Count = 13 };

}  // namespace cycle_marks

extern "C" volatile uint8_t modexlab_cycle_marks[cycle_marks::Count];

namespace cycle_marks {

inline void mark(Event e) { modexlab_cycle_marks[e] = 1; }

}  // namespace cycle_marks
