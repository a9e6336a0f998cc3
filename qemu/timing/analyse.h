// The static analyser (docs/cycles.md): a loop body (a listing's instructions, one iteration) run
// through a CPU model to a steady state, its data-dependent branches going as asked, with a
// diagram of one iteration and the cycles an iteration takes.
#pragma once

#include <string>
#include <vector>

#include "qemu/timing/i486.h"
#include "qemu/timing/insn.h"

namespace timing {

enum class Cpu { I486, Pentium };

// How the body's data-dependent branches go (a forward conditional jump inside the body; the jump
// back to the body's top, where there is one, is the loop's own and always taken): all taken, none,
// taken and not taken by turns, each taken with probability `share` (the expected cycles), or each
// as `pattern` says, one letter a branch in the body's order ('t' taken, 'n' not).
struct BranchPolicy {
    enum Kind { Taken, NotTaken, Alternate, Share, Pattern } kind = Taken;
    double share = 1;
    std::string pattern;
    std::string name() const;
    // Taken, NotTaken, Pattern: the one path every iteration takes (bit k: branch k taken) of
    // `count` branches; throws for a pattern of another length
    unsigned path(int count) const;
};

// One instruction of the diagram: where it issued on the path shown (cycle -1: not run on it).
struct Line {
    std::string text;
    long cycle = -1;
    int clocks = 0;
    std::vector<std::string> stalls;
    char pipe = 0;  // the Pentium's: 'U' or 'V'
};

struct Report {
    std::vector<Line> lines;        // the diagram's iteration (for Share and Alternate: all taken)
    double cycles_per_iteration = 0;
    int data_branches = 0;          // data-dependent branches in the body
    bool loop_branch = false;       // the body ends with its jump back to the top
    int exits = 0;                  // conditional jumps out of the body: not taken while the loop runs
};

struct Options {
    int precision = 64;  // the x87's precision control in force (24, 53, 64 bits): the Pentium's FDIV
    // straight-line code run once from an idle machine, its figure the cycles until the last
    // instruction completes (a result's latency included), not a loop's steady state
    bool once = false;
};

// Throws std::runtime_error for an instruction the model has no timing for, or a body it cannot
// run (empty; a JMP out of it; more than 16 data-dependent branches).
Report analyse(const std::vector<Insn>& body, Cpu cpu, Mode mode, const BranchPolicy& branch, const Options& options = {});

// The diagram (a line an instruction: its cycle, clocks, stalls) and its last lines: "cycles per
// iteration: X" and, for pixels > 1, "cycles per pixel: X / pixels".
std::string diagram(const Report& r, int pixels);
std::string json(const Report& r, int pixels, const std::string& cpu, const std::string& branch);

}  // namespace timing
