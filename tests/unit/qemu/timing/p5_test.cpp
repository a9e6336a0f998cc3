// The Pentium timing model: each documented rule on the example its source gives (the Black Book's
// chapters 19 to 21), and the calibration on the published Pentium loops (fatmap.txt, fatmap2.txt,
// the Black Book's L58-4), with the residuals docs/cycles.md explains.
#include <gtest/gtest.h>

#include <unistd.h>

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
    const std::string path = testing::TempDir() + "p5_test." + std::to_string(getpid()) + ".asm";  // (test runs side by side)
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

TEST(TimingP5, RefusesWhatItHasNoTimingFor) {
    EXPECT_THROW(cycles(asm32("cpuid\n")), std::runtime_error);
    EXPECT_THROW(cycles(asm32("fsin\n")), std::runtime_error);
}

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

// (a listing's `run: once` and `precision` header lines as the tool reads them; its figure per pixel
// where it draws more than one)
TEST_P(CalibrationPentium, TheModelGivesThePublishedFigure) {
    const Published& p = GetParam();
    const Listing l = read_listing(std::string("tests/timing/listings/") + p.file);
    ASSERT_EQ(l.header.count(p.key), 1u) << p.file;
    const double published = std::stod(l.header.at(p.key));
    Options o;
    o.once = l.header.count("run") && l.header.at("run") == "once";
    if (l.header.count("precision")) o.precision = std::stoi(l.header.at("precision"));
    const int pixels = l.header.count("pixels") ? std::stoi(l.header.at("pixels")) : 1;
    const Report r = analyse(l.insns, Cpu::Pentium, Mode::Protected32, p.branch, o);
    EXPECT_NEAR(r.cycles_per_iteration / pixels, published + p.residual, 0.0005) << p.file << " (" << p.branch.name() << "): " << p.why << "\n"
                                                                                 << diagram(r, pixels);
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
    ::testing::Values(Published{"l58-4.asm", "published-pentium", {BranchPolicy::Taken, 1, {}}, -1.5,
                                "no carry: TEST DH,80h pairs with nothing (only TEST with the accumulator does, Table 20.1) and JZ "
                                "then runs alone in U: 4 cycles"},
                      Published{"l58-4.asm", "published-pentium", {BranchPolicy::NotTaken, 0, {}}, 0.5,
                                "a carry: 4, then ADD ESI/AND DH, then the AGI on ESI the text names: 6"},
                      Published{"l58-4.asm", "published-pentium", {BranchPolicy::Share, 0.5, {}}, 1.036,
                                "half the pixels carry, at random: the mean of 4 and 6, 5, and the branch mispredicted by the "
                                "two-bit counter about half the time, 3 cycles each"}));

INSTANTIATE_TEST_SUITE_P(
    BlackBookChapter63, CalibrationPentium,
    ::testing::Values(Published{"l63-2.asm", "published", {}, 0, "as published, each instruction in the cycle the book gives"},
                      Published{"l63-3.asm", "published", {}, 0, "as published, each instruction in the cycle the book gives"},
                      Published{"l63-4.asm", "published", {}, 0, "as published, each instruction in the cycle the book gives"},
                      Published{"l63-5.asm", "published", {}, 0, "as published, each instruction in the cycle the book gives"},
                      Published{"l63-6.asm", "published", {}, 0, "as published (one FXCH a cycle earlier than the book marks it)"}));

INSTANTIATE_TEST_SUITE_P(
    QuakeSpans, CalibrationPentium,
    ::testing::Values(Published{"quake-d_draw16.asm", "published", {BranchPolicy::Taken, 1, {}}, -0.3125,
                                "t's step within a texel (LZero): 115 cycles a segment, the FDIV hidden under the pixels; the book's "
                                "7.5 is the routine's, over both paths"},
                      Published{"quake-d_draw16.asm", "published", {BranchPolicy::NotTaken, 0, {}}, 0.375,
                                "the IMUL path: its 10 cycles unpaired, and an unpaired JMP, 11 more: 126"},
                      Published{"quake-d_draw16.asm", "published", {BranchPolicy::Share, 0.5, {}}, 0.16131591796875,
                                "the two paths at random: their mean, 120.5, and the LZero branch mispredicted about half the time"}));

}  // namespace

namespace {

// Chapter 63's rules on its own examples: FADD, FSUB and FMUL pipelined, each result 3 cycles on
// (FADD ST(0),ST(2) / FSUB ST(0),ST(1): 2 stall cycles between); an FMUL every other cycle, FMUL /
// FLD / FMUL as fast as two FMULs; FMUL ST(0),ST(1) / FST [temp]: 6 cycles in all.
TEST(TimingX87P5, PipelinesAddAndMultiply) {
    auto issued = [](const std::string& code) {
        const std::vector<Insn> in = asm32(code);
        std::vector<Executed> s;
        for (const Insn& i : in) s.push_back(Executed{&i, false});
        std::vector<long> out;
        for (const P5Issue& is : P5().run(s)) out.push_back(is.cycle);
        return out;
    };
    EXPECT_EQ(issued("fadd st0,st2\nfsub st0,st1\n"), (std::vector<long>{0, 3}));
    EXPECT_EQ(issued("fadd st0,st2\nfsub st1,st0\n"), (std::vector<long>{0, 3})) << "reads the sum";
    EXPECT_EQ(issued("fadd st1,st0\nfsub st2,st0\n"), (std::vector<long>{0, 1})) << "independent: pipelined";
    EXPECT_EQ(issued("fmul st1,st0\nfmul st2,st0\n"), (std::vector<long>{0, 2}));
    EXPECT_EQ(issued("fmul st1,st0\nfld dword [var]\nfmul st3,st0\n"), (std::vector<long>{0, 1, 2}));
    Options once;
    once.once = true;
    EXPECT_EQ(analyse(asm32("fmul st0,st1\nfst dword [var]\n"), Cpu::Pentium, Mode::Protected32, {}, once).cycles_per_iteration, 6);
    EXPECT_EQ(analyse(asm32("fld dword [var]\nfst dword [var2]\n"), Cpu::Pentium, Mode::Protected32, {}, once).cycles_per_iteration, 3)
        << "a loaded value stores at once";
}

// FDIV: 19, 33 or 39 cycles by the precision control; integer work runs beside it but for its first
// cycle; the next FP instruction and an IMUL wait for it (chapter 63). FXCH pairs with the FP
// instruction before it and is free, unless an integer instruction follows (AP-500).
TEST(TimingX87P5, OverlapsTheDivideAndPairsFxch) {
    for (auto [precision, cycles] : {std::pair{24, 19}, {53, 33}, {64, 39}}) {
        const std::vector<Insn> in = asm32("fdiv st0,st1\nadd eax,ebx\ninc ecx\nfadd st0,st2\nimul edx,esi\n");
        std::vector<Executed> s;
        for (const Insn& i : in) s.push_back(Executed{&i, false});
        const std::vector<P5Issue> is = P5(precision).run(s);
        EXPECT_EQ(is[1].cycle, 1) << "integer work beside the divide";
        EXPECT_EQ(is[2].cycle, 1);
        EXPECT_EQ(is[3].cycle, cycles) << "the FADD waits for the divide at precision " << precision;
        const std::vector<Insn> m = asm32("fdiv st0,st1\nimul edx,esi\n");
        std::vector<Executed> ms;
        for (const Insn& i : m) ms.push_back(Executed{&i, false});
        EXPECT_EQ(P5(precision).run(ms)[1].cycle, cycles) << "IMUL runs on the FPU's multiplier";
    }
    EXPECT_EQ(cycles(asm32("fadd st0,st1\nfxch st2\nfmul st0,st3\n")), 2) << "FADD and FXCH paired, then FMUL";
    EXPECT_EQ(cycles(asm32("fadd st0,st1\nfxch st2\ninc eax\n")), 3) << "an integer instruction after the FXCH";
    EXPECT_EQ(cycles(asm32("fxch st1\nfxch st2\n")), 2) << "FXCH after FXCH: each alone";
    EXPECT_EQ(cycles(asm32("fld dword [var]\ninc eax\n")), 2) << "an FP instruction pairs with nothing else";
}

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

// quake-d_draw16 against d_draw16.s's segment as transcribed: the same instructions, but for what
// the listing leaves out, instruction by instruction. Our loop keeps the four clamp tests' jumps
// (falling through: on the 486 a cycle each; on the Pentium each pairs with its CMP where the
// listing's CMPs pair two by two, 2 cycles more), and the two jumps the listing's rotation drops:
// JA to the next segment's FDIV (taken: 3 cycles on the 486, paired and predicted on the Pentium)
// and the loop's JA back (3 on the 486; alone in U on the Pentium, a cycle). Paths: the LZero
// branch taken or not (the listing's one branch; ours first of three, the other two taken).
TEST(FaithfulLoops, QuakesSpanLoopTakesWhatItsListingTakesButItsJumps) {
    const Listing ours = read_mapper_loop("quake-d_draw16", "build/kernel/asm");
    const Listing theirs = read_listing("tests/timing/listings/quake-d_draw16.asm");
    ASSERT_EQ(ours.header.at("precision"), "24");
    Options o;
    o.precision = 24;
    for (auto [cpu, jumps] : {std::pair{Cpu::I486, 4 + 3 + 3}, {Cpu::Pentium, 2 + 1}}) {
        for (auto [path, listing_path] : {std::pair{"ttt", "t"}, {"ntt", "n"}}) {
            BranchPolicy a, b;
            a.kind = b.kind = BranchPolicy::Pattern, a.pattern = path, b.pattern = listing_path;
            const Report r = analyse(ours.insns, cpu, Mode::Protected32, a, o), l = analyse(theirs.insns, cpu, Mode::Protected32, b, o);
            EXPECT_EQ(r.exits, 4);
            EXPECT_EQ(r.cycles_per_iteration, l.cycles_per_iteration + jumps)
                << (cpu == Cpu::I486 ? "486 " : "Pentium ") << path << "\nours:\n" << diagram(r, 16) << "theirs:\n" << diagram(l, 16);
        }
    }
}

// xsharp-column runs two bodies of L58-4 a pass (two pixels, a column's rows 80 bytes apart), then its
// own loop control: ADD EDI (a cycle), DEC of the count in memory (3), JNZ back (3 on the 486). On a
// Y carry (the branches not taken) the 486 charges DEC a cycle more: it addresses memory two cycles
// after AND DH, a byte write (chapter 12, rule 4). On the Pentium the ADD and the DEC pair in
// lockstep (3) and the JNZ runs alone (1); on a carry, the second body's AGI on ESI falls in those
// cycles instead of on the next pass's first MOV: that body takes 5, not 6.
TEST(FaithfulLoops, XSharpsColumnLoopIsTwoBodiesOfL58_4AndItsLoopControl) {
    const Listing ours = read_mapper_loop("xsharp-column", "build/kernel/asm");
    const Listing theirs = read_listing("tests/timing/listings/l58-4.asm");
    struct Case {
        Cpu cpu;
        BranchPolicy::Kind branch;
        double control;  // ours less two bodies of the listing
    };
    for (const Case& c : {Case{Cpu::I486, BranchPolicy::Taken, 1 + 3 + 3}, Case{Cpu::I486, BranchPolicy::NotTaken, 1 + 3 + 1 + 3},
                          Case{Cpu::Pentium, BranchPolicy::Taken, 3 + 1}, Case{Cpu::Pentium, BranchPolicy::NotTaken, 3 + 1 - 1}}) {
        BranchPolicy b;
        b.kind = c.branch;
        const Report r = analyse(ours.insns, c.cpu, Mode::Protected32, b), l = analyse(theirs.insns, c.cpu, Mode::Protected32, b);
        EXPECT_EQ(r.cycles_per_iteration, 2 * l.cycles_per_iteration + c.control)
            << (c.cpu == Cpu::I486 ? "486 " : "Pentium ") << b.name() << "\nours:\n" << diagram(r, 2) << "theirs:\n" << diagram(l, 1);
    }
}

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

namespace {

// A conditional jump out of the body is the loop's exit, not taken while it runs; a JMP out of it
// leaves no loop to analyse.
TEST(TimingAnalyser, AJumpOutOfTheBodyIsTheLoopsExit) {
    const Report r = analyse(asm32("top:\ndec ecx\njz 0x2000\ninc eax\njmp top\n"), Cpu::Pentium, Mode::Protected32, {});
    EXPECT_EQ(r.exits, 1);
    EXPECT_EQ(r.data_branches, 0);
    EXPECT_NE(diagram(r, 1).find("jumps out of the loop, not taken while it runs: 1\n"), std::string::npos) << diagram(r, 1);
    EXPECT_EQ(analyse(asm32("top:\ndec ecx\njz 0x2000\ninc eax\njmp top\n"), Cpu::I486, Mode::Protected32, {}).cycles_per_iteration, 6)
        << "dec 1, jz falling through 1, inc 1, jmp 3";
    EXPECT_THROW(analyse(asm32("dec ecx\njmp 0x2000\n"), Cpu::Pentium, Mode::Protected32, {}), std::runtime_error);
    BranchPolicy two;
    two.kind = BranchPolicy::Pattern, two.pattern = "tn";
    EXPECT_THROW(analyse(asm32("top:\ndec ecx\njz over\ninc eax\nover:\njmp top\n"), Cpu::Pentium, Mode::Protected32, two), std::runtime_error)
        << "a pattern of two for one branch";
}

}  // namespace
