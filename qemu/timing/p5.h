// The P5 Pentium's (non-MMX) integer timing, from its documented rules (docs/cycles.md, "The
// Pentium"): two pipes, U and V, an instruction pairing with the next by its class (UV, PU, PV, NP)
// where neither writes what the other reads or writes (flags into a branch, and two flag writers,
// excepted); a pair in lockstep; the AGI (a register written in the cycle before or the same cycle
// cannot address memory); prefixes alone in U; data-cache bank conflicts where they can be told
// from the code; a branch target buffer of two-bit counters. The x87: FLD, FADD, FMUL pipelined
// (a result 3 cycles on, an FMUL every other cycle), FXCH paired with the FP instruction before it
// and free, FDIV by the precision control and overlapped by integer work, FST a cycle later after
// arithmetic.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "qemu/timing/i486.h"
#include "qemu/timing/insn.h"

namespace timing {

enum class Pairing { UV, PU, PV, NP };

// One instruction of a run as the P5 issued it.
struct P5Issue {
    long cycle = 0;   // the cycle it issued in (from 0), after its stalls (named in `stalls`)
    char pipe = 'U';
    int clocks = 0;   // its pair's clocks (lockstep), a bank conflict's or a misprediction's included
    long done = 0;    // the cycle it completes in (an x87 result's latency included)
    std::vector<std::string> stalls;
};

// An instruction of a run and whether it, a branch, went to its target.
struct Executed {
    const Insn* insn;
    bool taken;
};

// An x87 instruction on the P5: the cycles it holds the U pipe (integer work waits that long), its
// result's latency, and when the FPU takes its next instruction (from its issue).
struct FpCycles {
    int issue = 1;
    int latency = 1;
    int next = 1;
};

class P5 {
public:
    // precision: the x87's precision control in force (24, 53 or 64 bits), which FDIV's time follows;
    // mode: OUT's and IN's time follows it
    explicit P5(int precision = 64, Mode mode = Mode::Protected32) : precision_(precision), mode_(mode) {}

    // Runs the whole stream (its lookahead: an instruction pairs with the next) and returns each
    // instruction's issue.
    std::vector<P5Issue> run(const std::vector<Executed>& stream);

    static Pairing pairing(const Insn& in);
    static int clocks(const Insn& in, Mode mode);  // in the U pipe, alone; docs/cycles.md's table
    static FpCycles fpu_cycles(const Insn& in, int precision);

private:
    int precision_;
    Mode mode_;
};

}  // namespace timing
