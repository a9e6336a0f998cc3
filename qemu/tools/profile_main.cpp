// modexlab-profile: where a mapper's instructions go, function by function, against another
// mapper's on the same frames (docs/bench.md, "Where the instructions go"): the kernel under QEMU
// with -icount and the profile plugin, one bench row a mapper, the counts those of the frames'
// first drawing (the one whose ticks the bench reports), a polygon.
#include <cxxabi.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "kernel/core/mapper.h"
#include "qemu/accuracy/measure.h"
#include "qemu/harness/session.h"
#include "qemu/lib/command_line.h"
#include "qemu/lib/error.h"
#include "qemu/tools/demo_scenes.h"
#include "qemu/tools/trade.h"

namespace {

using namespace harness;

const char* USAGE =
    "usage: modexlab-profile --scene NAME|FILE [--mapper NAME] [--against NAME] [--budget E] [--frames N] [--top K]\n"
    "                        [--kernel ELF] [--isa i486]\n"
    "Boots the kernel in QEMU (-icount) with the profile plugin and benches the scene with --mapper\n"
    "(default auto) and then --against (default fast-oriented-1), N frames each (default 8); auto at\n"
    "footprint error E with exact coverage (default: the scene's budget). Prints the guest\n"
    "instructions a polygon each spends inside the frames, by kernel function, the K functions that\n"
    "differ most first (default 25), the rest summed, and the totals beside the bench's own draw\n"
    "ticks. --isa i486: the 486's build of the C++ (default: the P6's, which QEMU's CPU runs).\n";

struct Args {
    std::string scene, mapper = "auto", against = "fast-oriented-1", budget, kernel, isa;
    int frames = 8, top = 25;
};

std::optional<Args> parse(const std::vector<std::string>& words) {
    const CommandLine args = parse_command_line(words, {"--scene", "--mapper", "--against", "--budget", "--frames", "--top", "--kernel", "--isa"}, {});
    if (args.help()) return std::nullopt;
    if (!args.positionals().empty()) throw UsageError("unexpected argument '" + args.positionals()[0] + "'");
    Args a;
    a.scene = args.text("--scene");
    if (a.scene.empty()) throw UsageError("--scene NAME|FILE, please");
    try {  // (before booting)
        choose_scene(a.scene);
    } catch (const HarnessError& e) {
        throw UsageError(e.what());
    }
    a.mapper = args.text("--mapper", a.mapper), a.against = args.text("--against", a.against);
    for (const std::string* m : {&a.mapper, &a.against})
        if (!raster::find_mapper({m->data(), m->size()})) throw UsageError("no mapper '" + *m + "' (modexlab exec mappers lists them)");
    a.budget = args.text("--budget");
    if (!a.budget.empty()) {
        char* end = nullptr;
        const double e = std::strtod(a.budget.c_str(), &end);
        if (!end || *end || !(e >= 0 && e <= 1000000)) throw UsageError("--budget takes a footprint error from 0 to 1000000, not '" + a.budget + "'");
        a.budget = budget_text(e);
    }
    a.frames = args.integer("--frames", 1, 1000, a.frames);
    a.top = args.integer("--top", 1, 1000, a.top);
    a.kernel = args.text("--kernel", build_dir() + "/kernel/modexlab.elf");
    a.isa = args.choice<std::string>("--isa", {{"i486", "i486"}}, "");
    return a;
}

// A bench row: the reply's totals, and the plugin's counts by address.
struct Row {
    std::string mapper;
    uint64_t polygons = 0, pixels = 0, draw = 0, frame = 0;
    std::map<uint64_t, uint64_t> counts;
};

// The plugin's rows in the order they ended (profile_plugin_main.cpp's format).
std::vector<std::map<uint64_t, uint64_t>> plugin_rows(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw HarnessError(path + ": the profile plugin wrote nothing");
    std::vector<std::map<uint64_t, uint64_t>> rows;
    bool open = false;
    for (std::string line; std::getline(f, line);) {
        if (line.rfind("row ", 0) == 0) rows.emplace_back(), open = true;
        else if (line == "end") open = false;
        else if (open) {
            std::istringstream fields(line);
            std::string address;
            uint64_t count = 0;
            if (!(fields >> address >> count)) throw HarnessError(path + ": a line that is no 'ADDRESS COUNT': " + line);
            rows.back()[std::stoull(address, nullptr, 16)] += count;
        }
    }
    if (open) throw HarnessError(path + ": its last row has no end");
    return rows;
}

// The kernel's functions by start address, their names demangled (the P6 build's copies keep
// their "p6." prefix); and where modexlab_cycle_marks is (0: nowhere).
std::map<uint64_t, std::string> functions(const std::string& elf, uint64_t* marks) {
    std::map<uint64_t, std::string> f;
    *marks = 0;
    for (const ElfSymbol& s : elf_symbols(elf)) {
        if (s.name == "modexlab_cycle_marks") *marks = s.address;
        if (s.type != 't' && s.type != 'T' && s.type != 'W' && s.type != 'w') continue;
        const bool p6 = s.name.rfind("p6.", 0) == 0;
        const std::string bare = p6 ? s.name.substr(3) : s.name;
        int status = 0;
        char* d = abi::__cxa_demangle(bare.c_str(), nullptr, nullptr, &status);
        f[s.address] = (p6 ? "p6." : "") + (status == 0 && d ? std::string(d) : bare);
        std::free(d);
    }
    if (f.empty()) throw HarnessError(elf + ": no function symbols");
    return f;
}

std::map<std::string, double> by_function(const Row& r, const std::map<uint64_t, std::string>& f) {
    std::map<std::string, double> out;
    for (const auto& [address, count] : r.counts) {
        auto it = f.upper_bound(address);
        out[it == f.begin() ? "(before the first function)" : std::prev(it)->second] += double(count);
    }
    return out;
}

std::string shortened(const std::string& s, size_t most) { return s.size() <= most ? s : s.substr(0, most - 3) + "..."; }

int run(const Args& a) {
    const SceneChoice scene = choose_scene(a.scene);
    const LoadedWorld host = load_world_file(scene.path);
    uint64_t marks = 0;
    const std::map<uint64_t, std::string> f = functions(a.kernel, &marks);
    const std::string plugin = build_dir() + "/host/libmodexlab-profile.so";
    if (!marks) throw HarnessError(a.kernel + ": no symbol modexlab_cycle_marks (the profile plugin's marks)");
    if (!std::filesystem::exists(plugin)) throw HarnessError("no " + plugin + " (make host builds it)");
    // (a run directory of its own: profiles may run side by side)
    SessionOptions o;
    o.name = "profile." + std::to_string(getpid());
    const std::string out = build_dir() + "/runs/" + o.name + "/profile.txt";
    o.image = a.kernel;
    o.icount = true;
    if (!a.isa.empty()) o.append += " isa=" + a.isa;
    o.plugin = plugin + ",marks=" + std::to_string(marks) + ",out=" + out;
    o.command_timeout = std::chrono::milliseconds(600000);
    std::fprintf(stderr, "modexlab-profile: %s, %d frames, %s against %s, in QEMU with -icount and the profile plugin\n", scene.name.c_str(), a.frames,
                 a.mapper.c_str(), a.against.c_str());
    Session k(o);
    k.ok("mode modex");
    load_scene_in_kernel(k, scene, host);
    if (!a.budget.empty()) k.ok("budget " + a.budget + " exact");
    const json budget = k.ok("budget")["budget"];
    std::vector<Row> rows;
    for (const std::string& m : {a.mapper, a.against}) {
        const json r = k.ok("bench " + std::to_string(a.frames) + " " + m, [](const json&) {});  // (a frame's event each)
        Row row;
        row.mapper = m, row.polygons = r["polygons"].get<uint64_t>(), row.pixels = r["pixels"].get<uint64_t>();
        row.draw = r["ticks_draw"]["sum"].get<uint64_t>(), row.frame = r["ticks"]["sum"].get<uint64_t>();
        if (!row.polygons) throw HarnessError(m + " drew no polygon of " + scene.name);
        rows.push_back(row);
    }
    k.ok("exit 0");
    k.wait_exit();
    const std::vector<std::map<uint64_t, uint64_t>> counted = plugin_rows(out);
    if (counted.size() != rows.size()) throw HarnessError(out + ": " + std::to_string(counted.size()) + " rows, not " + std::to_string(rows.size()));
    std::filesystem::remove_all(k.run_dir());
    std::map<std::string, double> per[2];
    double total[2] = {0, 0};
    for (int i = 0; i < 2; ++i) {
        rows[size_t(i)].counts = counted[size_t(i)];
        for (const auto& [name, count] : by_function(rows[size_t(i)], f)) per[i][name] = count / double(rows[size_t(i)].polygons), total[i] += count;
    }
    std::vector<std::pair<double, std::string>> order;
    std::map<std::string, bool> seen;
    for (const auto& p : per)
        for (const auto& [name, v] : p)
            if (!seen[name]) seen[name] = true, order.emplace_back(-std::fabs(per[0][name] - per[1][name]), name);
    std::sort(order.begin(), order.end());

    const std::string max_error = budget.contains("max_error") ? budget["max_error"].dump() : "?";
    std::printf("%s, %d frames, budget %s (%s coverage): %s against %s. QEMU icount: guest instructions executed inside the frames' first\n"
                "drawing (geometry, clear, draw, blit), by kernel function, a polygon drawn (%s %llu, %s %llu polygons)\n\n",
                scene.name.c_str(), a.frames, max_error.c_str(), budget.value("exact_coverage", false) ? "exact" : "any", a.mapper.c_str(),
                a.against.c_str(), a.mapper.c_str(), static_cast<unsigned long long>(rows[0].polygons), a.against.c_str(),
                static_cast<unsigned long long>(rows[1].polygons));
    std::printf("%12s %12s %12s  %s\n", a.mapper.c_str(), a.against.c_str(), "difference", "function");
    double rest[2] = {0, 0};
    for (size_t n = 0; n < order.size(); ++n) {
        const std::string& name = order[n].second;
        if (int(n) >= a.top) {
            rest[0] += per[0][name], rest[1] += per[1][name];
            continue;
        }
        std::printf("%12.1f %12.1f %12.1f  %s\n", per[0][name], per[1][name], per[0][name] - per[1][name], shortened(name, 110).c_str());
    }
    if (order.size() > size_t(a.top))
        std::printf("%12.1f %12.1f %12.1f  (the other %zu functions)\n", rest[0], rest[1], rest[0] - rest[1], order.size() - size_t(a.top));
    const double p0 = double(rows[0].polygons), p1 = double(rows[1].polygons);
    std::printf("%12.1f %12.1f %12.1f  total inside the frames\n", total[0] / p0, total[1] / p1, total[0] / p0 - total[1] / p1);
    std::printf("%12.1f %12.1f %12.1f  the bench's frame ticks (rdtsc under icount: instructions)\n", double(rows[0].frame) / p0, double(rows[1].frame) / p1,
                double(rows[0].frame) / p0 - double(rows[1].frame) / p1);
    std::printf("%12.1f %12.1f %12.1f  the bench's draw ticks; draw instructions a pixel %.3f and %.3f, their ratio %.3f\n", double(rows[0].draw) / p0,
                double(rows[1].draw) / p1, double(rows[0].draw) / p0 - double(rows[1].draw) / p1, double(rows[0].draw) / double(rows[0].pixels),
                double(rows[1].draw) / double(rows[1].pixels), (double(rows[1].draw) / double(rows[1].pixels)) / (double(rows[0].draw) / double(rows[0].pixels)));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return run_cli("modexlab-profile", USAGE, argc, argv, [](const std::vector<std::string>& words) {
        std::optional<Args> a = parse(words);
        return a ? run(*a) : show_usage(USAGE);
    });
}
