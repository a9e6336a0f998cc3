// The Pentium timing model: each documented rule on the example its source gives (the Black Book's
// chapters 19 to 21), and the calibration on the published Pentium loops (fatmap.txt, fatmap2.txt,
// the Black Book's L58-4), with the residuals docs/cycles.md explains.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "qemu/timing/analyse.h"
#include "qemu/timing/listing.h"
#include "qemu/timing/p5.h"

namespace {

using namespace timing;

// `code` assembled by NASM in 32-bit mode.
std::vector<Insn> asm32(const std::string& code) {
    const std::string path = testing::TempDir() + "p5_test.asm";
    FILE* f = std::fopen(path.c_str(), "w");
    std::fputs(("bits 32\nvar equ 0x1000\nvar2 equ 0x1044\n" + code).c_str(), f);
    std::fclose(f);
    return read_listing(path).insns;
}

// The cycles the instructions take run once, in order, from an idle machine (branches taken).
long cycles(const std::vector<Insn>& insns) {
    std::vector<Executed> s;
    for (const Insn& in : insns) s.push_back(Executed{&in, true});
    const std::vector<P5Issue> issues = P5().run(s);
    return issues.back().cycle + issues.back().clocks;
}

// Chapter 21: a register an instruction writes cannot be read or written by the one it would pair
// with (inc eax / and ebx,eax: 2 cycles; sub eax,eax / mov al,[var]: 2; AL and AH are one register:
// mov al,bh / mov ah,ch, 2); a register read, then written, pairs (mov eax,edx / sub edx,edx: 1);
// a flag writer pairs with the branch that reads them (dec ecx / jnz: 1).
TEST(TimingP5, RegisterContentionAndItsExceptions) {
    EXPECT_EQ(cycles(asm32("inc eax\nand ebx,eax\n")), 2);
    EXPECT_EQ(cycles(asm32("sub eax,eax\nmov al,[var]\n")), 2);
    EXPECT_EQ(cycles(asm32("mov al,bh\nmov ah,ch\n")), 2);
    EXPECT_EQ(cycles(asm32("mov eax,edx\nsub edx,edx\n")), 1);
    EXPECT_EQ(cycles(asm32("top: dec ecx\njnz top\n")), 5) << "a pair; its branch, not yet in the buffer, mispredicted in V: 5";
    EXPECT_EQ(cycles(asm32("add eax,1\nadd ebx,2\n")), 1) << "two flag writers pair";
}

// Chapter 19: add edx,4 / mov ecx,[ebx] / add ebx,4 / mov [edx],ecx takes 3 cycles (an AGI on EDX);
// reordered as mov ecx,[ebx] / add ebx,4 / mov [edx+4],ecx / add edx,4, 2.
TEST(TimingP5, TheAddressGenerationInterlock) {
    EXPECT_EQ(cycles(asm32("add edx,4\nmov ecx,[ebx]\nadd ebx,4\nmov [edx],ecx\n")), 3);
    EXPECT_EQ(cycles(asm32("mov ecx,[ebx]\nadd ebx,4\nmov [edx+4],ecx\nadd edx,4\n")), 2);
}

// Chapter 20: a pair in lockstep (add [ebx],edx / inc eax: 3 cycles); two memory-destination
// instructions overlap a cycle only (and [ebx],al / and [ecx],dl: 5); two reads from memory pair
// fully (add esi,[var] / add edi,[var2]: 2); the same bank of the data cache stalls V a cycle
// (mov bl,[esi] / mov cl,[esi+1]: 2).
TEST(TimingP5, LockstepMemoryPairsAndBankConflicts) {
    EXPECT_EQ(cycles(asm32("add [ebx],edx\ninc eax\n")), 3);
    EXPECT_EQ(cycles(asm32("and [ebx],al\nand [ecx],dl\n")), 5);
    EXPECT_EQ(cycles(asm32("add esi,[var]\nadd edi,[var2]\n")), 2);
    EXPECT_EQ(cycles(asm32("mov bl,[esi]\nmov cl,[esi+1]\n")), 2);
    EXPECT_EQ(cycles(asm32("mov bl,[esi]\nmov cl,[esi+4]\n")), 1);
    EXPECT_EQ(cycles(asm32("add esi,[var]\nadd edi,[var+64]\n")), 3) << "64 bytes apart: the same bank";
}

// Chapters 19 to 21: a prefix is a cycle of its own in U, its instruction then pairs (mov ax,bx /
// inc ecx: 2); a shift by CL takes 4 and pairs with nothing; an immediate with a displacement
// cannot pair (mov dword [ebp+16],1 / inc ecx: 2); PUSH and POP change ESP without contention.
TEST(TimingP5, PrefixesShiftsByClImmediatesAndTheStack) {
    EXPECT_EQ(cycles(asm32("mov ax,bx\ninc ecx\n")), 2);
    EXPECT_EQ(cycles(asm32("shr edx,cl\ninc ecx\n")), 5);
    EXPECT_EQ(cycles(asm32("mov dword [ebp+16],1\ninc ecx\n")), 2);
    EXPECT_EQ(cycles(asm32("mov dword [ebx],1\ninc ecx\n")), 1);
    EXPECT_EQ(cycles(asm32("mov eax,[var]\npush esi\npush eax\npush edi\npush ebx\n")), 3);
}

TEST(TimingP5, RefusesWhatItHasNoTimingFor) { EXPECT_THROW(cycles(asm32("imul eax,ebx\n")), std::runtime_error); }

// The calibration on the Pentium's published loops; a residual is where the documented rules and
// the published count part (docs/cycles.md, "Calibration").
struct Published {
    const char* file;
    const char* key;  // the header line with the Pentium figure
    BranchPolicy branch;
    double residual;
    const char* why;
};

class CalibrationPentium : public ::testing::TestWithParam<Published> {};

TEST_P(CalibrationPentium, TheModelGivesThePublishedFigure) {
    const Published& p = GetParam();
    const Listing l = read_listing(std::string("tests/timing/listings/") + p.file);
    ASSERT_EQ(l.header.count(p.key), 1u) << p.file;
    const double published = std::stod(l.header.at(p.key));
    const Report r = analyse(l.insns, Cpu::Pentium, Mode::Protected32, p.branch);
    EXPECT_NEAR(r.cycles_per_iteration, published + p.residual, 0.0005) << p.file << " (" << p.branch.name() << "): " << p.why << "\n" << diagram(r, 1);
}

INSTANTIATE_TEST_SUITE_P(
    Fatmap, CalibrationPentium,
    ::testing::Values(Published{"fatmap-a.asm", "published", {}, 0, "as published"},
                      Published{"fatmap-combined.asm", "published", {}, 0, "as published"},
                      Published{"fatmap-lut.asm", "published", {}, 0, "as published"},
                      Published{"fatmap2-simmons.asm", "published", {}, 0, "as published"},
                      Published{"fatmap2-arbitrary.asm", "published", {}, 0, "as published"},
                      Published{"fatmap2-tiled.asm", "published", {}, 1,
                                "LEA EBP,[EAX+EBX] needs EBX the cycle after AND EBX wrote it: an AGI the count leaves out"}));

INSTANTIATE_TEST_SUITE_P(
    BlackBookL58_4, CalibrationPentium,
    ::testing::Values(Published{"l58-4.asm", "published-pentium", {BranchPolicy::Taken, 1}, -1.5,
                                "no carry: TEST DH,80h pairs with nothing (only TEST with the accumulator does, Table 20.1) and JZ "
                                "then runs alone in U: 4 cycles"},
                      Published{"l58-4.asm", "published-pentium", {BranchPolicy::NotTaken, 0}, 0.5,
                                "a carry: 4, then ADD ESI/AND DH, then the AGI on ESI the text names: 6"},
                      Published{"l58-4.asm", "published-pentium", {BranchPolicy::Share, 0.5}, 1.036,
                                "half the pixels carry, at random: the mean of 4 and 6, 5, and the branch mispredicted by the "
                                "two-bit counter about half the time, 3 cycles each"}));

}  // namespace

namespace {

// Our loops faithful to a published one take what it takes: each registered mapper's NASM inner
// loop, straight from the kernel's object, against its listing, on both CPUs (make listing).
struct Faithful {
    const char* mapper;
    const char* listing;
};

class FaithfulLoops : public ::testing::TestWithParam<Faithful> {};

TEST_P(FaithfulLoops, TakeWhatThePublishedLoopTakes) {
    const Faithful& f = GetParam();
    const Listing ours = read_mapper_loop(f.mapper, "build/kernel/asm");
    const Listing theirs = read_listing(std::string("tests/timing/listings/") + f.listing);
    for (Cpu cpu : {Cpu::I486, Cpu::Pentium}) {
        const Report a = analyse(ours.insns, cpu, Mode::Protected32, BranchPolicy{});
        const Report b = analyse(theirs.insns, cpu, Mode::Protected32, BranchPolicy{});
        EXPECT_EQ(a.cycles_per_iteration, b.cycles_per_iteration) << f.mapper << " against " << f.listing << (cpu == Cpu::I486 ? " (486)" : " (Pentium)")
                                                                   << "\nours:\n" << diagram(a, 1) << "theirs:\n" << diagram(b, 1);
    }
}

INSTANTIATE_TEST_SUITE_P(Fatmap, FaithfulLoops,
                         ::testing::Values(Faithful{"fatmap-256", "fatmap-combined.asm"}, Faithful{"fatmap-256-16", "fatmap2-simmons.asm"},
                                           Faithful{"fatmap-lut", "fatmap-lut.asm"}));

TEST(FaithfulLoops, AMapperWithoutANasmLoopIsSaidSo) {
    EXPECT_THROW(read_mapper_loop("affine", "build/kernel/asm"), std::runtime_error);
    EXPECT_THROW(read_mapper_loop("nosuch", "build/kernel/asm"), std::runtime_error);
}

}  // namespace

namespace {

// Chapter 21: PUSH and POP change ESP without an AGI on the next stack access, but an explicit
// write of ESP (sub esp,8) stalls a PUSH that follows it.
TEST(TimingP5, TheStackPointersAgi) {
    EXPECT_EQ(cycles(asm32("push eax\npush ebx\npush ecx\npush edx\n")), 2);
    EXPECT_EQ(cycles(asm32("sub esp,8\nnop\npush eax\n")), 3) << "written in cycle 1: the push waits for cycle 3";
    EXPECT_EQ(cycles(asm32("mov esp,ebp\nnop\nnop\nnop\npush eax\n")), 3) << "two cycles on: none";
}

}  // namespace
