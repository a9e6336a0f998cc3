// The 486 timing model: Capstone's decoding as the model reads it, each documented rule on the
// example its source gives, and the calibration on the Black Book's chapter 58 listings
// (tests/timing/listings), each against its published figure, with the residuals docs/cycles.md
// explains.
#include <gtest/gtest.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "qemu/timing/analyse.h"
#include "qemu/timing/decode.h"
#include "qemu/timing/i486.h"
#include "qemu/timing/listing.h"

namespace {

using namespace timing;

std::vector<Insn> code(std::vector<uint8_t> bytes, int bits) { return decode(bytes.data(), bytes.size(), bits); }

// The cycles the instructions take run once, one after the other, from an idle machine.
long cycles(const std::vector<Insn>& insns, Mode mode) {
    I486 cpu(mode);
    for (const Insn& in : insns) cpu.run(in, true);
    return cpu.now();
}

TEST(TimingDecode, ReadsPrefixesAddressesAndRegisterBytes) {
    // 16-bit: mov [es:di],ah; add edx,ecx (66h); shl ax,1 (D1: no immediate); mov word [bp+16],1
    const std::vector<Insn> in = code({0x26, 0x88, 0x25, 0x66, 0x01, 0xCA, 0xD1, 0xE0, 0xC7, 0x46, 0x10, 0x01, 0x00}, 16);
    ASSERT_EQ(in.size(), 4u);
    EXPECT_TRUE(in[0].segment_prefix);
    EXPECT_TRUE(in[0].mem.present && in[0].mem.write && !in[0].mem.read);
    EXPECT_EQ(in[0].mem.base, Family::DI);
    EXPECT_FALSE(in[0].mem.has_disp);
    ASSERT_EQ(in[0].reads.size(), 2u) << "ah and di";
    EXPECT_TRUE(overlaps(in[0].reads[0], RegPart{Family::A, 2}) || overlaps(in[0].reads[1], RegPart{Family::A, 2}));
    EXPECT_TRUE(in[1].opsize_prefix);
    EXPECT_TRUE(in[1].writes_flags);
    EXPECT_FALSE(in[2].has_imm) << "a shift by 1 has no immediate field";
    EXPECT_TRUE(in[3].has_imm && in[3].mem.has_disp && in[3].mem.base == Family::BP);
    // 32-bit: jz back to 0 from 2; push eax
    const std::vector<Insn> j = code({0x74, 0xFE, 0x50}, 32);
    EXPECT_EQ(j[0].kind, Kind::Jcc);
    EXPECT_EQ(j[0].target, 0u);
    EXPECT_TRUE(j[0].reads_flags);
    EXPECT_TRUE(j[1].mem.stack && j[1].mem.write && j[1].mem.base == Family::SP);
}

// The x87 by its encoding: each instruction's class, the stack registers it reads and writes
// (counted from the top before it runs), what it pushes and pops, and a store's memory written.
TEST(TimingDecode, ReadsTheX87ByItsEncoding) {
    // fld dword [eax]; faddp st2,st0; fxch st3; fstp qword [ebx]; fdivr st0,st1; fcompp; fistp dword [esp+8]; fnstsw ax; fld1
    const std::vector<Insn> in = code({0xD9, 0x00, 0xDE, 0xC2, 0xD9, 0xCB, 0xDD, 0x1B, 0xD8, 0xF9, 0xDE, 0xD9, 0xDB, 0x5C, 0x24, 0x08, 0xDF, 0xE0,
                                       0xD9, 0xE8},
                                      32);
    ASSERT_EQ(in.size(), 9u);
    for (const Insn& i : in) EXPECT_EQ(i.kind, Kind::Fpu) << i.text;
    EXPECT_EQ(in[0].fpu.op, FpOp::Load);
    EXPECT_TRUE(in[0].fpu.push && in[0].fpu.dest == 0 && in[0].mem.read && !in[0].mem.write);
    EXPECT_EQ(in[1].fpu.op, FpOp::Add);
    EXPECT_EQ(in[1].fpu.reads, 0b101);
    EXPECT_EQ(in[1].fpu.dest, 2);
    EXPECT_EQ(in[1].fpu.pops, 1);
    EXPECT_EQ(in[2].fpu.op, FpOp::Exchange);
    EXPECT_EQ(in[2].fpu.reads, 0b1001);
    EXPECT_EQ(in[3].fpu.op, FpOp::Store);
    EXPECT_TRUE(in[3].mem.write && !in[3].mem.read) << "a store writes its memory";
    EXPECT_EQ(in[3].fpu.pops, 1);
    EXPECT_EQ(in[4].fpu.op, FpOp::Div);
    EXPECT_EQ(in[4].fpu.dest, 0);
    EXPECT_EQ(in[5].fpu.op, FpOp::Compare);
    EXPECT_EQ(in[5].fpu.pops, 2);
    EXPECT_EQ(in[6].fpu.op, FpOp::StoreInt);
    EXPECT_TRUE(in[6].mem.write && in[6].mem.base == Family::SP);
    EXPECT_EQ(in[7].fpu.op, FpOp::StoreStatus);
    ASSERT_EQ(in[7].writes.size(), 1u);
    EXPECT_EQ(in[7].writes[0].family, Family::A);
    EXPECT_EQ(in[8].fpu.op, FpOp::LoadConst);
    EXPECT_TRUE(in[8].fpu.push);
    EXPECT_EQ(code({0x0F, 0xAF, 0xC3}, 32)[0].fpu.op, FpOp::None) << "imul eax,ebx";
}

TEST(TimingDecode, RefusesBytesThatAreNoInstruction) { EXPECT_THROW(code({0x90, 0xFE, 0xF8}, 32), DecodeError) << "FE /7"; }

// Black Book chapter 12, rule 2, as Intel documents it: a register written by one instruction and
// used by the next to address memory costs a cycle (mov ebx,esi; mov eax,[ebx]).
TEST(Timing486, TheAddressGenerationInterlockCostsACycle) {
    EXPECT_EQ(cycles(code({0x89, 0xF3, 0x8B, 0x03}, 32), Mode::Protected32), 3);
    // one instruction between (mov ebx,esi; nop; mov eax,[ebx]): none
    EXPECT_EQ(cycles(code({0x89, 0xF3, 0x90, 0x8B, 0x03}, 32), Mode::Protected32), 3);
}

// Chapter 12, rule 4, measured: `mov dl,cl / nop / mov ax,[bx]` 4 cycles, `nop / mov dl,cl / mov
// ax,[bx]` 3; `mov bl,al / mov cl,3 / mov bx,[si]` 5 (byte writes both 1 and 2 cycles before).
TEST(Timing486, AByteRegisterTwoCyclesBeforeAnAddressCostsACycle) {
    EXPECT_EQ(cycles(code({0x88, 0xCA, 0x90, 0x8B, 0x07}, 16), Mode::Real16), 4);
    EXPECT_EQ(cycles(code({0x90, 0x88, 0xCA, 0x8B, 0x07}, 16), Mode::Real16), 3);
    EXPECT_EQ(cycles(code({0x88, 0xC3, 0xB1, 0x03, 0x8B, 0x1C}, 16), Mode::Real16), 5);
}

// Chapter 12, rule 3: a byte loaded, then the whole register read by the next instruction
// (mov al,[si]; add cx,ax) costs a cycle; with one between, nothing.
TEST(Timing486, AByteThenTheWholeRegisterCostsACycle) {
    EXPECT_EQ(cycles(code({0x8A, 0x04, 0x01, 0xC1}, 16), Mode::Real16), 3);
    EXPECT_EQ(cycles(code({0x8A, 0x04, 0x90, 0x01, 0xC1}, 16), Mode::Real16), 3);
}

// Chapter 12: `add ax,[si] / add si,2 / dec cx / jnz` runs in 7 cycles; `[bx+si]` costs one more
// (indexed addressing). Chapter 21: an immediate with a displacement costs one more.
TEST(Timing486, IndexedAddressingAndImmediateWithDisplacementCostACycle) {
    const std::vector<Insn> loop = code({0x03, 0x04, 0x83, 0xC6, 0x02, 0x49, 0x75, 0xF8}, 16);
    EXPECT_EQ(analyse(loop, Cpu::I486, Mode::Real16, BranchPolicy{}).cycles_per_iteration, 7);
    const std::vector<Insn> indexed = code({0x03, 0x00, 0x83, 0xC6, 0x02, 0x49, 0x75, 0xF8}, 16);
    EXPECT_EQ(analyse(indexed, Cpu::I486, Mode::Real16, BranchPolicy{}).cycles_per_iteration, 8);
    EXPECT_EQ(cycles(code({0xC7, 0x45, 0x10, 0x01, 0x00, 0x00, 0x00}, 32), Mode::Protected32), 2) << "mov dword [ebp+16],1";
    EXPECT_EQ(cycles(code({0x8B, 0x04, 0x8B}, 32), Mode::Protected32), 2) << "mov eax,[ebx+ecx*4]";
    EXPECT_EQ(cycles(code({0x8B, 0x04, 0x24}, 32), Mode::Protected32), 1) << "mov eax,[esp]: ESP as a base is free";
}

// Chapters 13 and 19: a prefix costs a cycle, but decodes while an AGI waits (mov di,ax;
// mov [es:di],al: 3 cycles, not 4) or while the instruction before runs on.
TEST(Timing486, APrefixCostsACycleUnlessItOverlaps) {
    EXPECT_EQ(cycles(code({0x26, 0x88, 0x05}, 16), Mode::Real16), 2);
    EXPECT_EQ(cycles(code({0x89, 0xC7, 0x26, 0x88, 0x05}, 16), Mode::Real16), 3);
    EXPECT_EQ(cycles(code({0x01, 0x04, 0x66, 0x01, 0xCA}, 16), Mode::Real16), 4) << "add [si],ax (3), then add edx,ecx: its prefix hidden";
}

// Chapters 45 and 58: OUT takes 16 cycles in real mode, 10 with full I/O privilege (ring 0); a
// taken Jcc 3, one falling through 1.
TEST(Timing486, OutAndBranches) {
    EXPECT_EQ(cycles(code({0xEE}, 16), Mode::Real16), 16);
    EXPECT_EQ(cycles(code({0xEE}, 32), Mode::Protected32), 10);
    const std::vector<Insn> jz = code({0x74, 0x00}, 32);
    I486 cpu(Mode::Protected32);
    EXPECT_EQ(cpu.run(jz[0], true).clocks, 3);
    EXPECT_EQ(cpu.run(jz[0], false).clocks, 1);
}

// The 486's x87 is not pipelined: an FP instruction waits for the one before; integer work runs
// beside it for its concurrent clocks (FDIV 73, 70 of them concurrent; FMUL 16, 13). FXCH costs 4.
TEST(Timing486, RunsIntegerWorkBesideTheX87) {
    const std::vector<Insn> in = code({0xD8, 0xF1, 0x40, 0x43, 0xD8, 0xC2}, 32);  // fdiv st0,st1; inc eax; inc ebx; fadd st0,st2
    I486 cpu(Mode::Protected32);
    EXPECT_EQ(cpu.run(in[0], false).start, 0);
    EXPECT_EQ(cpu.run(in[1], false).start, 3) << "the divide's 3 clocks of its own";
    EXPECT_EQ(cpu.run(in[2], false).start, 4);
    const Step fadd = cpu.run(in[3], false);
    ASSERT_EQ(fadd.stalls.size(), 1u);
    EXPECT_EQ(fadd.stalls[0], "x87 busy +68") << "the FADD waits for the divide, from cycle 5 to 73";
    EXPECT_EQ(fadd.done, 80) << "then its 8 clocks";
    EXPECT_EQ(cycles(code({0xD9, 0xC9}, 32), Mode::Protected32), 4) << "fxch st1";
    EXPECT_EQ(cycles(code({0xD8, 0xC9, 0x40}, 32), Mode::Protected32), 4) << "fmul st0,st1; inc eax: 3 + 1";
}

TEST(Timing486, RefusesWhatItHasNoTimingFor) {
    EXPECT_THROW(cycles(code({0xD9, 0xFE}, 32), Mode::Protected32), std::runtime_error) << "fsin: no kernel loop runs it";
    EXPECT_THROW(cycles(code({0x0F, 0xA2}, 32), Mode::Protected32), std::runtime_error) << "cpuid";
}

// The calibration: each of chapter 58's listings against its published 486 figure. A residual is
// where the documented rules and the published count part, each explained in docs/cycles.md
// ("Calibration").
struct Published {
    const char* file;
    BranchPolicy branch;
    double residual;  // the model's figure less the published one
    const char* why;
};

class Calibration486 : public ::testing::TestWithParam<Published> {};

TEST_P(Calibration486, TheModelGivesThePublishedFigure) {
    const Published& p = GetParam();
    const Listing l = read_listing(std::string("tests/timing/listings/") + p.file);
    ASSERT_EQ(l.header.count("published"), 1u) << p.file;
    const double published = std::stod(l.header.at("published"));
    const Mode mode = l.bits == 16 ? Mode::Real16 : Mode::Protected32;
    const Report r = analyse(l.insns, Cpu::I486, mode, p.branch);
    EXPECT_EQ(r.cycles_per_iteration, published + p.residual) << p.file << " (" << p.branch.name() << "): " << p.why << "\n" << diagram(r, 1);
}

BranchPolicy policy(BranchPolicy::Kind k, double share = 1) { return BranchPolicy{k, share, {}}; }

INSTANTIATE_TEST_SUITE_P(
    BlackBookChapter58, Calibration486,
    ::testing::Values(
        Published{"l58-2.asm", policy(BranchPolicy::Taken), 0, "both steps without a carry"},
        Published{"l58-2.asm", policy(BranchPolicy::NotTaken), 0, "a carry costs its ADD what the taken JNC costs"},
        Published{"l58-2.asm", policy(BranchPolicy::Share, 0.5), 0, "so every mix of carries takes 22"},
        Published{"l58-3.asm", policy(BranchPolicy::Taken), 0, "no Y carry: no stall"},
        Published{"l58-3.asm", policy(BranchPolicy::NotTaken), 2,
                  "a Y carry ends with AND DH, a byte write two cycles before the next store's address (rule 4), and "
                  "then MOV BL is: two cycles the count leaves out"},
        Published{"l58-4.asm", policy(BranchPolicy::Taken), 0, "the store moved past ADC ESI: no byte write two cycles before it"},
        Published{"l58-4.asm", policy(BranchPolicy::NotTaken), 0, "a carry costs its ADD and AND what the taken JZ costs"},
        Published{"l58-1.asm", policy(BranchPolicy::Share, 0.5), 1,
                  "ROL AL,1: chapter 58 counts 2 cycles, chapter 13 and Intel 3 for the 1-bit form; the model keeps 3"}));

}  // namespace

namespace {

// The analyser's output: a line an instruction, the path's skipped ones marked, the last line the
// figure; and a listing NASM refuses is an error naming the file.
TEST(TimingAnalyser, DiagramJsonAndErrors) {
    const Listing l = read_listing("tests/timing/listings/l58-4.asm");
    EXPECT_EQ(l.bits, 32);
    EXPECT_EQ(l.header.at("pixels"), "1");
    const Report r = analyse(l.insns, Cpu::I486, Mode::Protected32, BranchPolicy{});
    const std::string d = diagram(r, 4);
    EXPECT_NE(d.find("     -     add esi, ecx"), std::string::npos) << d;
    EXPECT_NE(d.find("cycles per iteration: 8\ncycles per pixel: 2\n"), std::string::npos) << d;
    EXPECT_EQ(r.data_branches, 1);
    EXPECT_FALSE(r.loop_branch);
    const std::string j = json(r, 4, "486", "taken");
    EXPECT_NE(j.find("\"cycles_per_pixel\":2.0"), std::string::npos) << j;
    const std::string p5 = diagram(analyse(l.insns, Cpu::Pentium, Mode::Protected32, BranchPolicy{}), 1);
    EXPECT_NE(p5.find("     1 U 1   mov bl, byte ptr [esi]\n     1 V 1   add edx, ebp\n"), std::string::npos) << "its pipes: " << p5;

    const std::string bad = testing::TempDir() + "bad." + std::to_string(getpid()) + ".asm";
    FILE* f = std::fopen(bad.c_str(), "w");
    std::fputs("bits 32\n  movv eax, 1\n", f);
    std::fclose(f);
    try {
        read_listing(bad);
        FAIL() << "NASM took it";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(bad + ": NASM refused it"), std::string::npos) << e.what();
    }
}

}  // namespace
