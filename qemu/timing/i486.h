// The i486's timing, from its documented rules (docs/cycles.md, "The 486"): each instruction's
// clocks with its code and data in the cache, and the penalties Abrash measured and Intel
// documents: prefixes, an immediate with a displacement, indexed addressing, the address
// generation interlock (AGI), the byte-register rules, taken branches and their targets.
// An in-order machine: one instruction at a time, each starting when the one before it ends.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "qemu/timing/insn.h"

namespace timing {

// Real mode (a `bits 16` listing, as the Black Book's were measured) or 32-bit protected mode at
// ring 0 (the kernel's).
enum class Mode { Real16, Protected32 };

// One instruction as the model ran it: the cycle it started in (from 0), the clocks it took in all,
// and each penalty in them, named ("AGI on esi +1").
struct Step {
    long start = 0;
    int clocks = 0;
    std::vector<std::string> stalls;
    long done = 0;  // the cycle it completes in: an x87 instruction's result later than `clocks` says
};

// An x87 instruction's clocks on the 486, and how many of them the integer unit may run on beside
// it (the manual's "concurrent execution").
struct FpClocks {
    int clocks = 0;
    int concurrent = 0;
};

class I486 {
public:
    explicit I486(Mode mode) : mode_(mode) { last_write_.fill(NEVER), last_byte_write_.fill(NEVER); }

    // Runs `in` (`taken`: the branch it is goes to its target) and returns what it cost.
    Step run(const Insn& in, bool taken);
    long now() const { return now_; }  // the cycle the next instruction may start in
    void explain(bool on) { explain_ = on; }  // name the stalls (the default), or only count them

    // The instruction's own clocks, penalties aside (docs/cycles.md's table, with each row's source).
    static int base_clocks(const Insn& in, bool taken, Mode mode);
    static FpClocks fpu_clocks(const Insn& in);

private:
    const Memo& facts(const Insn& in) const;

    static constexpr long NEVER = -1000;
    Mode mode_;
    bool explain_ = true;
    long now_ = 0;
    long fpu_free_ = 0;         // the cycle the x87 takes its next instruction in
    int last_clocks_ = 1;       // the instruction before's clocks (a prefix decodes under its extra ones)
    // per register family: the last cycle of the instruction that last wrote it, and of the last
    // that wrote one of its bytes alone (AL, AH, ...)
    std::array<long, size_t(Family::Count)> last_write_, last_byte_write_;
    long last_byte_dest_ = NEVER, byte_dest_before_ = NEVER;  // the last two instructions with a byte register destination
    uint8_t last_byte_bytes_[size_t(Family::Count)] = {};    // which byte the last byte write wrote
};

}  // namespace timing
