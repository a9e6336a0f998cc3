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

Machine::Machine(Cpu cpu, int precision, const Bus& bus) : cpu_(cpu), bus_(bus), i486_(Mode::Protected32), p5_(precision, Mode::Protected32) {
    i486_.explain(false), p5_.explain(false);
    stand_in_.mnemonic = stand_in_.text = UNMODELLED;
}

long Machine::cycles() const { return (cpu_ == Cpu::I486 ? i486_.now() : p5_.now()) + delayed_; }

void Machine::feed(const Insn* in, bool taken, Effects fx, bool is_modelled) {
    const Insn* original = in;
    if (!is_modelled) in = &stand_in_;
    if (cpu_ == Cpu::I486) {
        const Step s = i486_.run(*in, taken);
        issued(Pending{in, taken, fx, original}, s.start + delayed_);
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
    for (int k = 0; k < n; ++k) issued(window_[size_t(k)], issues_[size_t(k)].cycle + delayed_);
    for (int k = n; k < held_; ++k) window_[size_t(k - n)] = window_[size_t(k)];
    held_ -= n;
}

void Machine::flush() {
    while (held_ > 0) issue_pentium();
}

// An instruction issued in `cycle` (the bus's stalls so far included): its bus work, then its mark.
void Machine::issued(const Pending& p, long cycle) {
    ++since_lap_;
    if (in_frame_) {
        ++row_.instructions;
        if (p.in == &stand_in_) ++row_.unmodelled, ++row_.unknown[p.original->mnemonic];
    }
    long delay = 0;
    if (p.fx.display_write || p.in->kind == Kind::Out || p.in->kind == Kind::In) bus(p, &delay);
    if (delay) {
        delayed_ += delay;
        if (in_frame_) row_.bus_stall += uint64_t(delay);
    }
    if (p.fx.mark >= 0) mark(p.fx.mark, cycle + delay);
}

// The write buffer and the bus: a write to display memory is posted, and the CPU waits only when
// the buffer is full; an OUT or an IN waits for the posted writes, then for its own bus cycle.
void Machine::bus(const Pending& p, long* delay) {
    const long now = cycles();
    while (!buffer_.empty() && buffer_.front() <= now) buffer_.pop_front();
    if (p.in->kind == Kind::Out || p.in->kind == Kind::In) {
        if (in_frame_) ++row_.outs;
        const long free = std::max(now, bus_free_);
        const long done = free + bus_.out_cycles();
        buffer_.clear();
        bus_free_ = done;
        *delay = done - now;
        return;
    }
    if (in_frame_) ++row_.display_writes;
    long at = now;
    if (int(buffer_.size()) >= bus_.write_buffer && bus_.write_buffer > 0) {
        at = buffer_.front();
        buffer_.pop_front();
    }
    const long start = std::max(at, bus_free_);
    bus_free_ = start + bus_.write_cycles(p.fx.display_write);
    buffer_.push_back(bus_free_);
    *delay = at - now;
}

void Machine::mark(int8_t m, long cycle) {
    switch (m) {
    case ProbeStart: lap_from_ = cycle, since_lap_ = 0; break;
    case CalibrationStart: calibration_from_ = cycle, lap_cost_ = -1; break;
    case CalibrationLap:
        // the least interval between back-to-back laps, as Probe::calibrate takes it
        if (lap_cost_ < 0 || cycle - calibration_from_ < lap_cost_) lap_cost_ = cycle - calibration_from_;
        calibration_from_ = cycle;
        break;
    case FrameStart:
        frame_from_ = cycle, in_frame_ = true;
        lap_from_ = cycle;
        break;
    case FrameEnd:
        if (in_frame_) row_.frame_cycles += uint64_t(cycle - frame_from_), ++row_.frames;
        in_frame_ = false;
        break;
    case RowEnd:
        row_.lap_cost = uint64_t(std::max<long>(0, lap_cost_));
        rows_.push_back(row_);
        row_ = Row{};
        break;
    default:
        if (m >= 0 && m < PHASES) {
            row_.phase_cycles[m] += uint64_t(cycle - lap_from_);
            row_.phase_instructions[m] += since_lap_;
            ++row_.laps[m];
            since_lap_ = 0;
            lap_from_ = cycle;
        }
    }
}

}  // namespace timing
