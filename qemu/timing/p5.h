// The P5 Pentium's (non-MMX) integer timing, from its documented rules (docs/cycles.md, "The
// Pentium"): two pipes, U and V, an instruction pairing with the next by its class (UV, PU, PV, NP)
// where neither writes what the other reads or writes (flags into a branch, and two flag writers,
// excepted); a pair in lockstep; the AGI (a register written in the cycle before or the same cycle
// cannot address memory); prefixes alone in U; data-cache bank conflicts where they can be told
// from the code; a branch target buffer of two-bit counters. The x87 is not modelled yet.
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
    std::vector<std::string> stalls;
};

// An instruction of a run and whether it, a branch, went to its target.
struct Executed {
    const Insn* insn;
    bool taken;
};

class P5 {
public:
    // Runs the whole stream (its lookahead: an instruction pairs with the next) and returns each
    // instruction's issue.
    std::vector<P5Issue> run(const std::vector<Executed>& stream);

    static Pairing pairing(const Insn& in);
    static int clocks(const Insn& in);  // in the U pipe, alone; docs/cycles.md's table
};

}  // namespace timing
