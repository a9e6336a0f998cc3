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
    in.text = in.mnemonic + (c.op_str[0] ? std::string(" ") + c.op_str : std::string());
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
    } else if (cs_insn_group(h, &c, X86_GRP_FPU)) {
        in.kind = Kind::Fpu;
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
    Handle handle(bits);
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
