// modexlab-extremes: every mapper through the classes of extreme input (qemu/tools/extremes.h),
// the report in build/report/extremes.md and .csv (docs/accuracy.md, "Stability at the extremes").
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "qemu/harness/session.h"
#include "qemu/lib/command_line.h"
#include "qemu/lib/error.h"
#include "qemu/tools/extremes.h"
#include "qemu/tools/trade.h"

namespace {

using namespace harness;

const char* USAGE =
    "usage: modexlab-extremes [--polygons N] [--seed N] [--mappers NAME,...] [--classes NAME,...] [--timeout S] [--out DIR]\n"
    "  --polygons  polygons a random class (default 300; the sweeps have their own counts)\n"
    "  --seed      of every class (default 2026)\n"
    "  --mappers   mappers (default: all of the registry)\n"
    "  --classes   near-plane, convex, sliver, tiny, huge, degenerate, perspective, anywhere, beyond,\n"
    "              texture-limits, rotation (default: all)\n"
    "  --timeout   seconds a mapper and class may take before it counts as a hang (default 600)\n"
    "  --out       where extremes.md and extremes.csv go (default build/report)\n"
    "Exit status 1 when a mapper breaks a promise (a fault, a hang, a write outside the clip, an\n"
    "error above its bound, coverage it promised not kept). MODEXLAB_EXTREMES_DEBUG=1 prints every polygon\n"
    "measured above its bound, with its vertices.\n";

int run(const std::vector<std::string>& words) {
    const CommandLine args = parse_command_line(words, {"--polygons", "--seed", "--mappers", "--classes", "--timeout", "--out"}, {});
    if (args.help()) return show_usage(USAGE);
    if (!args.positionals().empty()) throw UsageError("unexpected argument '" + args.positionals()[0] + "'");
    ExtremesOptions o;
    o.polygons = args.integer("--polygons", 1, 10000000, 300);
    o.seed = uint32_t(args.integer("--seed", 0, 2147483647, 2026));
    o.mappers = known_mappers(args.list("--mappers"));
    o.classes = args.list("--classes");
    for (const std::string& c : o.classes) {
        bool known = false;
        for (const std::string& k : extreme_classes()) known = known || k == c;
        if (!known) throw UsageError("unknown class '" + c + "' (see --help)");
    }
    o.timeout_seconds = args.integer("--timeout", 1, 86400, 600);
    const std::string out = args.text("--out", build_dir() + "/report");
    const std::vector<ExtremeRow> rows = run_extremes(o, [](const ExtremeRow& r, size_t done, size_t all) {
        std::fprintf(stderr, "extremes: %zu/%zu %-20s %-15s %6u tried %6u drawn, max footprint error %.3f%s%s\n", done, all, r.mapper.c_str(),
                     r.cls.c_str(), r.tried, r.drawn, r.max_footprint, r.broken_promise().empty() ? "" : ", BROKEN: ",
                     r.broken_promise().c_str());
    });
    write_extremes_report(rows, o, out);
    size_t broken = 0;
    for (const ExtremeRow& r : rows) broken += !r.broken_promise().empty();
    std::printf("extremes: %zu rows, %zu with a broken promise: %s/extremes.md, %s/extremes.csv\n", rows.size(), broken, out.c_str(), out.c_str());
    return broken ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    return run_cli("modexlab-extremes", USAGE, argc, argv, run);
}
