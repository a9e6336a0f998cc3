// A decoded x86 instruction as the timing models see it (docs/cycles.md): what it reads and writes
// (registers by their bytes, flags, memory), how it addresses memory, its prefixes and its kind.
// Model-independent: decode.h fills it from Capstone.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace timing {

// A general register as a family (EAX, EBX, ...) and the bytes of it an access touches: bit 0 the
// low byte (AL), bit 1 the next (AH), bits 2-3 the upper half. ESP and EBP have no byte parts.
enum class Family : uint8_t { None, A, B, C, D, SI, DI, BP, SP, Count };
struct RegPart {
    Family family = Family::None;
    uint8_t bytes = 0;  // 1: low byte, 2: high byte, 3: the word, 15: the dword
};

enum class Kind : uint8_t {
    Plain,   // runs straight on
    Jcc,     // a conditional branch (LOOP and JCXZ too: `loop`)
    Jmp,     // an unconditional jump
    Call,
    Ret,
    Out,     // OUT to a port
    In,
    String,  // STOS, MOVS, LODS, SCAS, CMPS (rep: `rep`)
    Fpu,     // x87
};

struct Memory {
    bool present = false;
    bool read = false, write = false;
    Family base = Family::None, index = Family::None;
    int scale = 1;
    bool has_disp = false;  // a displacement field in the encoding (even a zero one)
    int32_t disp = 0;
    int size = 0;           // bytes accessed
    bool stack = false;     // an implicit stack access (PUSH, POP, CALL, RET)
};

// What an x87 instruction does, by its encoding (D8h-DFh, 9Bh): its class for the timing tables, the
// stack registers it reads and writes, counted from the top before it runs, and what it pushes and pops.
enum class FpOp : uint8_t {
    None,
    Load,          // FLD m32/m64/st(i): a push
    LoadExtended,  // FLD m80
    LoadInt,       // FILD
    LoadConst,     // FLD1, FLDZ, FLDPI, ...
    Store,         // FST, FSTP m32/m64/st(i)
    StoreExtended, // FSTP m80
    StoreInt,      // FIST, FISTP
    Add,           // FADD, FSUB, FSUBR (and their P forms)
    Mul,           // FMUL, FMULP
    Div,           // FDIV, FDIVR (and P)
    IntAdd,        // FIADD, FISUB, FISUBR
    IntMul,        // FIMUL
    IntDiv,        // FIDIV, FIDIVR
    Compare,       // FCOM, FCOMP, FCOMPP, FUCOM.., FTST, FICOM
    Exchange,      // FXCH
    Unary,         // FCHS, FABS
    Sqrt,          // FSQRT
    LoadControl,   // FLDCW
    StoreControl,  // FNSTCW
    StoreStatus,   // FNSTSW
    Wait,          // WAIT
    Other,         // the rest (transcendentals, FNINIT, FRNDINT, ...): the models name it and stop
};
struct Fpu {
    FpOp op = FpOp::None;
    uint8_t reads = 0;   // bit i: st(i) read
    int8_t dest = -1;    // the st(i) written (the new top where `push`)
    bool push = false;
    uint8_t pops = 0;    // popped after the result is written
};

// A model's table entries for an instruction, worked out once and kept with it for a stream that
// runs it again (a whole run's hot path, machine.h): `key` names the model and its settings that
// filled it, 0 none. Each model reads only what it filled.
struct Memo {
    uint32_t key = 0;
    int16_t clocks = 0, clocks_not_taken = 0;  // -1: the model has no timing for it
    int8_t pairing = 0, prefix = 0;
    bool memory = false, memory_dest = false, multiplier = false;
    int16_t fp_issue = 0, fp_latency = 0, fp_next = 0, fp_concurrent = 0;
};

struct Insn {
    uint32_t address = 0;
    uint8_t size = 0;         // bytes
    std::string text;         // "mov bl, byte ptr [esi]"
    std::string mnemonic;     // "mov"
    unsigned id = 0;          // Capstone's instruction id
    Kind kind = Kind::Plain;
    bool loop = false;        // LOOP/LOOPcc/JCXZ/JECXZ: a Jcc that reads (E)CX
    uint32_t target = 0;      // a branch's target
    bool has_imm = false;     // an immediate operand
    int operand_bytes = 0;    // the size of its largest register or memory operand
    // prefixes in the encoding
    bool opsize_prefix = false, addrsize_prefix = false, segment_prefix = false, rep_prefix = false, lock_prefix = false;
    bool two_byte_opcode = false;  // 0Fh
    uint8_t opcode = 0;            // the (first) opcode byte, after 0Fh
    std::vector<RegPart> reads, writes;  // general registers, explicit and implicit (the address's among reads)
    bool reads_flags = false, writes_flags = false;
    bool writes_sp_explicitly = false;  // ESP as an explicit destination (not PUSH/POP's implicit change)
    Memory mem;
    Fpu fpu;  // Kind::Fpu
    mutable Memo memo;
};

// The mnemonic of the stand-in a whole run puts in place of an instruction the models have no
// timing for (machine.h): a cycle, pairing with nothing.
inline constexpr const char* UNMODELLED = "(unmodelled)";

// The family's 32-bit name ("esi").
inline const char* family_name(Family f) {
    static const char* const NAMES[] = {"-", "eax", "ebx", "ecx", "edx", "esi", "edi", "ebp", "esp"};
    return NAMES[size_t(f)];
}

// Whether a mnemonic is one of `names` (the models' tables).
inline bool among(const std::string& mnemonic, std::initializer_list<const char*> names) {
    for (const char* n : names)
        if (mnemonic == n) return true;
    return false;
}

// Whether two parts of registers overlap.
inline bool overlaps(RegPart a, RegPart b) { return a.family == b.family && a.family != Family::None && (a.bytes & b.bytes); }

}  // namespace timing
