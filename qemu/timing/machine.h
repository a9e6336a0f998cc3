// A whole run through a timing model (docs/cycles.md, "Whole frames"): the instructions a program
// executes, fed one at a time as they run, with what they did on the bus (a write to display
// memory, an OUT), cycles charged to the phase the program marks, and the display bus as a bus
// model charges it. The QEMU plugin (qemu/plugin) feeds it; so can a test.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <vector>

#include "qemu/timing/analyse.h"
#include "qemu/timing/i486.h"
#include "qemu/timing/p5.h"

namespace timing {

// The display bus: what a write to display memory and an OUT cost there, in nanoseconds, and the
// CPU's clock and write buffer (docs/cycles.md has each preset's sources).
struct Bus {
    std::string name;
    double cpu_mhz = 0;
    double write_ns[3] = {};  // a byte, a word, a dword written to display memory, on the bus
    double out_ns = 0;        // an OUT's or an IN's bus cycle (beside the instruction's own clocks)
    int write_buffer = 0;     // writes the CPU posts before it waits

    // zero-wait, isa, vlb for a CPU; throws for another name
    static Bus preset(const std::string& name, Cpu cpu);
    int write_cycles(int bytes) const;
    int out_cycles() const;
};

// What one instruction did beside running: a write of `bytes` to display memory, and a mark.
struct Effects {
    uint8_t display_write = 0;  // bytes written to display memory (0: none)
    int8_t mark = -1;           // the mark it wrote (Machine::Mark), -1: none
};

class Machine {
public:
    // The marks a program writes (by address: the plugin sees where, not what), as the bench
    // probe lays them out (kernel/core/probe.h): a lap closing a phase, the probe's start, the same
    // two for the probe that calibrates a lap's cost, a frame's start and end, and the end of a
    // run of frames (a bench row).
    enum Mark : int8_t {
        Setup, Walk, Inner, Choose, ProbeStart,
        CalibrationLap, CalibrationStart = CalibrationLap + ProbeStart,
        FrameStart, FrameEnd, RowEnd, MarkCount
    };
    static constexpr int PHASES = 4;

    // What it counted between two RowEnd marks.
    struct Row {
        uint64_t frames = 0;
        uint64_t frame_cycles = 0;           // between FrameStart and FrameEnd, summed
        uint64_t phase_cycles[PHASES] = {};  // each lap's interval, charged to the phase it closes
        uint64_t laps[PHASES] = {};
        uint64_t phase_instructions[PHASES] = {};  // the instructions of those intervals, laps included
        uint64_t lap_cost = 0;               // a lap's own cycles, as the probe calibrates it
        uint64_t instructions = 0, unmodelled = 0;  // of the frames
        uint64_t display_writes = 0, outs = 0, bus_stall = 0;  // of the frames (outs: OUT and IN); bus_stall in cycles
        std::map<std::string, uint64_t> unknown;  // the unmodelled instructions of the frames, by mnemonic
        // the phase's cycles without the laps' own
        uint64_t net(int phase) const {
            const uint64_t cost = lap_cost * laps[phase];
            return phase_cycles[phase] > cost ? phase_cycles[phase] - cost : 0;
        }
    };

    // One CPU model, and a bus model for each of `buses`: the buses' stalls leave the CPU model as
    // it is, so one run gives each bus its own cycles and rows.
    Machine(Cpu cpu, int precision, const std::vector<Bus>& buses);
    Machine(Cpu cpu, int precision, const Bus& bus) : Machine(cpu, precision, std::vector<Bus>{bus}) {}

    // The next instruction as it ran (`taken`: it jumped to its target), with its effects.
    // `modelled` false: the models have no timing for it; it runs as a one-cycle instruction and
    // is counted (a row's `unmodelled`, by mnemonic in its `unknown`).
    void feed(const Insn* in, bool taken, Effects fx, bool modelled);
    // The instructions fed so far, issued (the Pentium holds two back to pair them).
    void flush();

    // the cycles so far, and the rows, with bus `k`'s stalls
    long cycles(size_t k = 0) const;
    const std::vector<Row>& rows(size_t k = 0) const { return tracks_[k].rows; }
    const Bus& bus(size_t k) const { return tracks_[k].bus; }
    size_t buses() const { return tracks_.size(); }

    // Whether a model has a timing for `in` (what feed()'s `modelled` says).
    static bool modelled(const Insn& in, Cpu cpu);

private:
    struct Pending {
        const Insn* in = nullptr;
        bool taken = false;
        Effects fx;
        const Insn* original = nullptr;  // the instruction where `in` is the stand-in
    };
    // A bus and what it counts: the posted writes, its stalls so far (added to the CPU model's
    // cycles), the marks' state, the rows.
    struct Track {
        Bus bus;
        std::deque<long> buffer;  // the cycles the posted writes reach the display in
        long bus_free = 0;
        long delayed = 0;
        long lap_from = 0, frame_from = -1, calibration_from = 0;
        long lap_cost = -1;
        uint64_t since_lap = 0;   // instructions since the last lap or probe start
        bool in_frame = false;
        Row row;
        std::vector<Row> rows;
    };
    void issue_pentium();
    void issued(const Pending& p, long cycle);
    long bus_wait(Track& t, const Pending& p, long now) const;
    void mark(Track& t, int8_t m, long cycle);
    long model_cycles() const { return cpu_ == Cpu::I486 ? i486_.now() : p5_.now(); }

    Cpu cpu_;
    I486 i486_;
    P5 p5_;
    std::array<Pending, 3> window_{};  // the Pentium's instructions held back to pair (`held_` of them)
    int held_ = 0;
    std::array<P5Issue, 2> issues_;     // (kept: the Pentium's issues of the pair in hand)
    Insn stand_in_;                     // an unmodelled instruction, as the models run it
    std::vector<Track> tracks_;
};

}  // namespace timing
