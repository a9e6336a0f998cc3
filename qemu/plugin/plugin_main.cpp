// libmodexlab-timing.so: the timing model over everything the kernel executes, as a QEMU 7.2 TCG
// plugin (docs/cycles.md, "Whole frames"). It observes and never alters: the guest runs, and its
// instruction counts come out, as without it.
//
//   -plugin build/host/libmodexlab-timing.so,cpu=486|pentium,bus=zero-wait|isa|vlb,precision=53,
//           marks=ADDRESS,out=FILE
//
// bus: a bus model; given again, more than one, all counted in the one run. marks: the address of
// the kernel's modexlab_cycle_marks (its symbol), where the bench probe marks its laps, the frames
// and the rows by the byte it writes. Each bench row's figures go to FILE when the row ends, as a
// JSON line a bus.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "qemu/plugin/qemu_plugin_api.h"
#include "qemu/timing/decode.h"
#include "qemu/timing/machine.h"

int qemu_plugin_version = 1;

namespace {

using timing::Effects;
using timing::Machine;

constexpr uint64_t DISPLAY_FIRST = 0xA0000, DISPLAY_END = 0xC0000;

// A translated block: its instructions, decoded once, and where it falls through to.
struct Block {
    uint64_t address = 0, end = 0;
    std::vector<timing::Insn> insns;
    std::vector<bool> modelled;
};

struct Plugin {
    std::unique_ptr<Machine> machine;
    timing::Cpu cpu = timing::Cpu::Pentium;
    std::string cpu_name;
    int precision = 53;
    uint64_t marks = 0;
    std::vector<std::unique_ptr<Block>> blocks;  // every block translated (QEMU may translate one again)
    const Block* running = nullptr;              // the block executing, fed when the next one starts
    std::vector<Effects> effects;                // its instructions' effects
    size_t rows_written = 0;
    FILE* out = nullptr;
};

Plugin g;

void write_rows() {
    for (const size_t rows = g.machine->rows(0).size(); g.rows_written < rows; ++g.rows_written) {
        for (size_t k = 0; k < g.machine->buses(); ++k) {
            const Machine::Row& r = g.machine->rows(k)[g.rows_written];
            nlohmann::json j = {{"row", g.rows_written},
                                {"model", "modexlab timing " + g.cpu_name},
                                {"cpu", g.cpu_name},
                                {"bus", g.machine->bus(k).name},
                                {"precision", g.precision},
                                {"frames", r.frames},
                                {"frame_cycles", r.frame_cycles},
                                {"setup", r.net(Machine::Setup)},
                                {"walk", r.net(Machine::Walk)},
                                {"inner", r.net(Machine::Inner)},
                                {"choose", r.net(Machine::Choose)},
                                {"lap_cost", r.lap_cost},
                                {"laps", r.laps},
                                {"phase_instructions", r.phase_instructions},
                                {"instructions", r.instructions},
                                {"unmodelled", r.unmodelled},
                                {"display_writes", r.display_writes},
                                {"outs", r.outs},
                                {"bus_stall", r.bus_stall},
                                {"unmodelled_by_mnemonic", r.unknown}};
            std::fprintf(g.out, "%s\n", j.dump().c_str());
        }
    }
    std::fflush(g.out);
}

void feed(const Block& b, uint64_t next) {
    size_t n = b.insns.size();
    const timing::Insn& last = b.insns.back();
    const bool jumped_there = (last.kind == timing::Kind::Jcc || last.kind == timing::Kind::Jmp) && last.target == next;
    if (next > b.address && next < b.end && !jumped_there)
        for (size_t i = 0; i < b.insns.size(); ++i)
            if (b.insns[i].address == next) n = i;
    for (size_t i = 0; i < n; ++i) {
        const timing::Insn& in = b.insns[i];
        const bool branch = in.kind == timing::Kind::Jcc || in.kind == timing::Kind::Jmp || in.kind == timing::Kind::Call || in.kind == timing::Kind::Ret;
        const bool taken = branch && i + 1 == b.insns.size() && next != b.end;
        g.machine->feed(&in, taken, g.effects[i], b.modelled[i]);
    }
}

void on_block(unsigned int, void* userdata) {
    const Block* b = static_cast<const Block*>(userdata);
    if (g.running) {
        const size_t rows = g.machine->rows(0).size();
        feed(*g.running, b->address);
        if (g.machine->rows(0).size() != rows) write_rows();
    }
    g.running = b;
    std::fill_n(g.effects.begin(), std::min(g.effects.size(), b->insns.size()), Effects{});
    if (g.effects.size() < b->insns.size()) g.effects.resize(b->insns.size());
}

void on_store(unsigned int, qemu_plugin_meminfo_t info, uint64_t vaddr, void* userdata) {
    const size_t i = size_t(reinterpret_cast<uintptr_t>(userdata));
    if (i >= g.effects.size()) return;
    if (vaddr - g.marks < uint64_t(Machine::MarkCount)) {
        // (a mark is a byte; the wider stores that clear the array at boot are not)
        if (qemu_plugin_mem_size_shift(info) == 0) g.effects[i].mark = int8_t(vaddr - g.marks);
        return;
    }
    // (the kernel maps every address to itself: kernel/platform/guard.h)
    if (vaddr >= DISPLAY_FIRST && vaddr < DISPLAY_END) g.effects[i].display_write = uint8_t(1u << qemu_plugin_mem_size_shift(info));
}

void on_translate(qemu_plugin_id_t, struct qemu_plugin_tb* tb) {
    auto b = std::make_unique<Block>();
    b->address = qemu_plugin_tb_vaddr(tb);
    const size_t n = qemu_plugin_tb_n_insns(tb);
    for (size_t i = 0; i < n; ++i) {
        struct qemu_plugin_insn* insn = qemu_plugin_tb_get_insn(tb, i);
        const uint64_t at = qemu_plugin_insn_vaddr(insn);
        const size_t size = qemu_plugin_insn_size(insn);
        std::vector<timing::Insn> d = timing::decode(static_cast<const uint8_t*>(qemu_plugin_insn_data(insn)), size, 32, uint32_t(at), true);
        timing::Insn in;
        if (d.empty()) {
            in.address = uint32_t(at), in.size = uint8_t(size), in.mnemonic = in.text = "(undecoded)";
        } else {
            in = d.front();
        }
        b->modelled.push_back(!d.empty() && Machine::modelled(in, g.cpu));
        b->insns.push_back(in);
        b->end = at + size;
        if (in.mem.write || in.kind == timing::Kind::String)
            qemu_plugin_register_vcpu_mem_cb(insn, on_store, QEMU_PLUGIN_CB_NO_REGS, QEMU_PLUGIN_MEM_W, reinterpret_cast<void*>(uintptr_t(i)));
    }
    qemu_plugin_register_vcpu_tb_exec_cb(tb, on_block, QEMU_PLUGIN_CB_NO_REGS, b.get());
    g.blocks.push_back(std::move(b));
}

void on_exit(qemu_plugin_id_t, void*) {
    if (g.running) feed(*g.running, 0);
    g.machine->flush();
    write_rows();
    std::fclose(g.out);
}

bool argument(const std::string& a, const std::string& key, std::string* value) {
    if (a.compare(0, key.size() + 1, key + "=") != 0) return false;
    *value = a.substr(key.size() + 1);
    return true;
}

}  // namespace

int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t*, int argc, char** argv) {
    std::string cpu = "pentium", precision = "53", marks, out, bus;
    std::vector<std::string> buses;
    for (int k = 0; k < argc; ++k) {
        const std::string a = argv[k];
        if (argument(a, "bus", &bus)) {
            buses.push_back(bus);
            continue;
        }
        if (!argument(a, "cpu", &cpu) && !argument(a, "precision", &precision) && !argument(a, "marks", &marks) && !argument(a, "out", &out)) {
            qemu_plugin_outs(("modexlab timing plugin: unknown argument '" + a + "' (cpu, bus, precision, marks, out)\n").c_str());
            return 1;
        }
    }
    if ((cpu != "486" && cpu != "pentium") || (precision != "24" && precision != "53" && precision != "64") || out.empty() || marks.empty()) {
        qemu_plugin_outs("modexlab timing plugin: cpu=486|pentium, precision=24|53|64, marks=ADDRESS and out=FILE, please\n");
        return 1;
    }
    g.cpu = cpu == "486" ? timing::Cpu::I486 : timing::Cpu::Pentium;
    g.cpu_name = cpu, g.precision = std::atoi(precision.c_str());
    g.marks = std::strtoull(marks.c_str(), nullptr, 0);
    if (buses.empty()) buses.push_back("zero-wait");
    try {
        std::vector<timing::Bus> models;
        for (const std::string& b : buses) models.push_back(timing::Bus::preset(b, g.cpu));
        g.machine = std::make_unique<Machine>(g.cpu, g.precision, models);
    } catch (const std::exception& e) {
        qemu_plugin_outs((std::string("modexlab timing plugin: ") + e.what() + "\n").c_str());
        return 1;
    }
    g.out = std::fopen(out.c_str(), "w");
    if (!g.out) {
        qemu_plugin_outs(("modexlab timing plugin: cannot write " + out + "\n").c_str());
        return 1;
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, on_exit, nullptr);
    return 0;
}
