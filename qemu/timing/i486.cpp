// The i486 model (i486.h). Sources, by the abbreviations of docs/cycles.md: BB12, BB13, BB19, BB21,
// BB45, BB58 (Abrash's Black Book, chapters 12, 13, 19, 21, 45, 58); i486 (Intel's i486 manual's
// table as MAME's cycles.h carries it, and its x87 rows, concurrent clocks included, as 86Box's
// x87 timings carry them, for what the Black Book does not give).
#include "qemu/timing/i486.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace timing {

namespace {

// (in real mode, the 16-bit name)
std::string register_name(Family f, Mode mode) {
    const std::string name = family_name(f);
    return mode == Mode::Real16 && f != Family::None ? name.substr(1) : name;
}

bool is_byte(RegPart p) { return p.bytes == 1 || p.bytes == 2; }

// The registers the instruction addresses memory through: its base and index (None where it has
// none); the stack pointer of PUSH, POP, CALL and RET counts only after an explicit write of it
// (BB12, "Stack Addressing"), which the caller checks.
struct Address {
    Family base = Family::None, index = Family::None;
    bool uses(Family f) const { return f != Family::None && (f == base || f == index); }
};
Address address_registers(const Insn& in) {
    if (!in.mem.present) return {};
    return {in.mem.base, in.mem.index};
}

bool addresses_32(const Insn& in, Mode mode) { return (mode == Mode::Protected32) != in.addrsize_prefix; }

}  // namespace

int I486::base_clocks(const Insn& in, bool taken, Mode mode) {
    const std::string& m = in.mnemonic;
    const bool mem = in.mem.present && !in.mem.stack;
    const bool mem_dest = mem && in.mem.write, mem_src = mem && !in.mem.write;
    if (m == "mov" || m == "nop" || m == "lea" || m == "bswap") return 1;                               // BB12, BB13
    if (among(m, {"add", "sub", "adc", "sbb", "and", "or", "xor"})) return mem_dest ? 3 : mem_src ? 2 : 1;  // BB13, BB28
    if (m == "cmp" || m == "test") return mem ? 2 : 1;                                                   // BB16
    if (among(m, {"inc", "dec", "neg", "not"})) return mem_dest ? 3 : 1;                                 // BB12; i486 (memory)
    if (among(m, {"shl", "sal", "shr", "sar", "rol", "ror"})) {
        // by an immediate count (C0/C1) 2, by 1 (D0/D1) 3 (BB13: "Go figure"; BB58 counts ROL AL,1
        // as 2, docs/cycles.md says why the model keeps 3); by CL (D2/D3) 3 (i486); memory 4 (i486)
        if (mem) return 4;
        return in.opcode == 0xC0 || in.opcode == 0xC1 ? 2 : 3;
    }
    if (m == "rcl" || m == "rcr") return in.opcode == 0xD0 || in.opcode == 0xD1 ? 3 : 8;  // BB9 (Intel: 8 to 30 multibit: its least)
    if (m == "push") return mem ? 4 : 1;  // BB13
    if (m == "pop") return mem ? 6 : 1;   // BB13 (the manual's 4 for a register is wrong: BB13)
    if (m == "xchg") return mem ? 9 : 3;  // BB19 (measured, with memory); i486 (registers)
    if (among(m, {"movzx", "movsx", "cbw", "cwde", "cwd", "cdq"}) || m.rfind("set", 0) == 0) return 3;  // i486
    if (m == "sahf") return 2;                  // i486
    if (m == "lahf") return 3;                  // i486
    if (m == "xlatb" || m == "xlat") return 4;  // BB12
    // a string instruction; with REP, each repetition runs as an instruction of its own (as QEMU
    // executes it): REP STOS 4 a repetition, REP MOVS 3 (i486: 7+4n, 12+3n)
    if (m.rfind("stos", 0) == 0) return in.rep_prefix ? 4 : 5;  // BB12 (STOSB)
    if (m.rfind("lods", 0) == 0) return 5;                        // i486
    if (m.rfind("movs", 0) == 0 && m != "movsx") return in.rep_prefix ? 3 : 7;  // i486
    // i486, the rest a compiled program runs
    if (m == "leave") return 5;
    if (among(m, {"cld", "std", "clc", "stc", "cmc"})) return 2;
    if (m == "cli" || m == "sti") return 5;
    if (m == "pushfd" || m == "pushf") return 4;
    if (m == "popfd" || m == "popf") return 9;
    if (m == "pushal" || m == "pushad") return 11;
    if (m == "popal" || m == "popad") return 9;
    if (m == "bt") return mem ? 8 : 3;
    if (among(m, {"bts", "btr", "btc"})) return mem ? 13 : 6;
    if (m == "bsf" || m == "bsr") return 6;  // (6 to 42: its least)
    if (m == "shld" || m == "shrd") return mem ? 4 : 2;
    if (m == "iretd" || m == "iret") return 15;
    if (m == "hlt") return 4;
    if (m == UNMODELLED) return 1;
    if (m == "mul" || m == "imul") return 13;  // BB45 (MUL 13 to 42: its least); i486 (IMUL r, r/m)
    if (m == "div" || m == "idiv") {
        const int bytes = in.operand_bytes;
        const bool s = m == "idiv";
        return bytes == 1 ? (s ? 19 : 16) : bytes == 2 ? (s ? 27 : 24) : (s ? 43 : 40);  // i486
    }
    if (in.kind == Kind::Jcc && in.loop) return taken ? 7 : 6;  // BB7: LOOP is DEC/JNZ + 3; i486: 6 not taken
    if (in.kind == Kind::Jcc) return taken ? 3 : 1;             // BB19
    if (in.kind == Kind::Jmp || in.kind == Kind::Call) return 3;  // i486
    if (in.kind == Kind::Ret) return 5;                           // BB12 (POP + RET = 6)
    if (in.kind == Kind::Out) return mode == Mode::Real16 ? 16 : 10;  // BB45, BB58: real mode 16; full I/O privilege 10
    if (in.kind == Kind::In) return 14;                               // i486 (real mode)
    throw std::runtime_error("no 486 timing for '" + in.text + "' (docs/cycles.md lists what the model knows)");
}

FpClocks I486::fpu_clocks(const Insn& in) {
    // i486 (the manual's table: its least where it gives a range), "concurrent" its own column
    const int bytes = in.mem.present ? in.mem.size : 0;
    switch (in.fpu.op) {
    case FpOp::Load: return {bytes ? 3 : 4, 0};
    case FpOp::LoadExtended: return {6, 0};
    case FpOp::LoadInt: return {bytes == 2 ? 13 : bytes == 4 ? 9 : 10, 0};
    case FpOp::LoadConst: return {in.mnemonic == "fld1" || in.mnemonic == "fldz" ? 4 : 8, 0};
    case FpOp::Store: return {bytes == 8 ? 8 : bytes ? 7 : 3, 0};
    case FpOp::StoreExtended: return {6, 0};
    case FpOp::StoreInt: return {bytes == 4 ? 28 : 29, 0};
    case FpOp::Add: return {8, 7};
    case FpOp::Mul: return bytes == 4 ? FpClocks{11, 8} : bytes == 8 ? FpClocks{14, 11} : FpClocks{16, 13};
    case FpOp::Div: return {73, 70};
    case FpOp::IntAdd: return {bytes == 2 ? 20 : 19, 7};
    case FpOp::IntMul: return {bytes == 2 ? 23 : 22, 8};
    case FpOp::IntDiv: return {bytes == 2 ? 85 : 84, 70};
    case FpOp::Compare: return {in.fpu.pops == 2 ? 5 : 4, 0};
    case FpOp::Exchange: return {4, 0};
    case FpOp::Unary: return {in.mnemonic == "fchs" ? 6 : 3, 0};
    case FpOp::Sqrt: return {83, 70};
    case FpOp::LoadControl: return {4, 0};
    case FpOp::StoreControl: return {3, 0};
    case FpOp::StoreStatus: return {3, 0};
    case FpOp::Wait: return {1, 0};
    default: throw std::runtime_error("no 486 timing for '" + in.text + "' (docs/cycles.md lists what the model knows)");
    }
}

// The instruction's entries in the tables, worked out once for this mode (insn.h, Memo); where
// the tables have none, they throw here.
const Memo& I486::facts(const Insn& in) const {
    const uint32_t key = 0x4860000u + uint32_t(mode_);
    Memo& m = in.memo;
    if (m.key == key) return m;
    Memo fresh;
    if (in.kind == Kind::Fpu) {
        const FpClocks c = fpu_clocks(in);
        fresh.clocks = int16_t(c.clocks), fresh.fp_concurrent = int16_t(c.concurrent);
    } else {
        fresh.clocks = int16_t(base_clocks(in, true, mode_)), fresh.clocks_not_taken = int16_t(base_clocks(in, false, mode_));
    }
    fresh.key = key;
    m = fresh;
    return m;
}

Step I486::run(const Insn& in, bool taken) {
    Step s;
    s.start = now_;
    long start = now_;
    const Address address = address_registers(in);
    const bool addressing = in.mem.present && !in.mem.stack;

    // AGI: a register written in the cycle before is used to address memory: 1 lost (Intel's rule,
    // BB12; BB12 measured 2, and 1 more two cycles later, in real mode on early 486s, which the
    // published counts of BB58 do not take: docs/cycles.md, "Where the sources disagree")
    int agi = 0;
    Family agi_on = Family::None;
    for (Family f : {address.base, address.index, in.mem.stack ? Family::SP : Family::None}) {
        if (f == Family::None) continue;
        const long d = start - last_write_[size_t(f)];
        const int lost = d == 1 ? 1 : 0;
        if (lost > agi) agi = lost, agi_on = f;
    }
    if (agi) {
        start += agi;
        if (explain_) s.stalls.push_back(std::string("AGI on ") + register_name(agi_on, mode_) + " +" + std::to_string(agi));
    }
    // a byte register written exactly two cycles before an instruction that addresses memory, by any
    // register (BB12, rule 4; twice where two byte writes fall there in turn)
    for (int k = 0; addressing && k < 2; ++k)
        if (last_byte_dest_ == start - 2 || byte_dest_before_ == start - 2) {
            ++start;
            if (explain_) s.stalls.push_back("byte register two cycles before an address +1");
        }
    // a byte of a register written in the cycle before, then the register read whole (BB12, rule 3)
    for (RegPart r : in.reads) {
        const size_t f = size_t(r.family);
        if (address.uses(r.family)) continue;  // (the AGI's)
        if (last_byte_write_[f] == start - 1 && (r.bytes & ~last_byte_bytes_[f])) {
            ++start;
            if (explain_) s.stalls.push_back(std::string("byte then whole of ") + register_name(r.family, mode_) + " +1");
            break;
        }
    }

    // the x87 takes one instruction at a time: the next waits for it; the integer unit runs on
    // beside it for its concurrent clocks (i486)
    const bool fpu = in.kind == Kind::Fpu;
    const Memo& m = facts(in);
    const FpClocks fc = fpu ? FpClocks{m.clocks, m.fp_concurrent} : FpClocks{};
    if (fpu && fpu_free_ > start) {
        if (explain_) s.stalls.push_back("x87 busy +" + std::to_string(fpu_free_ - start));
        start = fpu_free_;
    }
    int clocks = fpu ? fc.clocks - fc.concurrent : taken ? m.clocks : m.clocks_not_taken;
    // prefixes: a cycle each, but one decodes while an AGI waits or the instruction before runs on
    // (BB13, BB19: "prefix cycles can overlap with previous multicycle instructions, or AGIs")
    const int prefixes = int(in.opsize_prefix) + int(in.addrsize_prefix) + int(in.segment_prefix);
    const int hidden = std::min(prefixes, agi + std::max(0, last_clocks_ - 1));
    if (prefixes > hidden) {
        clocks += prefixes - hidden;
        if (explain_) s.stalls.push_back("prefix +" + std::to_string(prefixes - hidden));
    }
    if (in.lock_prefix) {
        clocks += 5;  // BB19 (measured)
        if (explain_) s.stalls.push_back("lock +5");
    }
    if (in.has_imm && in.mem.has_disp) {  // BB21
        ++clocks;
        if (explain_) s.stalls.push_back("immediate and displacement +1");
    }
    // indexed addressing: two registers in 16-bit addressing, an index (two registers, or a scale)
    // in 32-bit addressing; ESP as a base is free (BB12, BB13)
    if (addressing && (addresses_32(in, mode_) ? in.mem.index != Family::None : in.mem.base != Family::None && in.mem.index != Family::None)) {
        ++clocks;
        if (explain_) s.stalls.push_back("index register +1");
    }

    const long end = start + clocks - 1;
    s.done = end;
    if (fpu) fpu_free_ = start + clocks + fc.concurrent, s.done = fpu_free_ - 1;
    for (RegPart w : in.writes) {
        if (w.family == Family::SP && !in.writes_sp_explicitly) continue;  // PUSH, POP, CALL, RET: implicit (BB12)
        const size_t f = size_t(w.family);
        last_write_[f] = end;
        if (is_byte(w)) last_byte_write_[f] = end, last_byte_bytes_[f] = w.bytes;
    }
    if (std::any_of(in.writes.begin(), in.writes.end(), is_byte)) byte_dest_before_ = last_byte_dest_, last_byte_dest_ = end;
    s.clocks = int(end - s.start + 1);
    now_ = end + 1;
    last_clocks_ = clocks;
    return s;
}

}  // namespace timing
