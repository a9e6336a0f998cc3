// The P5 model (p5.h). Sources, by the abbreviations of docs/cycles.md: BB19, BB20, BB21, BB63
// (Abrash's Black Book: the Pentium's pipes, Tables 20.1 and 20.2, register contention, AGIs,
// prefixes, the x87); FM (Byggmastar's fatmap.txt and fatmap2.txt); P5 (Intel's Pentium table);
// AF (Agner Fog's Pentium tables) and AP-500 (Intel's application note), for the rest of the x87.
#include "qemu/timing/p5.h"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace timing {

namespace {

bool mem_operand(const Insn& in) { return in.mem.present && !in.mem.stack; }
bool accesses_memory(const Insn& in) { return mem_operand(in) && in.mnemonic != "lea"; }
bool mem_dest(const Insn& in) { return accesses_memory(in) && in.mem.write; }
// An immediate and a displacement in one instruction: it cannot pair (BB20's Tables, BB21)
bool disp_and_imm(const Insn& in) { return in.has_imm && in.mem.has_disp && mem_operand(in); }
// prefix bytes that run alone in U, a cycle each: 66h, 67h, segment, LOCK, REP, and 0Fh but on a
// conditional jump (BB19, BB20) and on the instructions whose figure is Intel's table's, which counts
// it (P5: IMUL r,r/m, MOVZX, MOVSX, SETcc)
int prefix_cycles(const Insn& in) {
    const bool counted = among(in.mnemonic, {"imul", "movzx", "movsx"}) || in.mnemonic.rfind("set", 0) == 0;
    return int(in.opsize_prefix) + int(in.addrsize_prefix) + int(in.segment_prefix) + int(in.lock_prefix) + int(in.rep_prefix) +
           int(in.two_byte_opcode && in.kind != Kind::Jcc && !counted);
}

bool arithmetic(FpOp op) {
    return op == FpOp::Add || op == FpOp::Mul || op == FpOp::Div || op == FpOp::IntAdd || op == FpOp::IntMul || op == FpOp::IntDiv || op == FpOp::Sqrt;
}
// the FP instructions FXCH pairs with, in V (BB63; AP-500)
bool pairs_with_fxch(const Insn& in) {
    const FpOp op = in.fpu.op;
    return op == FpOp::Load || op == FpOp::Add || op == FpOp::Mul || op == FpOp::Div || op == FpOp::Compare || op == FpOp::Unary;
}

}  // namespace

void FpStack::push() {
    std::rotate(ready.rbegin(), ready.rbegin() + 1, ready.rend()), std::rotate(arith.rbegin(), arith.rbegin() + 1, arith.rend());
    ready[0] = -1000, arith[0] = false;
}

void FpStack::pop(int n) {
    for (int k = 0; k < n; ++k) {
        std::rotate(ready.begin(), ready.begin() + 1, ready.end()), std::rotate(arith.begin(), arith.begin() + 1, arith.end());
        ready[7] = -1000, arith[7] = false;
    }
}

FpCycles P5::fpu_cycles(const Insn& in, int precision) {
    // BB63 where it gives the figure; AF (Agner Fog's Pentium tables) for the rest
    const int by_precision = precision <= 24 ? 0 : precision <= 53 ? 1 : 2;
    const bool mem = in.mem.present;
    switch (in.fpu.op) {
    case FpOp::Load: return {1, 1, 1};
    case FpOp::LoadExtended: return {3, 3, 3};
    case FpOp::LoadInt: return {1, 3, 1};
    case FpOp::LoadConst: return {2, 2, 2};
    case FpOp::Store: return mem ? FpCycles{2, 2, 2} : FpCycles{1, 1, 1};
    case FpOp::StoreExtended: return {3, 3, 3};
    case FpOp::StoreInt: return {6, 6, 6};
    case FpOp::Add: case FpOp::Mul: return {1, 3, 1};
    case FpOp::Div: {
        static constexpr int DIVIDE[3] = {19, 33, 39};
        return {1, DIVIDE[by_precision], DIVIDE[by_precision]};
    }
    case FpOp::IntAdd: case FpOp::IntMul: return {4, 6, 4};
    case FpOp::IntDiv: {
        static constexpr int DIVIDE[3] = {22, 36, 42};
        return {4, DIVIDE[by_precision], DIVIDE[by_precision]};
    }
    case FpOp::Compare: case FpOp::Unary: case FpOp::Wait: return {1, 1, 1};
    case FpOp::Exchange: return {1, 0, 1};
    case FpOp::Sqrt: return {1, 70, 70};
    case FpOp::LoadControl: return {7, 7, 7};
    case FpOp::StoreControl: return {2, 2, 2};
    case FpOp::StoreStatus: return {6, 6, 6};
    default: throw std::runtime_error("no Pentium timing for '" + in.text + "' (docs/cycles.md lists what the model knows)");
    }
}

Pairing P5::pairing(const Insn& in) {
    const std::string& m = in.mnemonic;
    const bool mem = mem_operand(in);
    if (in.kind == Kind::Jcc && !in.loop) return Pairing::PV;
    if (in.kind == Kind::Jmp || in.kind == Kind::Call) return Pairing::PV;
    if (disp_and_imm(in)) return Pairing::NP;
    if (among(m, {"mov", "add", "sub", "and", "or", "xor", "inc", "dec", "cmp", "lea", "nop"})) return Pairing::UV;
    if (m == "push" || m == "pop") return mem ? Pairing::NP : Pairing::UV;
    // TEST pairs with registers, or the accumulator and an immediate (BB20, Table 20.1)
    if (m == "test") {
        if (mem) return Pairing::NP;
        const bool imm = in.has_imm;
        const bool acc = std::all_of(in.reads.begin(), in.reads.end(), [](RegPart p) { return p.family == Family::A; });
        return !imm || acc ? Pairing::UV : Pairing::NP;
    }
    if (m == "adc" || m == "sbb") return Pairing::PU;
    if (among(m, {"shl", "sal", "shr", "sar"})) return !mem && (in.has_imm || in.opcode == 0xD0 || in.opcode == 0xD1) ? Pairing::PU : Pairing::NP;
    if (among(m, {"rol", "ror", "rcl", "rcr"})) return !mem && (in.opcode == 0xD0 || in.opcode == 0xD1) ? Pairing::PU : Pairing::NP;
    return Pairing::NP;
}

int P5::clocks(const Insn& in, Mode mode) {
    const std::string& m = in.mnemonic;
    const bool mem = accesses_memory(in), dest = mem_dest(in);
    if (among(m, {"mov", "lea", "nop", "neg", "not"})) return 1;  // BB20; FM (NEG: "non pairable, 1 tick")
    if (among(m, {"add", "sub", "and", "or", "xor", "adc", "sbb"})) return dest ? 3 : mem ? 2 : 1;  // BB20, Tables 20.1 and 20.2
    if (m == "cmp" || m == "test") return mem ? 2 : 1;                                           // BB20
    if (m == "inc" || m == "dec") return dest ? 3 : 1;                                           // BB19, BB20
    if (m == "push") return mem ? 2 : 1;                                                         // BB20
    if (m == "pop" && !mem) return 1;                                                            // BB20
    if (among(m, {"shl", "sal", "shr", "sar", "rol", "ror"}) && !mem) return in.opcode == 0xD2 || in.opcode == 0xD3 ? 4 : 1;  // BB20
    if ((m == "rcl" || m == "rcr") && !mem && (in.opcode == 0xD0 || in.opcode == 0xD1)) return 1;                         // BB20
    // P5 (Intel's Pentium table)
    if (among(m, {"sahf", "lahf", "cdq", "cwd"})) return 2;
    if (among(m, {"cbw", "cwde", "movzx", "movsx"}) || m.rfind("set", 0) == 0) return 3;
    // on the FPU's multiplier, unpairable
    if (m == "mul" || m == "imul") return in.operand_bytes == 4 ? 10 : 11;
    if (m == "div") return in.operand_bytes == 1 ? 17 : in.operand_bytes == 2 ? 25 : 41;
    if (m == "idiv") return in.operand_bytes == 1 ? 22 : in.operand_bytes == 2 ? 30 : 46;
    if (in.kind == Kind::Out) return mode == Mode::Real16 ? 12 : 9;  // P5: real mode; CPL at or below IOPL
    if (in.kind == Kind::In) return mode == Mode::Real16 ? 7 : 4;
    // the rest a compiled program runs; a REP string instruction's repetitions each run as an
    // instruction of their own (as QEMU executes them), a cycle each (P5: REP STOS 3+n, REP MOVS 13+n)
    if (m == "pop") return 3;  // memory
    if (m == "xchg" || m == "leave") return 3;
    if (m == "xlatb" || m == "xlat") return 4;
    if (m.rfind("stos", 0) == 0) return in.rep_prefix ? 1 : 3;
    if (m.rfind("lods", 0) == 0) return 2;
    if (m.rfind("movs", 0) == 0) return in.rep_prefix ? 1 : 4;
    if (among(m, {"cld", "std", "clc", "stc", "cmc"})) return 2;
    if (m == "cli" || m == "sti") return 7;
    if (m == "pushfd" || m == "pushf") return 4;
    if (m == "popfd" || m == "popf") return 6;
    if (among(m, {"pushal", "pushad", "popal", "popad"})) return 5;
    if (m == "bt") return 4;
    if (among(m, {"bts", "btr", "btc"})) return 7;
    if (m == "bsf" || m == "bsr") return 6;  // (6 to 34: its least)
    if (m == "shld" || m == "shrd") return 4;
    if (m == "rcl" || m == "rcr") return 7;  // by CL or an immediate (7 to 24: its least)
    if (in.kind == Kind::Ret) return in.has_imm ? 3 : 2;
    if (in.kind == Kind::Jcc && in.loop) return 5;
    if (m == "iretd" || m == "iret") return 10;
    if (m == UNMODELLED) return 1;
    if (in.kind == Kind::Jcc && !in.loop) return 1;  // predicted (BB19)
    if (in.kind == Kind::Jmp || in.kind == Kind::Call) return 1;
    throw std::runtime_error("no Pentium timing for '" + in.text + "' (docs/cycles.md lists what the model knows)");
}

// The instruction's entries in the tables, worked out once for this P5's settings (insn.h, Memo).
const Memo& P5::facts(const Insn& in) const {
    const uint32_t key = 0x50000u + uint32_t(mode_) * 128u + uint32_t(precision_);
    Memo& m = in.memo;
    if (m.key == key) return m;
    m = Memo{};
    m.key = key;
    m.pairing = int8_t(pairing(in));
    m.prefix = int8_t(prefix_cycles(in));
    m.memory = accesses_memory(in), m.memory_dest = mem_dest(in);
    m.multiplier = in.mnemonic == "imul" || in.mnemonic == "mul";
    try {
        if (in.kind == Kind::Fpu) {
            const FpCycles c = fpu_cycles(in, precision_);
            m.fp_issue = int16_t(c.issue), m.fp_latency = int16_t(c.latency), m.fp_next = int16_t(c.next);
        } else {
            m.clocks = int16_t(clocks(in, mode_));
        }
    } catch (const std::runtime_error&) {
        m.clocks = -1;
    }
    return m;
}

// the stream's copy of fpu_cycles and clocks: from the memo, or the tables' refusal
FpCycles P5::fp(const Insn& in) const {
    const Memo& m = facts(in);
    if (m.clocks < 0) fpu_cycles(in, precision_);  // (throws)
    return FpCycles{m.fp_issue, m.fp_latency, m.fp_next};
}

// The branch target buffer: 256 entries, 4-way set associative (P5, AF), the least recently used
// way replaced; a set by the branch's address bits 0-5 (the model's choice: the sources give the
// size and the ways, not the index).
P5::BtbEntry* P5::btb_find(uint32_t address) {
    BtbEntry* set = &btb_[(address & 63) * 4];
    for (int w = 0; w < 4; ++w)
        if (set[w].used && set[w].address == address) return &set[w];
    return nullptr;
}

bool P5::predicted(const Insn& in) {
    const BtbEntry* e = btb_find(in.address);
    return e && e->counter >= 2;  // (not in the buffer: not taken)
}

void P5::learn(const Insn& in, bool taken) {
    BtbEntry* e = btb_find(in.address);
    if (!e) {
        if (!taken) return;
        BtbEntry* set = &btb_[(in.address & 63) * 4];
        e = &set[0];
        for (int w = 1; w < 4; ++w)
            if (!set[w].used || (e->used && set[w].last_use < e->last_use)) e = &set[w];
        *e = BtbEntry{in.address, 3, true, 0};  // enters taken
    } else {
        e->counter = int8_t(std::clamp(e->counter + (taken ? 1 : -1), 0, 3));
    }
    e->last_use = ++btb_clock_;
}

// the cycle its address registers are ready in (written two cycles before, BB21); PUSH and POP
// address through ESP, which counts only as written explicitly (`written_` keeps no other)
long P5::address_ready(const Insn& in, Family* on) const {
    long r = -1000;
    if (!in.mem.present) return r;
    for (Family f : {in.mem.base, in.mem.index})
        if (f != Family::None && written_[size_t(f)] + 2 > r) r = written_[size_t(f)] + 2, *on = f;
    return r;
}

int P5::branch_clocks(const Insn& in, bool taken, char pipe, P5Issue* issue) {
    if (in.kind != Kind::Jcc && in.kind != Kind::Jmp && in.kind != Kind::Call) {
        const Memo& m = facts(in);
        return m.clocks >= 0 ? m.clocks : clocks(in, mode_);  // (throws)
    }
    const bool right = in.kind == Kind::Jcc ? predicted(in) == taken : btb_find(in.address) != nullptr;
    learn(in, taken || in.kind != Kind::Jcc);
    if (right) return 1;
    const int c = in.kind != Kind::Jcc ? 3 : pipe == 'U' ? 4 : 5;  // BB19, BB21
    stall(issue, "mispredicted", c - 1);
    return c;
}

void P5::stall(P5Issue* issue, const char* what, long cycles) const {
    if (explain_) issue->stalls.push_back(std::string(what) + " +" + std::to_string(cycles));
}

// The cycle the x87 lets `in` issue in, and what it waits for: the FPU's next issue, an FMUL's
// every other cycle, a divide (the next FP instruction or IMUL waits for it: BB63), its operands.
long P5::x87_ready(const Insn& in, std::string* why) const {
    long r = -1000;
    const char* name = "";
    int reg = -1;
    auto wait = [&](long t, const char* what, int k) {
        if (t > r) r = t, name = what, reg = k;
    };
    if (in.kind != Kind::Fpu) {
        if (facts(in).multiplier) wait(divide_done_, "the FDIV", -1);
    } else {
        const FpOp op = in.fpu.op;
        wait(fp_next_, divide_done_ == fp_next_ ? "the FDIV" : "the x87", -1);
        if (op == FpOp::Mul) wait(fmul_next_, "an FMUL every other cycle", -1);
        if (op == FpOp::StoreStatus) wait(status_ready_, "the compare", -1);
        const bool store = op == FpOp::Store || op == FpOp::StoreInt || op == FpOp::StoreExtended;
        if (op != FpOp::Exchange)
            for (int k = 0; k < 8; ++k)
                if ((in.fpu.reads >> k) & 1) wait(st_.ready[size_t(k)] + (store && st_.arith[size_t(k)] ? 1 : 0), "st", k);
        if (op == FpOp::Wait)
            for (long t : st_.ready) wait(t, "the x87", -1);
    }
    if (explain_ && r > -1000) *why = reg >= 0 ? "st(" + std::to_string(reg) + ")" : name;
    return r;
}

// `in` issued at `start`: the x87's state after it; the last cycle of its result
long P5::x87_issue(const Insn& in, long start) {
    const FpCycles c = fp(in);
    const FpOp op = in.fpu.op;
    if (op == FpOp::Exchange) {
        const int k = std::countr_zero(unsigned(in.fpu.reads & 0xFE));
        if (k < 8) std::swap(st_.ready[0], st_.ready[size_t(k)]), std::swap(st_.arith[0], st_.arith[size_t(k)]);
        return start;
    }
    const long result = start + c.latency;
    if (in.fpu.push) st_.push();
    if (in.fpu.dest >= 0) st_.ready[size_t(in.fpu.dest)] = result, st_.arith[size_t(in.fpu.dest)] = arithmetic(op);
    st_.pop(in.fpu.pops);
    fp_next_ = start + c.next;
    if (op == FpOp::Mul) fmul_next_ = start + 2;
    if (op == FpOp::Div || op == FpOp::IntDiv || op == FpOp::Sqrt) divide_done_ = start + c.latency;
    if (op == FpOp::Compare) status_ready_ = result;
    return result - 1;
}

int P5::issue(const Executed* window, size_t n, P5Issue* out) {
    const Insn& u = *window[0].insn;
    P5Issue& iu = out[0];
    iu.stalls.clear();
    Family agi_on = Family::None;
    const long agi_ready = address_ready(u, &agi_on);
    const Memo& fu = facts(u);
    const int prefixes = fu.prefix;
    std::string fp_why;
    const long fp_wait = std::max<long>(0, x87_ready(u, &fp_why) - now_);
    const long wait = std::max<long>(0, agi_ready - now_);
    const long start = now_ + std::max({wait, long(prefixes), fp_wait});  // (a prefix decodes while an AGI waits: BB19)
    if (explain_) {
        if (fp_wait > wait) stall(&iu, ("waits for " + fp_why).c_str(), fp_wait);
        else if (wait) stall(&iu, (std::string("AGI on ") + family_name(agi_on)).c_str(), wait);
        if (prefixes > std::max(wait, fp_wait)) stall(&iu, "prefix", prefixes - std::max(wait, fp_wait));
    }

    // the next pairs with it in V: both pairable their ways, no prefix on the second, neither
    // writing what the other reads or writes but the flags a branch reads and two flag writers
    // (BB20, BB21); ESP changed by PUSH, POP, CALL and RET only implicitly does not count (BB21);
    // an FP instruction pairs only with an FXCH after it (BB63)
    bool pair = false;
    const bool fp = u.kind == Kind::Fpu;
    if (fp) {
        pair = n > 1 && window[1].insn->kind == Kind::Fpu && window[1].insn->fpu.op == FpOp::Exchange && pairs_with_fxch(u) &&
               facts(*window[1].insn).prefix == 0;
    } else if (n > 1) {
        const Insn& v = *window[1].insn;
        const Memo& fv = facts(v);
        const Pairing pu = Pairing(fu.pairing), pv = Pairing(fv.pairing);
        Family v_on = Family::None;
        const bool contention = [&] {
            for (RegPart w : u.writes) {
                if (w.family == Family::SP && !u.writes_sp_explicitly) continue;
                for (RegPart r : v.reads)
                    if (r.family == w.family && (r.family != Family::SP || !v.mem.stack)) return true;
                for (RegPart x : v.writes)
                    if (x.family == w.family && (x.family != Family::SP || v.writes_sp_explicitly)) return true;
            }
            return u.writes_flags && v.reads_flags && v.kind != Kind::Jcc;
        }();
        pair = (pu == Pairing::UV || pu == Pairing::PU) && (pv == Pairing::UV || pv == Pairing::PV) && fv.prefix == 0 && !contention &&
               address_ready(v, &v_on) <= start;
    }
    int cu = fp ? this->fp(u).issue : branch_clocks(u, window[0].taken, 'U', &iu), cycles = cu;
    long fp_done = -1000;
    if (fp) {
        fp_done = x87_issue(u, start);
        if (pair) x87_issue(*window[1].insn, start);
    }
    if (pair && fp) {
        P5Issue& iv = out[1];
        iv.stalls.clear();
        // an FXCH paired but not followed by an FP instruction costs a cycle (AP-500; AF)
        if (n > 2 && window[2].insn->kind != Kind::Fpu) {
            ++cycles;
            stall(&iv, "an integer instruction after FXCH", 1);
        }
        iv.cycle = start, iv.pipe = 'V', iv.clocks = cycles, iv.done = start;
    } else if (pair) {
        const Insn& v = *window[1].insn;
        P5Issue& iv = out[1];
        iv.stalls.clear();
        const int cv = branch_clocks(v, window[1].taken, 'V', &iv);
        // lockstep; two memory-destination instructions overlap a cycle only (BB20)
        const Memo& fv = facts(v);
        cycles = fu.memory_dest && fv.memory_dest ? cu + cv - 1 : std::max(cu, cv);
        // the same bank of the data cache (address bits 2-4) where the code tells: the same
        // registers, displacements in the same dword of the 32 bytes (BB20)
        if (fu.memory && fv.memory && u.mem.base == v.mem.base && u.mem.index == v.mem.index && u.mem.scale == v.mem.scale &&
            ((u.mem.disp >> 2) & 7) == ((v.mem.disp >> 2) & 7)) {
            ++cycles;
            stall(&iv, "bank conflict", 1);
        }
        iv.cycle = start, iv.pipe = 'V', iv.clocks = cycles, iv.done = start + cycles - 1;
    }
    iu.cycle = start, iu.pipe = 'U', iu.clocks = cycles, iu.done = std::max(start + cycles - 1, fp_done);
    const long end = start + cycles - 1;
    for (size_t k = 0; k < (pair ? 2u : 1u); ++k)
        for (RegPart w : window[k].insn->writes)
            if (w.family != Family::SP || window[k].insn->writes_sp_explicitly) written_[size_t(w.family)] = end;
    now_ = start + cycles;
    return pair ? 2 : 1;
}

std::vector<P5Issue> P5::run(const std::vector<Executed>& stream) {
    std::vector<P5Issue> out(stream.size());
    for (size_t i = 0; i < stream.size();) i += size_t(issue(&stream[i], std::min<size_t>(3, stream.size() - i), &out[i]));
    return out;
}

}  // namespace timing
