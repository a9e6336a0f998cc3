// The P5 Pentium's (non-MMX) timing, from its documented rules (docs/cycles.md, "The Pentium"): two
// pipes, U and V, an instruction pairing with the next by its class (UV, PU, PV, NP) where neither
// writes what the other reads or writes (flags into a branch, and two flag writers, excepted); a
// pair in lockstep; the AGI (a register written in the cycle before or the same cycle cannot
// address memory); prefixes alone in U; data-cache bank conflicts where the code shows them; a
// branch target buffer of two-bit counters, 256 entries in 64 sets of 4. The x87: FLD, FADD, FMUL
// pipelined (a result 3 cycles on, an FMUL every other cycle), FXCH paired with the FP instruction
// before it and free, FDIV by the precision control and overlapped by integer work, FST a cycle
// later after arithmetic.
#pragma once

#include <array>
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

// The x87's stack as the P5 sees it: per register, counted from the top, the cycle its value can be
// used in, and whether arithmetic made it (a store of it waits a cycle more: BB63). FXCH renames.
struct FpStack {
    std::array<long, 8> ready;
    std::array<bool, 8> arith{};
    FpStack() { ready.fill(-1000); }
    void push();
    void pop(int n);
};

class P5 {
public:
    // precision: the x87's precision control in force (24, 53 or 64 bits), which FDIV's time follows;
    // mode: OUT's and IN's time follows it
    explicit P5(int precision = 64, Mode mode = Mode::Protected32) : precision_(precision), mode_(mode) {}

    // Runs the whole stream (its lookahead: an instruction pairs with the next) and returns each
    // instruction's issue.
    std::vector<P5Issue> run(const std::vector<Executed>& stream);

    // A stream a piece at a time: issues window[0] (and window[1] where it pairs with it in V),
    // `n` (1 to 3) instructions being known from there on; returns how many issued, their issues in
    // `out`. run() is this over its stream.
    int issue(const Executed* window, size_t n, P5Issue* out);
    long now() const { return now_; }  // the cycle the next instruction may issue in
    void explain(bool on) { explain_ = on; }  // name the stalls (the default), or only count them

    static Pairing pairing(const Insn& in);
    static int clocks(const Insn& in, Mode mode);  // in the U pipe, alone; docs/cycles.md's table
    static FpCycles fpu_cycles(const Insn& in, int precision);

private:
    const Memo& facts(const Insn& in) const;
    FpCycles fp(const Insn& in) const;
    struct BtbEntry {
        uint32_t address = 0;
        int8_t counter = 0;  // two bits: taken predicted from 2 up
        bool used = false;
        uint64_t last_use = 0;
    };
    BtbEntry* btb_find(uint32_t address);
    bool predicted(const Insn& in);
    void learn(const Insn& in, bool taken);
    long address_ready(const Insn& in, Family* on) const;
    int branch_clocks(const Insn& in, bool taken, char pipe, P5Issue* issue);
    long x87_ready(const Insn& in, std::string* why) const;
    long x87_issue(const Insn& in, long start);
    void stall(P5Issue* issue, const char* what, long cycles) const;

    int precision_;
    Mode mode_;
    bool explain_ = true;
    long now_ = 0;
    std::array<long, size_t(Family::Count)> written_ = filled(-1000);  // the cycle a write of each family ended in
    std::array<BtbEntry, 256> btb_{};  // 64 sets of 4 ways
    uint64_t btb_clock_ = 0;
    // the x87: its stack, when it takes its next instruction, its next FMUL, the end of a divide,
    // and the compare FNSTSW waits for
    FpStack st_;
    long fp_next_ = -1000, fmul_next_ = -1000, divide_done_ = -1000, status_ready_ = -1000;

    static std::array<long, size_t(Family::Count)> filled(long v) {
        std::array<long, size_t(Family::Count)> a;
        a.fill(v);
        return a;
    }
};

}  // namespace timing
