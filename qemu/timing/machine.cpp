// The whole-run engine (machine.h).
#include "qemu/timing/machine.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace timing {

Bus Bus::preset(const std::string& name, Cpu cpu) {
    // docs/cycles.md, "The bus model", gives each figure's source. The 486 runs at 33 MHz, the
    // clock of the Black Book's measurements of the ISA bus; the Pentium at 90. The 486 posts 4
    // writes; the Pentium 2, one buffer a pipe.
    Bus b;
    b.name = name;
    b.cpu_mhz = cpu == Cpu::I486 ? 33 : 90;
    b.write_buffer = cpu == Cpu::I486 ? 4 : 2;
    if (name == "zero-wait") return b;
    if (name == "isa") {  // a 16-bit card at 8.33 MHz: a byte or a word a bus cycle of 3 clocks, a dword two
        b.write_ns[0] = 360, b.write_ns[1] = 360, b.write_ns[2] = 720;
        b.out_ns = 600;
        return b;
    }
    if (name == "vlb") {  // a 32-bit local-bus card
        b.write_ns[0] = 120, b.write_ns[1] = 120, b.write_ns[2] = 120;
        b.out_ns = 100;
        return b;
    }
    throw std::runtime_error("no bus '" + name + "': zero-wait, isa or vlb");
}

int Bus::write_cycles(int bytes) const {
    const double ns = write_ns[bytes >= 4 ? 2 : bytes == 2 ? 1 : 0];
    return int(std::ceil(ns * cpu_mhz / 1000 - 1e-9));
}

int Bus::out_cycles() const { return int(std::ceil(out_ns * cpu_mhz / 1000 - 1e-9)); }

bool Machine::modelled(const Insn& in, Cpu cpu) {
    try {
        if (cpu == Cpu::I486) {
            if (in.kind == Kind::Fpu) I486::fpu_clocks(in);
            else I486::base_clocks(in, true, Mode::Protected32);
        } else {
            if (in.kind == Kind::Fpu) P5::fpu_cycles(in, 64);
            else P5::clocks(in, Mode::Protected32);
        }
        return true;
    } catch (const std::runtime_error&) {
        return false;
    }
}

Machine::Machine(Cpu cpu, int precision, const std::vector<Bus>& buses)
    : cpu_(cpu), i486_(Mode::Protected32), p5_(precision, Mode::Protected32) {
    i486_.explain(false), p5_.explain(false);
    stand_in_.mnemonic = stand_in_.text = UNMODELLED;
    for (const Bus& b : buses) tracks_.push_back(Track{b, {}, 0, 0, 0, -1, 0, -1, 0, false, {}, {}});
}

long Machine::cycles(size_t k) const { return model_cycles() + tracks_[k].delayed; }

void Machine::feed(const Insn* in, bool taken, Effects fx, bool is_modelled) {
    const Insn* original = in;
    if (!is_modelled) in = &stand_in_;
    if (cpu_ == Cpu::I486) {
        const Step s = i486_.run(*in, taken);
        issued(Pending{in, taken, fx, original}, s.start);
        return;
    }
    window_[held_++] = Pending{in, taken, fx, original};
    if (held_ == 3) issue_pentium();
}

// The Pentium issues the first instruction held (and the second where it pairs with it).
void Machine::issue_pentium() {
    Executed w[3];
    for (int k = 0; k < held_; ++k) w[k] = Executed{window_[size_t(k)].in, window_[size_t(k)].taken};
    const int n = p5_.issue(w, size_t(held_), issues_.data());
    for (int k = 0; k < n; ++k) issued(window_[size_t(k)], issues_[size_t(k)].cycle);
    for (int k = n; k < held_; ++k) window_[size_t(k - n)] = window_[size_t(k)];
    held_ -= n;
}

void Machine::flush() {
    while (held_ > 0) issue_pentium();
}

// An instruction issued in the model's `cycle`: on each bus, its bus work, then its mark.
void Machine::issued(const Pending& p, long cycle) {
    const bool io = p.fx.display_write || p.in->kind == Kind::Out || p.in->kind == Kind::In;
    for (Track& t : tracks_) {
        ++t.since_lap;
        if (t.in_frame) {
            ++t.row.instructions;
            if (p.in == &stand_in_) ++t.row.unmodelled, ++t.row.unknown[p.original->mnemonic];
        }
        long delay = 0;
        if (io) delay = bus_wait(t, p, model_cycles() + t.delayed);
        if (delay) {
            t.delayed += delay;
            if (t.in_frame) t.row.bus_stall += uint64_t(delay);
        }
        if (p.fx.mark >= 0) mark(t, p.fx.mark, cycle + t.delayed);
    }
}

// The write buffer and the bus: a write to display memory is posted, and the CPU waits only when
// the buffer is full; an OUT or an IN waits for the posted writes, then for its own bus cycle.
// Returns the cycles the CPU waits, from `now`.
long Machine::bus_wait(Track& t, const Pending& p, long now) const {
    while (!t.buffer.empty() && t.buffer.front() <= now) t.buffer.pop_front();
    if (p.in->kind == Kind::Out || p.in->kind == Kind::In) {
        if (t.in_frame) ++t.row.outs;
        const long done = std::max(now, t.bus_free) + t.bus.out_cycles();
        t.buffer.clear();
        t.bus_free = done;
        return done - now;
    }
    if (t.in_frame) ++t.row.display_writes;
    long at = now;
    if (int(t.buffer.size()) >= t.bus.write_buffer && t.bus.write_buffer > 0) {
        at = t.buffer.front();
        t.buffer.pop_front();
    }
    t.bus_free = std::max(at, t.bus_free) + t.bus.write_cycles(p.fx.display_write);
    t.buffer.push_back(t.bus_free);
    return at - now;
}

void Machine::mark(Track& t, int8_t m, long cycle) {
    switch (m) {
    case ProbeStart: t.lap_from = cycle, t.since_lap = 0; break;
    case CalibrationStart: t.calibration_from = cycle, t.lap_cost = -1; break;
    case CalibrationLap:
        // the least interval between back-to-back laps, as Probe::calibrate takes it
        if (t.lap_cost < 0 || cycle - t.calibration_from < t.lap_cost) t.lap_cost = cycle - t.calibration_from;
        t.calibration_from = cycle;
        break;
    case FrameStart:
        t.frame_from = cycle, t.in_frame = true;
        t.lap_from = cycle;
        break;
    case FrameEnd:
        if (t.in_frame) t.row.frame_cycles += uint64_t(cycle - t.frame_from), ++t.row.frames;
        t.in_frame = false;
        break;
    case RowEnd:
        t.row.lap_cost = uint64_t(std::max<long>(0, t.lap_cost));
        t.rows.push_back(t.row);
        t.row = Row{};
        break;
    default:
        if (m >= 0 && m < PHASES) {
            t.row.phase_cycles[m] += uint64_t(cycle - t.lap_from);
            t.row.phase_instructions[m] += t.since_lap;
            ++t.row.laps[m];
            t.lap_from = cycle, t.since_lap = 0;
        }
    }
}

}  // namespace timing
