// libmodexlab-profile.so: the guest instructions the kernel executes inside the bench's frames, by
// instruction address, as a QEMU 7.2 TCG plugin (docs/bench.md, "Where the instructions go"). It
// observes and never alters the guest.
//
//   -plugin build/host/libmodexlab-profile.so,marks=ADDRESS,out=FILE
//
// marks: the address of the kernel's modexlab_cycle_marks. A frame's first drawing runs between
// its FrameStart and FrameEnd marks (kernel/platform/cycle_marks.h): only instructions executed
// there are counted. At each RowEnd (a bench command's end) the counts since the last go to FILE as
// "row N", then "ADDRESS COUNT" lines (hexadecimal, decimal), then "end"; the counts start again.
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <map>
#include <string>

#include "qemu/plugin/qemu_plugin_api.h"

int qemu_plugin_version = 1;

namespace {

// the marks' bytes (kernel/platform/cycle_marks.h, timing::Machine::Mark)
constexpr uint64_t FRAME_START = 10, FRAME_END = 11, ROW_END = 12;

struct Counter {
    uint64_t address = 0, count = 0;
};

struct Plugin {
    uint64_t marks = 0;
    bool inside = false;  // between a FrameStart and its FrameEnd
    int row = 0;
    std::map<uint64_t, Counter*> at;  // a counter an address, shared by every translation of it
    std::deque<Counter> counters;     // (stable addresses)
    FILE* out = nullptr;
};

Plugin g;

void on_insn(unsigned int, void* userdata) {
    if (g.inside) ++static_cast<Counter*>(userdata)->count;
}

void write_row() {
    std::fprintf(g.out, "row %d\n", g.row++);
    for (Counter& c : g.counters) {
        if (c.count) std::fprintf(g.out, "%llx %llu\n", static_cast<unsigned long long>(c.address), static_cast<unsigned long long>(c.count));
        c.count = 0;
    }
    std::fprintf(g.out, "end\n");
    std::fflush(g.out);
}

void on_store(unsigned int, qemu_plugin_meminfo_t info, uint64_t vaddr, void*) {
    // (a mark is a byte; the wider stores that clear the array at boot are not)
    if (vaddr < g.marks || vaddr - g.marks > ROW_END || qemu_plugin_mem_size_shift(info) != 0) return;
    const uint64_t mark = vaddr - g.marks;
    if (mark == FRAME_START) g.inside = true;
    if (mark == FRAME_END) g.inside = false;
    if (mark == ROW_END) write_row();
}

void on_translate(qemu_plugin_id_t, struct qemu_plugin_tb* tb) {
    for (size_t i = 0, n = qemu_plugin_tb_n_insns(tb); i < n; ++i) {
        struct qemu_plugin_insn* insn = qemu_plugin_tb_get_insn(tb, i);
        const uint64_t address = qemu_plugin_insn_vaddr(insn);
        Counter*& c = g.at[address];
        if (!c) c = &g.counters.emplace_back(Counter{address, 0});
        qemu_plugin_register_vcpu_insn_exec_cb(insn, on_insn, QEMU_PLUGIN_CB_NO_REGS, c);
        qemu_plugin_register_vcpu_mem_cb(insn, on_store, QEMU_PLUGIN_CB_NO_REGS, QEMU_PLUGIN_MEM_W, nullptr);
    }
}

void on_exit(qemu_plugin_id_t, void*) { std::fclose(g.out); }

}  // namespace

int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t*, int argc, char** argv) {
    std::string marks, out;
    for (int k = 0; k < argc; ++k) {
        const std::string a = argv[k];
        if (a.rfind("marks=", 0) == 0) marks = a.substr(6);
        else if (a.rfind("out=", 0) == 0) out = a.substr(4);
        else {
            qemu_plugin_outs(("modexlab profile plugin: unknown argument '" + a + "' (marks, out)\n").c_str());
            return 1;
        }
    }
    if (marks.empty() || out.empty()) {
        qemu_plugin_outs("modexlab profile plugin: marks=ADDRESS and out=FILE, please\n");
        return 1;
    }
    g.marks = std::strtoull(marks.c_str(), nullptr, 0);
    g.out = std::fopen(out.c_str(), "w");
    if (!g.out) {
        qemu_plugin_outs(("modexlab profile plugin: cannot write " + out + "\n").c_str());
        return 1;
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, on_exit, nullptr);
    return 0;
}
