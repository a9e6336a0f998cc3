// The whole-run engine (qemu/timing/machine.h) without QEMU: instructions fed one at a time take
// what the static analyser gives their loop; the marks split the cycles into the probe's phases,
// less the lap cost the calibrating probe shows; the bus model posts display writes and stalls when
// its buffer is full, an OUT waits for the posted writes; an instruction the models do not know
// runs as a counted one-cycle stand-in.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "qemu/timing/analyse.h"
#include "qemu/timing/decode.h"
#include "qemu/timing/listing.h"
#include "qemu/timing/machine.h"

namespace {

using namespace timing;

std::vector<Insn> code(std::vector<uint8_t> bytes) { return decode(bytes.data(), bytes.size(), 32); }

// Feeds `iterations` runs of a loop body, its last branch taken.
void feed_loop(Machine& m, const std::vector<Insn>& body, int iterations, Effects fx = {}) {
    for (int k = 0; k < iterations; ++k)
        for (size_t i = 0; i < body.size(); ++i) m.feed(&body[i], i + 1 == body.size(), fx, true);
}

TEST(TimingMachine, ALoopFedAsItRunsTakesWhatTheAnalyserGives) {
    const Listing l = read_listing("tests/timing/listings/fatmap-lut.asm");
    for (Cpu cpu : {Cpu::I486, Cpu::Pentium}) {
        Machine m(cpu, 53, Bus::preset("zero-wait", cpu));
        feed_loop(m, l.insns, 50);
        const long at50 = m.cycles();  // (the Pentium holds the same instructions back at both)
        feed_loop(m, l.insns, 100);
        const double per_iteration = double(m.cycles() - at50) / 100;
        EXPECT_EQ(per_iteration, analyse(l.insns, cpu, Mode::Protected32, {}).cycles_per_iteration) << (cpu == Cpu::I486 ? "486" : "Pentium");
    }
}

TEST(TimingMachine, MarksSplitTheCyclesIntoPhasesLessTheLapCost) {
    const std::vector<Insn> nop = code({0x90});
    for (Cpu cpu : {Cpu::I486, Cpu::Pentium}) {
        Machine m(cpu, 53, Bus::preset("zero-wait", cpu));
        auto run = [&](int count, int8_t mark) {
            for (int k = 0; k < count; ++k) m.feed(&nop[0], false, Effects{0, k + 1 == count ? mark : int8_t(-1)}, true);
        };
        // the calibrating probe: laps 6 instructions apart, then one 4 apart: its least counts
        run(3, Machine::CalibrationStart);
        run(6, Machine::CalibrationLap);
        run(4, Machine::CalibrationLap);
        run(9, Machine::CalibrationLap);
        run(5, Machine::FrameStart);
        run(40, Machine::FrameEnd);
        run(2, Machine::ProbeStart);
        run(20, Machine::Setup);
        run(30, Machine::Inner);
        run(10, Machine::Inner);
        run(1, Machine::RowEnd);
        m.flush();
        ASSERT_EQ(m.rows().size(), 1u);
        const Machine::Row& r = m.rows()[0];
        // a NOP a cycle on the 486, two a cycle paired on the Pentium
        const uint64_t per = cpu == Cpu::I486 ? 1 : 2;
        EXPECT_EQ(r.lap_cost, 4 / per);
        EXPECT_EQ(r.frames, 1u);
        EXPECT_EQ(r.frame_cycles, 40 / per);
        EXPECT_EQ(r.instructions, 40u) << "the instructions of the frame";
        EXPECT_EQ(r.net(Machine::Setup), (20 - 4) / per);
        EXPECT_EQ(r.net(Machine::Inner), (40 - 8) / per);
        EXPECT_EQ(r.laps[Machine::Inner], 2u);
        EXPECT_EQ(r.net(Machine::Walk), 0u);
    }
}

TEST(TimingMachine, TheBusPostsWritesAndStallsWhenItsBufferIsFull) {
    // mov [edi],eax (a dword to display memory) ten times on the 486 over ISA: 24 cycles a write
    // at 33 MHz (720 ns); the buffer takes 4, then each write waits for the oldest
    const std::vector<Insn> store = code({0x89, 0x07});
    const Bus isa = Bus::preset("isa", Cpu::I486);
    ASSERT_EQ(isa.write_cycles(4), 24);
    ASSERT_EQ(isa.write_cycles(1), 12);
    Machine m(Cpu::I486, 53, isa);
    m.feed(&store[0], false, Effects{0, Machine::FrameStart}, true);
    for (int k = 0; k < 10; ++k) m.feed(&store[0], false, Effects{4, -1}, true);
    m.feed(&store[0], false, Effects{0, Machine::FrameEnd}, true);
    m.feed(&store[0], false, Effects{0, Machine::RowEnd}, true);
    const Machine::Row& r = m.rows().at(0);
    EXPECT_EQ(r.display_writes, 10u);
    // four writes are posted; from the fifth on, each waits for a slot, the bus taking 24 cycles a
    // write: the tenth is posted at cycle 146
    EXPECT_EQ(r.frame_cycles, 146u);
    EXPECT_EQ(r.bus_stall, 146u - 11u);
    // an OUT waits for what is posted, then its own bus cycle (600 ns: 20 cycles)
    const std::vector<Insn> out = code({0xEE});  // out dx,al
    Machine o(Cpu::I486, 53, isa);
    o.feed(&store[0], false, Effects{4, -1}, true);
    o.feed(&out[0], false, Effects{}, true);
    EXPECT_EQ(o.cycles(), 1 + 24 + 20) << "the write's 24 from cycle 1, then the OUT's 20 (its own 10 run beside)";
    // zero-wait: no stall at all
    Machine z(Cpu::I486, 53, Bus::preset("zero-wait", Cpu::I486));
    for (int k = 0; k < 10; ++k) z.feed(&store[0], false, Effects{4, -1}, true);
    EXPECT_EQ(z.cycles(), 10);
    EXPECT_THROW(Bus::preset("pci", Cpu::I486), std::runtime_error);
}

// Buses side by side in one run: each its own stalls, the CPU model's cycles shared.
TEST(TimingMachine, CountsEachBusOfOneRun) {
    const std::vector<Insn> store = code({0x89, 0x07});  // mov [edi],eax
    Machine m(Cpu::Pentium, 53, std::vector<Bus>{Bus::preset("zero-wait", Cpu::Pentium), Bus::preset("isa", Cpu::Pentium)});
    for (int k = 0; k < 20; ++k) m.feed(&store[0], false, Effects{4, -1}, true);
    m.flush();
    ASSERT_EQ(m.buses(), 2u);
    EXPECT_EQ(m.bus(1).name, "isa");
    EXPECT_EQ(m.cycles(0), 20) << "paired, each pair a bank conflict: a store a cycle";
    // ISA at 90 MHz: 65 cycles a dword; two posted: the twentieth waits until 18 have left the bus
    EXPECT_EQ(Bus::preset("isa", Cpu::Pentium).write_cycles(4), 65);
    EXPECT_GE(m.cycles(1), 18 * 65);
}

TEST(TimingMachine, AnInstructionWithoutATimingRunsAsACountedStandIn) {
    const std::vector<Insn> in = code({0x0F, 0xA2, 0x90});  // cpuid; nop
    EXPECT_FALSE(Machine::modelled(in[0], Cpu::Pentium));
    EXPECT_TRUE(Machine::modelled(in[1], Cpu::Pentium));
    Machine m(Cpu::I486, 53, Bus::preset("zero-wait", Cpu::I486));
    m.feed(&in[1], false, Effects{0, Machine::FrameStart}, true);
    m.feed(&in[0], false, Effects{}, false);
    m.feed(&in[1], false, Effects{0, Machine::FrameEnd}, true);
    m.feed(&in[1], false, Effects{0, Machine::RowEnd}, true);
    EXPECT_EQ(m.cycles(), 4) << "the stand-in takes a cycle";
    EXPECT_EQ(m.rows().at(0).unmodelled, 1u);
    EXPECT_EQ(m.rows().at(0).unknown.at("cpuid"), 1u);
}

}  // namespace
