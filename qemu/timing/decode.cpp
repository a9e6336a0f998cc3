// Capstone's x86 decoding (its detail mode) turned into timing::Insn.
#include "qemu/timing/decode.h"

#include <capstone/capstone.h>

#include <memory>
#include <string>

namespace timing {

namespace {

RegPart part_of(unsigned reg) {
    switch (reg) {
    case X86_REG_AL: return {Family::A, 1};
    case X86_REG_AH: return {Family::A, 2};
    case X86_REG_AX: return {Family::A, 3};
    case X86_REG_EAX: return {Family::A, 15};
    case X86_REG_BL: return {Family::B, 1};
    case X86_REG_BH: return {Family::B, 2};
    case X86_REG_BX: return {Family::B, 3};
    case X86_REG_EBX: return {Family::B, 15};
    case X86_REG_CL: return {Family::C, 1};
    case X86_REG_CH: return {Family::C, 2};
    case X86_REG_CX: return {Family::C, 3};
    case X86_REG_ECX: return {Family::C, 15};
    case X86_REG_DL: return {Family::D, 1};
    case X86_REG_DH: return {Family::D, 2};
    case X86_REG_DX: return {Family::D, 3};
    case X86_REG_EDX: return {Family::D, 15};
    case X86_REG_SI: return {Family::SI, 3};
    case X86_REG_ESI: return {Family::SI, 15};
    case X86_REG_DI: return {Family::DI, 3};
    case X86_REG_EDI: return {Family::DI, 15};
    case X86_REG_BP: return {Family::BP, 3};
    case X86_REG_EBP: return {Family::BP, 15};
    case X86_REG_SP: return {Family::SP, 3};
    case X86_REG_ESP: return {Family::SP, 15};
    default: return {};
    }
}

bool is_string(unsigned id) {
    switch (id) {
    case X86_INS_STOSB: case X86_INS_STOSW: case X86_INS_STOSD:
    case X86_INS_MOVSB: case X86_INS_MOVSW: case X86_INS_MOVSD:
    case X86_INS_LODSB: case X86_INS_LODSW: case X86_INS_LODSD:
    case X86_INS_SCASB: case X86_INS_SCASW: case X86_INS_SCASD:
    case X86_INS_CMPSB: case X86_INS_CMPSW: case X86_INS_CMPSD: return true;
    default: return false;
    }
}

// Whether the encoding carries a displacement (a moffs, or ModR/M's mod and r/m ask for one).
bool has_displacement(const cs_x86& x, bool moffs) {
    if (moffs) return true;
    const int mod = x.modrm >> 6, rm = x.modrm & 7;
    if (mod == 1 || mod == 2) return true;
    if (mod != 0) return false;
    return x.addr_size == 2 ? rm == 6 : rm == 5 || (rm == 4 && (x.sib & 7) == 5);
}

// The x87's view of the instruction at `b` (Fpu.op None where it is no x87 instruction), from its
// escape byte (D8h-DFh) and ModR/M: the Intel manuals' opcode map.
Fpu x87(const uint8_t* b, size_t n) {
    size_t k = 0;
    while (k < n && (b[k] == 0x66 || b[k] == 0x67 || b[k] == 0x26 || b[k] == 0x2E || b[k] == 0x36 || b[k] == 0x3E || b[k] == 0x64 ||
                     b[k] == 0x65 || b[k] == 0xF0 || b[k] == 0xF2 || b[k] == 0xF3))
        ++k;
    Fpu f;
    if (k < n && b[k] == 0x9B) {
        if (k + 1 == n || b[k + 1] < 0xD8 || b[k + 1] > 0xDF) return f.op = FpOp::Wait, f;
        ++k;  // FSTCW, FSTSW, FINIT, ...: WAIT and the no-wait form as one
    }
    if (k + 1 >= n || b[k] < 0xD8 || b[k] > 0xDF) return f;
    const uint8_t esc = b[k], modrm = b[k + 1];
    const int reg = (modrm >> 3) & 7, i = modrm & 7;
    static const FpOp ARITH[8] = {FpOp::Add, FpOp::Mul, FpOp::Compare, FpOp::Compare, FpOp::Add, FpOp::Add, FpOp::Div, FpOp::Div};
    static const FpOp INT_ARITH[8] = {FpOp::IntAdd, FpOp::IntMul, FpOp::Compare, FpOp::Compare, FpOp::IntAdd, FpOp::IntAdd, FpOp::IntDiv, FpOp::IntDiv};
    auto set = [&](FpOp op, uint8_t reads, int dest, bool push, int pops) {
        f.op = op, f.reads = reads, f.dest = int8_t(dest), f.push = push, f.pops = uint8_t(pops);
        return f;
    };
    if ((modrm >> 6) != 3) {  // a memory operand
        switch (esc) {
        case 0xD8: case 0xDC: return set(ARITH[reg], 1, reg == 2 || reg == 3 ? -1 : 0, false, reg == 3);
        case 0xDA: case 0xDE: return set(INT_ARITH[reg], 1, reg == 2 || reg == 3 ? -1 : 0, false, reg == 3);
        case 0xD9: {
            static const FpOp D9[8] = {FpOp::Load, FpOp::Other, FpOp::Store, FpOp::Store, FpOp::Other, FpOp::LoadControl, FpOp::Other, FpOp::StoreControl};
            return set(D9[reg], reg == 2 || reg == 3, reg == 0 ? 0 : -1, reg == 0, reg == 3);
        }
        case 0xDB: {
            static const FpOp DB[8] = {FpOp::LoadInt, FpOp::Other, FpOp::StoreInt, FpOp::StoreInt, FpOp::Other, FpOp::LoadExtended, FpOp::Other, FpOp::StoreExtended};
            return set(DB[reg], reg == 2 || reg == 3 || reg == 7, reg == 0 || reg == 5 ? 0 : -1, reg == 0 || reg == 5, reg == 3 || reg == 7);
        }
        case 0xDD: {
            static const FpOp DD[8] = {FpOp::Load, FpOp::Other, FpOp::Store, FpOp::Store, FpOp::Other, FpOp::Other, FpOp::Other, FpOp::StoreStatus};
            return set(DD[reg], reg == 2 || reg == 3, reg == 0 ? 0 : -1, reg == 0, reg == 3);
        }
        default: {  // DF
            static const FpOp DF[8] = {FpOp::LoadInt, FpOp::Other, FpOp::StoreInt, FpOp::StoreInt, FpOp::Other, FpOp::LoadInt, FpOp::Other, FpOp::StoreInt};
            return set(DF[reg], reg == 2 || reg == 3 || reg == 7, reg == 0 || reg == 5 ? 0 : -1, reg == 0 || reg == 5, reg == 3 || reg == 7);
        }
        }
    }
    const uint8_t both = uint8_t(1 | (1u << i));
    switch (esc) {
    case 0xD8: return set(ARITH[reg], both, reg == 2 || reg == 3 ? -1 : 0, false, reg == 3);  // st0 = st0 op st(i)
    case 0xDC: return set(ARITH[reg], both, reg == 2 || reg == 3 ? -1 : i, false, reg == 3);  // st(i) = st(i) op st0
    case 0xDE:
        if (reg == 3 && i == 1) return set(FpOp::Compare, 3, -1, false, 2);  // FCOMPP
        return set(ARITH[reg], both, reg == 2 || reg == 3 ? -1 : i, false, 1);
    case 0xD9:
        if (reg == 0) return set(FpOp::Load, uint8_t(1u << i), 0, true, 0);
        if (reg == 1) return set(FpOp::Exchange, both, -1, false, 0);
        if (modrm == 0xE0 || modrm == 0xE1) return set(FpOp::Unary, 1, 0, false, 0);
        if (modrm == 0xE4) return set(FpOp::Compare, 1, -1, false, 0);
        if (modrm >= 0xE8 && modrm <= 0xEE) return set(FpOp::LoadConst, 0, 0, true, 0);
        if (modrm == 0xFA) return set(FpOp::Sqrt, 1, 0, false, 0);
        return set(FpOp::Other, 0, -1, false, 0);
    case 0xDA: return modrm == 0xE9 ? set(FpOp::Compare, 3, -1, false, 2) : set(FpOp::Other, 0, -1, false, 0);
    case 0xDD:
        if (reg == 2 || reg == 3) return set(FpOp::Store, 1, i, false, reg == 3);
        if (reg == 4 || reg == 5) return set(FpOp::Compare, both, -1, false, reg == 5);
        return set(FpOp::Other, 0, -1, false, 0);
    case 0xDF: return modrm == 0xE0 ? set(FpOp::StoreStatus, 0, -1, false, 0) : set(FpOp::Other, 0, -1, false, 0);
    default: return set(FpOp::Other, 0, -1, false, 0);  // DB: FNINIT, FNCLEX, FCMOV, FCOMI
    }
}

struct Handle {
    csh h = 0;
    explicit Handle(int bits) {
        if (cs_open(CS_ARCH_X86, bits == 16 ? CS_MODE_16 : CS_MODE_32, &h) != CS_ERR_OK) throw DecodeError("Capstone: cannot open x86");
        cs_option(h, CS_OPT_DETAIL, CS_OPT_ON);
    }
    ~Handle() { cs_close(&h); }
};

Insn convert(csh h, const cs_insn& c) {
    const cs_x86& x = c.detail->x86;
    Insn in;
    in.address = uint32_t(c.address), in.size = uint8_t(c.size), in.id = c.id;
    in.mnemonic = c.mnemonic;
    // (Capstone writes REP, REPNE and LOCK into the mnemonic; the prefix flags below carry them)
    if (const size_t space = in.mnemonic.find(' '); space != std::string::npos) in.mnemonic = in.mnemonic.substr(space + 1);
    in.text = std::string(c.mnemonic) + (c.op_str[0] ? std::string(" ") + c.op_str : std::string());
    in.opsize_prefix = x.prefix[2] == X86_PREFIX_OPSIZE, in.addrsize_prefix = x.prefix[3] == X86_PREFIX_ADDRSIZE;
    in.segment_prefix = x.prefix[1] != 0;
    in.rep_prefix = x.prefix[0] == X86_PREFIX_REP || x.prefix[0] == X86_PREFIX_REPNE;
    in.lock_prefix = x.prefix[0] == X86_PREFIX_LOCK;
    in.two_byte_opcode = x.opcode[0] == 0x0F;
    in.opcode = in.two_byte_opcode ? x.opcode[1] : x.opcode[0];

    cs_regs reads, writes;
    uint8_t nreads = 0, nwrites = 0;
    if (cs_regs_access(h, &c, reads, &nreads, writes, &nwrites) == CS_ERR_OK) {
        for (uint8_t i = 0; i < nreads; ++i) {
            if (reads[i] == X86_REG_EFLAGS) in.reads_flags = true;
            if (RegPart p = part_of(reads[i]); p.family != Family::None) in.reads.push_back(p);
        }
        for (uint8_t i = 0; i < nwrites; ++i) {
            if (writes[i] == X86_REG_EFLAGS) in.writes_flags = true;
            if (RegPart p = part_of(writes[i]); p.family != Family::None) in.writes.push_back(p);
        }
    }
    constexpr uint64_t TESTS = X86_EFLAGS_TEST_OF | X86_EFLAGS_TEST_SF | X86_EFLAGS_TEST_ZF | X86_EFLAGS_TEST_PF | X86_EFLAGS_TEST_CF |
                               X86_EFLAGS_TEST_AF | X86_EFLAGS_TEST_DF;
    if (x.eflags & TESTS) in.reads_flags = true;
    if (x.eflags & ~TESTS) in.writes_flags = true;

    const bool moffs = x.opcode[0] >= 0xA0 && x.opcode[0] <= 0xA3;
    const bool by_one = x.opcode[0] == 0xD0 || x.opcode[0] == 0xD1;  // (a shift by 1: Capstone shows the 1 as an immediate)
    for (uint8_t i = 0; i < x.op_count; ++i) {
        const cs_x86_op& op = x.operands[i];
        if (op.size > in.operand_bytes && op.type != X86_OP_IMM) in.operand_bytes = op.size;
        if (op.type == X86_OP_IMM && !by_one) in.has_imm = true;
        if (op.type == X86_OP_REG && (op.access & CS_AC_WRITE) && part_of(op.reg).family == Family::SP) in.writes_sp_explicitly = true;
        if (op.type != X86_OP_MEM) continue;
        Memory& m = in.mem;
        m.present = true;
        m.read = m.read || (op.access & CS_AC_READ) || op.access == 0;
        m.write = m.write || (op.access & CS_AC_WRITE);
        m.base = part_of(op.mem.base).family, m.index = part_of(op.mem.index).family;
        m.scale = op.mem.scale;
        m.disp = int32_t(op.mem.disp);
        m.has_disp = !is_string(c.id) && has_displacement(x, moffs);
        m.size = op.size;
    }

    if (cs_insn_group(h, &c, X86_GRP_JUMP)) {
        in.kind = c.id == X86_INS_JMP || c.id == X86_INS_LJMP ? Kind::Jmp : Kind::Jcc;
        in.loop = c.id == X86_INS_LOOP || c.id == X86_INS_LOOPE || c.id == X86_INS_LOOPNE || c.id == X86_INS_JCXZ || c.id == X86_INS_JECXZ;
        if (x.op_count > 0 && x.operands[0].type == X86_OP_IMM) in.target = uint32_t(x.operands[0].imm);
    } else if (cs_insn_group(h, &c, X86_GRP_CALL)) {
        in.kind = Kind::Call;
    } else if (cs_insn_group(h, &c, X86_GRP_RET)) {
        in.kind = Kind::Ret;
    } else if (c.id == X86_INS_OUT) {
        in.kind = Kind::Out;
    } else if (c.id == X86_INS_IN) {
        in.kind = Kind::In;
    } else if (is_string(c.id)) {
        in.kind = Kind::String;
    }
    in.fpu = x87(c.bytes, c.size);
    if (in.fpu.op != FpOp::None) {
        in.kind = Kind::Fpu;
        // (Capstone marks a store's memory operand read)
        const bool store = in.fpu.op == FpOp::Store || in.fpu.op == FpOp::StoreExtended || in.fpu.op == FpOp::StoreInt ||
                           in.fpu.op == FpOp::StoreControl || in.fpu.op == FpOp::StoreStatus;
        if (in.mem.present) in.mem.read = !store, in.mem.write = store;
    }
    const bool stack = c.id == X86_INS_PUSH || c.id == X86_INS_POP || in.kind == Kind::Call || in.kind == Kind::Ret;
    if (stack && !in.mem.present) {
        in.mem.present = true, in.mem.stack = true, in.mem.base = Family::SP;
        in.mem.read = c.id == X86_INS_POP || in.kind == Kind::Ret;
        in.mem.write = !in.mem.read;
    }
    return in;
}

}  // namespace

std::vector<Insn> decode(const uint8_t* bytes, size_t size, int bits, uint32_t address, bool stop_at_bad) {
    // (a handle each mode, opened once a thread: a whole run decodes each block it translates)
    thread_local Handle handle32(32), handle16(16);
    Handle& handle = bits == 16 ? handle16 : handle32;
    std::vector<Insn> out;
    size_t offset = 0;
    while (offset < size) {
        cs_insn* c = nullptr;
        const size_t n = cs_disasm(handle.h, bytes + offset, size - offset, address + offset, 1, &c);
        if (n != 1 && stop_at_bad) break;
        if (n != 1) throw DecodeError("byte " + std::to_string(offset) + ": no x86 instruction decodes here");
        std::unique_ptr<cs_insn, void (*)(cs_insn*)> own(c, [](cs_insn* p) { cs_free(p, 1); });
        out.push_back(convert(handle.h, *c));
        offset += c->size;
    }
    return out;
}

}  // namespace timing
