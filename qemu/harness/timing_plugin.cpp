// The timing plugin's argument and rows (timing_plugin.h).
#include "qemu/harness/timing_plugin.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "qemu/harness/session.h"
#include "qemu/lib/error.h"

namespace harness {

std::string timing_plugin_spec(const TimingPlugin& p, const std::string& kernel_elf) {
    const std::string plugin = build_dir() + "/host/libmodexlab-timing.so";
    if (!std::filesystem::exists(plugin)) throw HarnessError("no " + plugin + " (make host builds it)");
    FILE* nm = popen(("nm " + kernel_elf + " 2>/dev/null").c_str(), "r");
    if (!nm) throw HarnessError("cannot run nm");
    std::string marks;
    char line[512];
    while (fgets(line, sizeof line, nm)) {
        unsigned long long address = 0;
        char type = 0, name[400] = "";
        if (std::sscanf(line, "%llx %c %399s", &address, &type, name) == 3 && std::string(name) == "modexlab_cycle_marks")
            marks = std::to_string(address);
    }
    pclose(nm);
    if (marks.empty()) throw HarnessError(kernel_elf + ": no symbol modexlab_cycle_marks (the timing plugin's marks)");
    std::string spec = plugin + ",cpu=" + p.cpu + ",precision=" + std::to_string(p.precision) + ",marks=" + marks + ",out=" + p.out;
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
