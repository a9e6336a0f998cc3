// The timing plugin's argument and rows (timing_plugin.h).
#include "qemu/harness/timing_plugin.h"

#include <filesystem>
#include <fstream>

#include "qemu/harness/session.h"
#include "qemu/lib/error.h"

namespace harness {

std::string timing_plugin_spec(const TimingPlugin& p, const std::string& kernel_elf) {
    const std::string plugin = build_dir() + "/host/libmodexlab-timing.so";
    if (!std::filesystem::exists(plugin)) throw HarnessError("no " + plugin + " (make host builds it)");
    const uint64_t marks = elf_symbol(kernel_elf, "modexlab_cycle_marks");
    if (!marks) throw HarnessError(kernel_elf + ": no symbol modexlab_cycle_marks (the timing plugin's marks)");
    std::string spec = plugin + ",cpu=" + p.cpu + ",precision=" + std::to_string(p.precision) + ",marks=" + std::to_string(marks) + ",out=" + p.out;
    for (const std::string& b : p.buses) spec += ",bus=" + b;
    return spec;
}

std::vector<json> timing_plugin_rows(const std::string& out) {
    std::vector<json> rows;
    std::ifstream f(out);
    for (std::string line; std::getline(f, line);) {
        json j = json::parse(line, nullptr, false);
        if (!j.is_discarded() && j.contains("row")) rows.push_back(j);
    }
    return rows;
}

}  // namespace harness
