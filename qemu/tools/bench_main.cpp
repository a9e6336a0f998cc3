// modexlab-bench: every mapper on every demo scene, speed measured in the kernel under QEMU's
// icount, accuracy on the host twin against the exact reference, the kernel's pictures checked
// against the host's; the report under build/report. docs/bench.md describes it all.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "qemu/tools/cost_model.h"
#include "qemu/tools/demo_scenes.h"
#include "qemu/lib/command_line.h"
#include "qemu/lib/error.h"
#include "qemu/lib/host_image.h"
#include "qemu/accuracy/measure.h"
#include "qemu/harness/session.h"
#include "qemu/harness/timing_plugin.h"
#include "qemu/tools/trade.h"
#include "qemu/tools/trade_docs.h"

namespace {

using namespace harness;

const char* USAGE =
    "usage: modexlab-bench [--scenes NAME,...] [--mappers NAME,...] [--frames N] [--out DIR] [--kernel ELF] [--no-wall]\n"
    "                      [--targets 486,pentium]\n"
    "       modexlab-bench --costs-from CSV [--out DIR]\n"
    "       modexlab-bench --refresh-docs CSV\n"
    "  --scenes   demo scenes (default: all; modexlab-scene list) or scene files (uploaded with their texture files)\n"
    "  --mappers  mappers (default: all of the registry)\n"
    "  --frames   frames a scene, spread evenly over its animation (default 8)\n"
    "  --out      where the report goes (default build/report): trade.csv, trade.md, trade-SCENE.png, costs.cpp\n"
    "  --no-wall  skip the wall-clock frames per second (QEMU without icount)\n"
    "  --targets  the timing model's CPUs to run the frames again on, under QEMU with its plugin (default: none)\n"
    "  --costs-from  measure nothing: fit the cost model (costs.cpp) to an earlier run's trade.csv\n"
    "  --refresh-docs  measure nothing: rewrite the generated tables of README.md and docs/results.md (run from the\n"
    "             source tree) and the plot docs/img/trade-corridor.png from a trade.csv, and say which changed\n";

struct BenchScene {
    std::string name;  // in the report
    std::string path;  // the file on the host
    const DemoScene* demo;  // a demo scene: the kernel has it; nullptr: a file, uploaded
    LoadedWorld host;
};

struct Args {
    std::vector<std::string> scenes, mappers, targets;
    int frames = 8;
    std::string out, kernel, costs_from, refresh_docs;
    bool wall = true;
};

// The settings a command line asks for; none when it asks for the usage.
std::optional<Args> parse(const std::vector<std::string>& words) {
    const CommandLine args = parse_command_line(words, {"--scenes", "--mappers", "--frames", "--out", "--kernel", "--costs-from", "--refresh-docs", "--targets"},
                                                {"--no-wall"});
    if (args.help()) return std::nullopt;
    if (!args.positionals().empty()) throw UsageError("unexpected argument '" + args.positionals()[0] + "'");
    Args a;
    a.scenes = args.list("--scenes");
    a.mappers = known_mappers(args.list("--mappers"));
    a.frames = args.integer("--frames", 1, 1000, a.frames);
    a.out = args.text("--out", build_dir() + "/report");
    a.kernel = args.text("--kernel");
    a.wall = !args.has("--no-wall");
    a.targets = args.list("--targets");
    for (const std::string& t : a.targets)
        if (t != "486" && t != "pentium") throw UsageError("--targets takes 486 and pentium, not '" + t + "'");
    a.costs_from = args.text("--costs-from");
    a.refresh_docs = args.text("--refresh-docs");
    if (a.scenes.empty())
        for (const DemoScene& d : demo_scenes()) a.scenes.push_back(d.name);
    if (a.mappers.empty())
        for (int i = 0; i < raster::MAPPER_COUNT; ++i) a.mappers.push_back(raster::MAPPERS[i].name);
    return a;
}

BenchScene open_scene(const std::string& spec) {
    SceneChoice c = choose_scene(spec);
    BenchScene s;
    s.name = c.name, s.path = c.path, s.demo = c.demo;
    s.host = load_world_file(s.path);
    return s;
}

// The kernel loads the scene: a built-in by name, a file by upload.
void load_in_kernel(Session& k, const BenchScene& s) { load_scene_in_kernel(k, SceneChoice{s.name, s.path, s.demo}, s.host); }


uint64_t sum_of(const json& r, const char* field) {
    if (!r.contains(field) || !r[field].is_object() || !r[field].contains("sum") || !r[field]["sum"].is_number_unsigned())
        throw HarnessError(std::string("the kernel's bench reply has no ") + field + " (a kernel older than this harness? make kernel)");
    return r[field]["sum"].get<uint64_t>();
}

// One row: the mapper on the scene's frames, in the kernel and on the host; auto at `budget`
// when one is given (the row is named auto@BUDGET), else at the scene's.
TradeRow bench_one(Session& k, BenchScene& s, const raster::Mapper& m, int frames, const raster::Budget* budget = nullptr) {
    TradeRow row;
    row.scene = s.name, row.mapper = m.name, row.family = m.family, row.surface = raster::surface_name(raster::home_surface(m));
    if (budget) {
        row.mapper += "@" + budget_text(budget->max_error);
        k.ok("budget " + budget_text(budget->max_error) + " exact");
    }
    json last;
    json r = k.ok("bench " + std::to_string(frames) + " " + m.name + " " + row.surface, [&](const json& e) { last = e; });
    if (budget) k.ok("budget scene");
    row.walker = r["walker"].get<std::string>(), row.loop = r["loop"].get<std::string>();
    row.frames = r["frames"].get<uint32_t>();
    row.polygons = r["polygons"].get<uint64_t>(), row.rejected = r["rejected"].get<uint64_t>();
    row.spans = r["spans"].get<uint64_t>(), row.pixels = r["pixels"].get<uint64_t>();
    row.ticks = sum_of(r, "ticks"), row.geometry = sum_of(r, "ticks_geometry"), row.clear = sum_of(r, "ticks_clear");
    row.draw = sum_of(r, "ticks_draw"), row.setup = sum_of(r, "ticks_setup"), row.walk = sum_of(r, "ticks_walk");
    row.inner = sum_of(r, "ticks_inner"), row.choose = sum_of(r, "ticks_choose"), row.blit = sum_of(r, "ticks_blit");
    for (const json& d : r["drawn_by"])
        row.drawn_by.emplace_back(d["mapper"].get<std::string>(), d["polygons"].get<uint64_t>(), d["pixels"].get<uint64_t>());
    row.enveloped = r.value("enveloped", uint64_t(0));
    row.proven_whole = r.value("proven_whole", uint64_t(0)), row.proven_spans = r.value("proven_spans", uint64_t(0));
    const raster::Budget& b = budget ? *budget : s.host.world->budget;
    row.budget_error = b.max_error, row.budget_exact = b.exact_coverage, row.budget_given = b.given;
    row.budget = budget_words(b);

    // accuracy on the host twin, the same frames; the last one also against the kernel's screen
    const raster::Axis axis = row.walker == "rows" ? raster::Axis::Rows : raster::Axis::Columns;
    const int32_t length = s.host.world->frames;
    for (int i = 0; i < frames; ++i) {
        int32_t n = int32_t(int64_t(i) * length / frames);
        auto frame = world_frame(s.host, n);
        if (budget) frame->budget = *budget;
        raster::accumulate(row.accuracy, measure_world_frame(s.host, *frame, m, axis));
        if (!m.is_auto) {
            const FrameBound proof = world_frame_bound(s.host, *frame, m, axis);
            row.max_bound = i == 0 || proof.footprint > row.max_bound ? proof.footprint : row.max_bound;
            row.bound_exact = (i == 0 || row.bound_exact) && proof.exact_coverage;
        }
        if (i == frames - 1) {
            if (last["frame"].get<int32_t>() != n) throw HarnessError("the kernel benched frame " + last["frame"].dump() + ", expected " + std::to_string(n));
            IndexImage want = render_world_frame(s.host, *frame, m, axis);
            RgbImage dump = k.screendump("bench-" + s.name + "-" + m.name);
            row.kernel_equals_host = dump.rgb == screendump_of(want, s.host.world->palette).rgb;
        }
    }
    return row;
}

// Every single mapper's rows and auto's at the scene's budget benched again in `k` (the same
// frames), the progress named `label`: each must draw the pixels it drew before; `after` takes the
// scene, the row, the reply and the last frame's event. Ends the session.
template <typename After>
void bench_again(Session& k, const std::string& label, std::vector<BenchScene>& scenes, int frames, std::vector<TradeRow>& rows, After after) {
    auto taken = [](const TradeRow& r) { return single_mapper(r) || r.mapper == "auto"; };
    k.ok("mode modex");
    size_t done = 0, total = 0;
    for (const TradeRow& r : rows) total += taken(r);
    for (BenchScene& s : scenes) {
        load_in_kernel(k, s);
        for (TradeRow& row : rows) {
            if (row.scene != s.name || !taken(row)) continue;
            std::fprintf(stderr, "[%s %zu/%zu] %s %s ", label.c_str(), ++done, total, s.name.c_str(), row.mapper.c_str());
            json last;
            const json r = k.ok("bench " + std::to_string(frames) + " " + row.mapper + " " + row.surface, [&](const json& e) { last = e; });
            if (r["pixels"].get<uint64_t>() != row.pixels)
                throw HarnessError(s.name + " " + row.mapper + ": the " + label + " pass drew " + r["pixels"].dump() + " pixels, the first " +
                                   std::to_string(row.pixels));
            after(s, row, r, last);
        }
    }
    k.ok("exit 0");
    k.wait_exit();
}

// The 486's build of the kernel's C++ (booted isa=i486; the bench's QEMU CPU, a P6, runs the P6's
// otherwise): every mapper's row and auto's at the scene's budget drawn again, the same pixels and
// the same picture as the host's, their drawing's ticks kept in draw_i486.
void bench_486_path(const SessionOptions& p6, std::vector<BenchScene>& scenes, int frames, std::vector<TradeRow>& rows) {
    SessionOptions o = p6;
    o.name = "bench-i486";
    o.append += " isa=i486";
    Session k(o);
    const json hello = k.ok("hello");
    if (hello.value("isa", std::string()) != "i486") throw HarnessError("the kernel booted isa=i486 runs the " + hello.value("isa", std::string("?")) + " build");
    bench_again(k, "486 path", scenes, frames, rows, [&](BenchScene& s, TradeRow& row, const json& r, const json& last) {
        const raster::Mapper& m = *raster::find_mapper({row.mapper.data(), row.mapper.size()});
        auto frame = world_frame(s.host, last["frame"].get<int32_t>());
        const raster::Axis axis = row.walker == "rows" ? raster::Axis::Rows : raster::Axis::Columns;
        const IndexImage want = render_world_frame(s.host, *frame, m, axis);
        const bool equal = k.screendump("bench-i486-" + s.name + "-" + m.name).rgb == screendump_of(want, s.host.world->palette).rgb;
        row.kernel_equals_host = row.kernel_equals_host && equal;
        row.draw_i486 = sum_of(r, "ticks_draw");
        std::fprintf(stderr, "%.1f instructions/pixel drawing (P6 path %.1f)%s\n", row.per_pixel(row.draw_i486), row.draw_per_pixel(),
                     equal ? "" : ", kernel DIFFERS from host");
    });
}

// The timing model's cycles (docs/cycles.md, "Whole frames"): the kernel under QEMU's `-cpu
// target` with the timing plugin, every single mapper's rows and auto's at the scene's budget drawn
// again, the plugin's rows (a bench row and bus each) kept in the row; and auto's row once more with
// the scene's budget priced for the target (docs/auto.md, "Per target"), its picture the host's.
void cycles_pass(const SessionOptions& p6, const std::string& target, std::vector<BenchScene>& scenes, int frames, std::vector<TradeRow>& rows) {
    SessionOptions o = p6;
    o.name = "bench-" + target;
    o.cpu = target;
    TimingPlugin plugin;
    plugin.cpu = target, plugin.buses = {"zero-wait", "isa", "vlb"};
    plugin.out = build_dir() + "/runs/bench-" + target + ".cycles.jsonl";
    std::filesystem::create_directories(build_dir() + "/runs");
    std::filesystem::remove(plugin.out);
    o.plugin = timing_plugin_spec(plugin, o.image.empty() ? build_dir() + "/kernel/modexlab.elf" : o.image);
    Session k(o);
    size_t read = 0;
    // the plugin's lines of the bench row just run (one a bus)
    auto plugin_lines = [&]() {
        const std::vector<json> lines = timing_plugin_rows(plugin.out);
        if (lines.size() != read + plugin.buses.size())
            throw HarnessError(plugin.out + ": " + std::to_string(lines.size()) + " lines after " + std::to_string(read / plugin.buses.size() + 1) +
                               " rows; expected one a bus each row");
        std::vector<json> mine(lines.begin() + std::ptrdiff_t(read), lines.end());
        read = lines.size();
        return mine;
    };
    auto draw_cycles = [](const json& l) {
        return l["setup"].get<uint64_t>() + l["walk"].get<uint64_t>() + l["inner"].get<uint64_t>() + l["choose"].get<uint64_t>();
    };
    raster::CostTarget priced_for = raster::CostTarget::Icount;
    if (!raster::cost_target_named(target.data(), target.size(), &priced_for)) throw HarnessError("no cost model for the target '" + target + "'");
    bench_again(k, target, scenes, frames, rows, [&](BenchScene& s, TradeRow& row, const json&, const json&) {
        const std::vector<json> lines = plugin_lines();
        TradeRow::Cycles& c = row.cycles_on(target);
        for (size_t b = 0; b < plugin.buses.size(); ++b) c.frame[b] = lines[b]["frame_cycles"].get<uint64_t>();
        c.setup = lines[0]["setup"].get<uint64_t>(), c.walk = lines[0]["walk"].get<uint64_t>();
        c.inner = lines[0]["inner"].get<uint64_t>(), c.choose = lines[0]["choose"].get<uint64_t>();
        c.draw = draw_cycles(lines[0]);
        std::fprintf(stderr, "%.1f cycles/pixel drawing, %.1f a frame's pixel (zero-wait), %.1f (isa)\n", row.per_pixel(c.draw),
                     row.per_pixel(c.frame[0]), row.per_pixel(c.frame[1]));
        if (row.mapper != "auto") return;
        raster::Budget priced = s.host.world->budget;
        priced.target = priced_for;
        k.ok("budget " + (priced.max_error < 0 ? std::string("any") : budget_text(priced.max_error)) + (priced.exact_coverage ? " exact " : " any ") + target);
        json last;
        const json r = k.ok("bench " + std::to_string(frames) + " auto " + row.surface, [&](const json& e) { last = e; });
        k.ok("budget scene");
        c.priced_draw = draw_cycles(plugin_lines()[0]), c.priced_pixels = r["pixels"].get<uint64_t>();
        c.priced_by.clear();
        for (const json& d : r["drawn_by"]) c.priced_by.emplace_back(d["mapper"].get<std::string>(), d["polygons"].get<uint64_t>(), d["pixels"].get<uint64_t>());
        auto frame = world_frame(s.host, last["frame"].get<int32_t>());
        frame->budget = priced;
        const raster::Axis axis = row.walker == "rows" ? raster::Axis::Rows : raster::Axis::Columns;
        const IndexImage want = render_world_frame(s.host, *frame, *raster::find_mapper("auto"), axis);
        const bool equal = k.screendump("bench-" + target + "-priced-" + s.name).rgb == screendump_of(want, s.host.world->palette).rgb;
        row.kernel_equals_host = row.kernel_equals_host && equal;
        std::fprintf(stderr, "[%s] %s auto priced for the %s: %.1f cycles/pixel drawing%s\n", target.c_str(), s.name.c_str(), target.c_str(),
                     c.priced_pixels ? double(c.priced_draw) / double(c.priced_pixels) : 0.0, equal ? "" : ", kernel DIFFERS from host");
    });
}

// Frames per second in QEMU without icount: the emulator's cost of VGA memory against RAM and
// blit, on this host. Returns a Markdown table.
std::string wall_clock(std::vector<BenchScene>& scenes, const std::string& kernel, bool tty) {
    SessionOptions o;
    o.name = "bench-wall";
    o.image = kernel;
    Session k(o);
    double tsc_hz = k.ok("hello")["tsc_hz"].get<double>();
    k.ok("mode modex");
    struct Way {
        const char* mapper;
        const char* surface;
    };
    const Way ways[] = {{"persp-subdiv-16", "linear"}, {"persp-subdiv-16", "planar"}, {"persp-subdiv-16", "vga"},
                        {"fast-affine", "linear"},     {"fast-columns", "planar"},    {"fast-columns", "vga"}};
    std::ostringstream md;
    md << "## Wall clock in QEMU (TCG, no icount)\n\nFrames per second of `play 60` on this host: what emulated VGA memory costs "
          "against drawing into RAM and blitting. It measures QEMU, not a PC; run to run it varies by some percent.\n\n| scene |";
    for (const Way& w : ways) md << " " << w.mapper << " " << w.surface << " |";
    md << "\n|---|";
    for (size_t i = 0; i < sizeof ways / sizeof ways[0]; ++i) md << "--:|";
    md << "\n";
    for (BenchScene& s : scenes) {
        load_in_kernel(k, s);
        md << "| " << s.name << " |";
        for (const Way& w : ways) {
            if (tty) std::fprintf(stderr, "\r  wall clock: %s, %s %s          ", s.name.c_str(), w.mapper, w.surface);
            json r = k.ok(std::string("play 60 ") + w.mapper + " " + w.surface, [](const json&) {});
            double seconds = r["ticks_wall"].get<double>() / tsc_hz;
            bool all = r["pixels"].get<uint64_t>() > 0;
            md << " " << (all ? std::to_string(int(60 / seconds + 0.5)) : std::string("-")) << " |";
        }
        md << "\n";
    }
    if (tty) std::fprintf(stderr, "\r%70s\r", "");
    md << "\n(-: the mapper refuses this scene's polygons.)\n";
    k.ok("exit 0");
    k.wait_exit();
    return md.str();
}

// Real host cycles (modexlab-cycles, 32-bit static): each row's cycles per pixel as a ratio to the
// baseline mapper's on the same scene, timed in the same run. Returns the baseline's name, or ""
// where this machine runs 32-bit programs only under an emulator, whose timings mean nothing: the
// rows are then left without host cycles, and `why` says so.
std::string host_cycles(const std::vector<BenchScene>& scenes, const std::vector<const raster::Mapper*>& mappers, int frames,
                        std::vector<TradeRow>& rows, std::string* why) {
    const std::string tool = build_dir() + "/host32/modexlab-cycles", run32 = build_dir() + "/host32/run32";
    for (const std::string& f : {tool, run32})
        if (!std::filesystem::is_regular_file(f)) throw HarnessError(f + " is missing: make host builds it");
    std::string how;
    if (!command_output("'" + run32 + "' --how", &how)) throw HarnessError(run32 + " --how failed: " + how);
    if (how.rfind("emulated: ", 0) == 0) {
        const std::string base = "this machine runs no 32-bit programs natively", reason = how.substr(10, how.size() - 11);  // "emulated: " ... "\n"
        *why = "Host cycles: not measured, " + base + (reason == base ? "" : " (" + reason + ")") + ".";
        return "";
    }
    if (how != "native\n") throw HarnessError(run32 + " --how said: " + how);
    std::string paths, names, out;
    for (const BenchScene& s : scenes) paths += (paths.empty() ? "" : ",") + s.path;
    for (const raster::Mapper* m : mappers) names += (names.empty() ? "" : ",") + std::string(m->name);
    if (!command_output("'" + tool + "' '" + paths + "' '" + names + "' " + std::to_string(frames) + " '" + build_dir() + "/scenes'", &out))
        throw HarnessError(tool + " failed");
    std::map<std::pair<std::string, std::string>, double> per_pixel;
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);) {
        char scene[200], mapper[100];
        unsigned long long pixels, cycles;
        if (std::sscanf(line.c_str(), "%199s %99s %llu %llu", scene, mapper, &pixels, &cycles) == 4 && pixels)
            per_pixel[{scene, mapper}] = double(cycles) / double(pixels);
    }
    const std::string baseline = "affine";
    for (TradeRow& r : rows) {
        auto mine = per_pixel.find({r.scene, r.mapper}), base = per_pixel.find({r.scene, baseline});
        if (mine != per_pixel.end() && base != per_pixel.end()) r.host_ratio = mine->second / base->second;
    }
    return baseline;
}

void write_text(const std::string& path, const std::string& text) {
    FILE* f = std::fopen(path.c_str(), "w");
    if (!f) throw HarnessError(path + ": cannot write");
    bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (std::fclose(f) != 0 || !ok) throw HarnessError(path + ": cannot write");
}

// What the kernel takes from a trade.csv: the cost model fitted to it, as DIR/costs.cpp, and the
// measured errors, as DIR/errors.cpp (make bench copies both into kernel/mappers).
void write_costs(const std::string& csv, const std::string& dir) {
    std::filesystem::create_directories(dir);
    const std::vector<std::vector<std::string>> rows = read_csv(csv);
    const std::string source = std::filesystem::path(csv).filename().string() + " of a make bench run";
    harness::FittedModel models[int(raster::CostTarget::Count)];
    for (int t = 0; t < int(raster::CostTarget::Count); ++t) models[t] = fit_costs(rows, raster::CostTarget(t));
    write_text(dir + "/costs.cpp", cost_model_source(models, source));
    write_text(dir + "/errors.cpp", measured_errors_source(rows, source));
    std::printf("cost model: %s/costs.cpp, measured errors: %s/errors.cpp\n", dir.c_str(), dir.c_str());
}

// The docs' generated tables (trade_docs.h) from `csv`, each file rewritten only where it changed.
void refresh_docs(const std::string& csv) {
    const std::vector<TradeRow> rows = read_trade(csv);
    for (const std::string& path : GENERATED_DOCS) {
        const std::string text = read_whole_file(path);
        int blocks = 0;
        const std::string fresh = refresh_generated(text, rows, path, &blocks);
        if (fresh != text) write_text(path, fresh);
        std::printf("%s: %d generated tables, %s\n", path.c_str(), blocks, fresh == text ? "unchanged" : "refreshed (commit it)");
    }
    // the README's plot, drawn again from the same rows
    const std::string dir = build_dir() + "/report-docs", png = write_plot(dir, "corridor", rows);
    if (!png.empty()) std::filesystem::copy_file(png, "docs/img/trade-corridor.png", std::filesystem::copy_options::overwrite_existing);
    std::printf("docs/img/trade-corridor.png: %s\n", png.empty() ? "not drawn (no gnuplot)" : "drawn again");
}

int run(const Args& a) {
    if (!a.refresh_docs.empty()) {
        refresh_docs(a.refresh_docs);
        return 0;
    }
    if (!a.costs_from.empty()) {
        write_costs(a.costs_from, a.out);
        return 0;
    }
    const bool tty = isatty(2);
    std::vector<BenchScene> scenes;
    for (const std::string& spec : a.scenes) scenes.push_back(open_scene(spec));
    std::vector<const raster::Mapper*> mappers;
    for (const std::string& name : a.mappers) mappers.push_back(raster::find_mapper({name.data(), name.size()}));

    SessionOptions o;
    o.name = "bench";
    o.image = a.kernel;
    o.icount = true;
    o.command_timeout = std::chrono::milliseconds(300000);
    std::fprintf(stderr, "modexlab-bench: %zu scenes x %zu mappers, %d frames each, in QEMU with -icount shift=0 (ticks = guest instructions)\n",
                 scenes.size(), mappers.size(), a.frames);
    Session k(o);
    k.ok("mode modex");
    std::vector<TradeRow> rows;
    const size_t total = scenes.size() * mappers.size();
    size_t benched = 0;
    for (BenchScene& s : scenes) {
        load_in_kernel(k, s);
        for (const raster::Mapper* m : mappers) {
            std::fprintf(stderr, "[%zu/%zu] %s %s ", ++benched, total, s.name.c_str(), m->name);
            TradeRow row = bench_one(k, s, *m, a.frames);
            if (row.pixels) std::fprintf(stderr, "%.1f instructions/pixel, mean texel error %.3f%s\n", row.frame_per_pixel(),
                                         row.accuracy.mean_texel_error, row.kernel_equals_host ? "" : ", kernel DIFFERS from host");
            else std::fprintf(stderr, "refuses every polygon\n");
            rows.push_back(row);
        }
        for (const raster::Mapper* m : mappers) {
            if (!m->is_auto) continue;
            for (double e : AUTO_BUDGETS) {
                raster::Budget b{true, e, true};
                std::fprintf(stderr, "[%s] %s auto at budget %s ", s.name.c_str(), s.name.c_str(), budget_text(e).c_str());
                TradeRow row = bench_one(k, s, *m, a.frames, &b);
                std::fprintf(stderr, "%.1f instructions/pixel, max footprint error %.3f%s\n", row.frame_per_pixel(),
                             row.accuracy.max_footprint_error, row.kernel_equals_host ? "" : ", kernel DIFFERS from host");
                rows.push_back(row);
            }
        }
    }
    k.ok("exit 0");
    k.wait_exit();
    bench_486_path(o, scenes, a.frames, rows);
    for (const std::string& t : a.targets) cycles_pass(o, t, scenes, a.frames, rows);
    mark_pareto(rows);
    std::fprintf(stderr, "host cycles: every mapper again, natively (32-bit, rdtsc)\n");
    std::string unmeasured;
    const std::string baseline = host_cycles(scenes, mappers, a.frames, rows, &unmeasured);
    if (!unmeasured.empty()) std::fprintf(stderr, "%s\n", unmeasured.c_str());

    ReportInfo info;
    info.how = "Measured in the kernel under QEMU 7.2 TCG with `-icount shift=0,align=off,sleep=off`: ticks are guest "
               "instructions, identical run to run. " + std::to_string(a.frames) + " frames a scene, spread evenly over its animation; "
               "per-pixel figures divide by the pixels the mapper drew. Accuracy: the host build of the same code against the exact "
               "reference, on the same frames. " +
               (baseline.empty() ? unmeasured
                                 : "Host cycles: the same code built as a 32-bit static program (NASM loops included) drawing the "
                                   "same frames into RAM on the machine that ran the bench, timed with rdtsc (the least of 9 runs a "
                                   "frame), as a ratio to `" + baseline + "` on the same scene (below 1: faster than it).");
    info.command = "make bench";
    if (a.wall) info.wall_clock = wall_clock(scenes, a.kernel, tty);
    for (const BenchScene& s : scenes)
        for (const std::string target : {"", "486", "pentium"}) {
            const std::string png = write_plot(a.out, s.name, rows, target);
            if (!png.empty()) info.plots.push_back(std::filesystem::path(png).filename().string());
        }
    // trade.md from the CSV read back: the figures it shows are the CSV's, as the docs' tables are
    write_csv(a.out + "/trade.csv", rows);
    write_markdown(a.out + "/trade.md", read_trade(a.out + "/trade.csv"), info);
    write_costs(a.out + "/trade.csv", a.out);
    int differs = 0;
    for (const TradeRow& r : rows) differs += !r.kernel_equals_host;
    std::printf("report: %s/trade.csv, %s/trade.md, %zu plots (%s/trade-SCENE.png)\n", a.out.c_str(), a.out.c_str(), info.plots.size(), a.out.c_str());
    if (differs) std::printf("modexlab-bench: %d kernel pictures DIFFER from the host's\n", differs);
    return differs ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    return run_cli("modexlab-bench", USAGE, argc, argv, [](const std::vector<std::string>& words) {
        std::optional<Args> a = parse(words);
        return a ? run(*a) : show_usage(USAGE);
    });
}
