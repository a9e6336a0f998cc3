// The report: CSV for tools, Markdown for people, a plot per scene.
#include "qemu/tools/trade.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "kernel/core/footprint.h"
#include "kernel/core/mapper.h"
#include "qemu/lib/command_line.h"
#include "qemu/lib/error.h"
#include "qemu/tools/cycles_report.h"
#include "qemu/tools/published.h"

namespace harness {

std::string fixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::vector<std::string> scenes_in_order(const std::vector<TradeRow>& rows) {
    std::vector<std::string> scenes;
    for (const TradeRow& r : rows)
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    return scenes;
}

std::ofstream open_out(const std::string& path) {
    std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    std::ofstream out(path);
    if (!out) throw HarnessError(path + ": cannot write");
    return out;
}

std::vector<const TradeRow*> drawing_rows_by_speed(const std::vector<TradeRow>& rows, const std::string& scene) {
    std::vector<const TradeRow*> out;
    for (const TradeRow& r : rows)
        if (r.scene == scene && r.pixels > 0) out.push_back(&r);
    std::stable_sort(out.begin(), out.end(), [](const TradeRow* a, const TradeRow* b) { return a->draw_per_pixel() < b->draw_per_pixel(); });
    return out;
}

std::string budget_text(double max_error) {
    char t[32];
    std::snprintf(t, sizeof t, "%g", max_error);
    return t;
}

std::string budget_words(const raster::Budget& b) {
    return (b.max_error < 0 ? std::string("any footprint error") : "footprint error " + budget_text(b.max_error)) +
           (b.exact_coverage ? ", exact coverage" : ", any coverage") +
           (b.target == raster::CostTarget::Icount ? "" : std::string(", priced for the ") + raster::cost_target_name(b.target)) +
           (b.given ? "" : ": the default");
}

std::string unknown_mapper(const std::string& name, const std::vector<std::string>& also) {
    std::vector<std::string> names = also;
    for (int i = 0; i < raster::MAPPER_COUNT; ++i) names.push_back(raster::MAPPERS[i].name);
    return "unknown mapper '" + name + "' (the mappers, the nearest first: " + nearest_first(name, names) + ")";
}

std::vector<std::string> known_mappers(std::vector<std::string> names) {
    for (const std::string& m : names)
        if (!raster::find_mapper({m.data(), m.size()})) throw UsageError(unknown_mapper(m));
    return names;
}

std::vector<size_t> pareto_front(const std::vector<std::pair<double, double>>& points) {
    std::vector<size_t> front;
    for (size_t i = 0; i < points.size(); ++i) {
        bool dominated = false;
        for (size_t k = 0; k < points.size() && !dominated; ++k) {
            if (k == i) continue;
            const auto& a = points[k];
            const auto& b = points[i];
            dominated = a.first <= b.first && a.second <= b.second && (a.first < b.first || a.second < b.second);
        }
        if (!dominated) front.push_back(i);
    }
    return front;
}

void mark_pareto(std::vector<TradeRow>& rows) {
    for (const std::string& scene : scenes_in_order(rows)) {
        std::vector<size_t> index;
        std::vector<std::pair<double, double>> points;
        for (size_t i = 0; i < rows.size(); ++i) {
            if (rows[i].scene != scene) continue;
            rows[i].pareto = false;
            if (!rows[i].draws_everything()) continue;
            index.push_back(i);
            points.emplace_back(rows[i].draw_per_pixel(), rows[i].accuracy.mean_footprint_error);
        }
        for (size_t k : pareto_front(points)) rows[index[k]].pareto = true;
    }
}

std::vector<std::string> csv_header() {
    return {"scene", "mapper", "family", "surface", "walker", "loop", "frames[count]", "polygons[count]", "rejected[count]",
            "spans[count]", "pixels[count]", "ticks_frame[instructions]", "ticks_geometry[instructions]",
            "ticks_clear[instructions]", "ticks_draw[instructions]", "ticks_setup[instructions]", "ticks_walk[instructions]",
            "ticks_inner[instructions]", "ticks_choose[instructions]", "ticks_blit[instructions]", "inner_per_pixel[instructions/pixel]",
            "draw_per_pixel[instructions/pixel]", "frame_per_pixel[instructions/pixel]", "setup_per_polygon[instructions/polygon]", "walk_per_span[instructions/span]",
            "host_cycles_ratio[ratio]", "max_texel_error[texels]", "mean_texel_error[texels]", "p999_texel_error[texels]",
            "max_footprint_error[footprints]", "mean_footprint_error[footprints]", "p999_footprint_error[footprints]",
            "folded[pixels]", "share_exact[share]",
            "share_within_one[share]", "reference_pixels[pixels]", "gaps[pixels]", "overdraw[pixels]", "overlaps[pixels]",
            "index_differs[pixels]", "kernel_equals_host[bool]", "pareto[bool]", "max_bound[footprints]", "bound_exact_coverage[bool]",
            "drawn_by[mapper:polygons:pixels;...]", "compared[pixels]", "exact[pixels]", "within_one[pixels]", "enveloped[polygons]",
            "budget_error[footprints]", "budget_exact[bool]", "budget_given[bool]", "draw_per_pixel_i486[instructions/pixel]",
            "ticks_draw_i486[instructions]",
            "cycles_486_draw[cycles]", "cycles_486_inner[cycles]", "cycles_486_frame_zero-wait[cycles]", "cycles_486_frame_isa[cycles]",
            "cycles_486_frame_vlb[cycles]", "cycles_pentium_draw[cycles]", "cycles_pentium_inner[cycles]",
            "cycles_pentium_frame_zero-wait[cycles]", "cycles_pentium_frame_isa[cycles]", "cycles_pentium_frame_vlb[cycles]",
            "cycles_486_setup[cycles]", "cycles_486_walk[cycles]", "cycles_486_choose[cycles]",
            "cycles_pentium_setup[cycles]", "cycles_pentium_walk[cycles]", "cycles_pentium_choose[cycles]",
            "cycles_486_priced_draw[cycles]", "cycles_486_priced_pixels[pixels]", "drawn_by_priced_486[mapper:polygons:pixels;...]",
            "cycles_pentium_priced_draw[cycles]", "cycles_pentium_priced_pixels[pixels]", "drawn_by_priced_pentium[mapper:polygons:pixels;...]",
            "proven_whole[polygons]", "proven_spans[polygons]"};
}

namespace {

// (an unmeasured count: an empty field)
std::string count_or_empty(uint64_t n) { return n ? std::to_string(n) : ""; }

// mapper:polygons:pixels;...
std::string drawn_by_text(const TradeRow::DrawnBy& d) {
    std::string out;
    for (size_t i = 0; i < d.size(); ++i)
        out += (i ? ";" : "") + std::get<0>(d[i]) + ":" + std::to_string(std::get<1>(d[i])) + ":" + std::to_string(std::get<2>(d[i]));
    return out;
}

}  // namespace

void write_csv(const std::string& path, const std::vector<TradeRow>& rows) {
    std::ofstream out = open_out(path);
    std::vector<std::string> header = csv_header();
    for (size_t i = 0; i < header.size(); ++i) out << (i ? "," : "") << header[i];
    out << "\n";
    for (const TradeRow& r : rows) {
        const raster::AccuracyMetrics& a = r.accuracy;
        out << r.scene << "," << r.mapper << "," << r.family << "," << r.surface << "," << r.walker << "," << r.loop << ","
            << r.frames << "," << r.polygons << "," << r.rejected << "," << r.spans << "," << r.pixels << "," << r.ticks << ","
            << r.geometry << "," << r.clear << "," << r.draw << "," << r.setup << "," << r.walk << "," << r.inner << ","
            << r.choose << "," << r.blit << "," << fixed(r.inner_per_pixel(), 3) << "," << fixed(r.draw_per_pixel(), 3) << "," << fixed(r.frame_per_pixel(), 3) << ","
            << fixed(r.setup_per_polygon(), 1) << "," << fixed(r.walk_per_span(), 1) << ","
            << (r.host_ratio > 0 ? fixed(r.host_ratio, 3) : "") << "," << a.max_texel_error << ","
            << fixed(a.mean_texel_error, 4) << "," << a.p999_texel_error << "," << fixed(a.max_footprint_error, 4) << ","
            << fixed(a.mean_footprint_error, 4) << "," << fixed(a.p999_footprint_error, 4) << "," << a.folded << ","
            << fixed(r.share_exact(), 4) << ","
            << fixed(a.compared ? double(a.within_one) / a.compared : 0.0, 4) << "," << a.reference_pixels << "," << a.gaps
            << "," << a.overdraw << "," << a.overlaps << "," << a.index_differs << "," << (r.kernel_equals_host ? "true" : "false")
            << "," << (r.pareto ? "true" : "false") << "," << (r.max_bound < 0 ? "" : r.max_bound >= raster::NO_BOUND ? "none" : fixed(r.max_bound, 4))
            << "," << (r.max_bound < 0 ? "" : r.bound_exact ? "true" : "false") << ",";
        out << drawn_by_text(r.drawn_by) << "," << a.compared << "," << a.exact << "," << a.within_one << "," << r.enveloped << ","
            << (r.budget_error < 0 ? "any" : budget_text(r.budget_error)) << "," << (r.budget_exact ? "true" : "false") << ","
            << (r.budget_given ? "true" : "false") << "," << (r.draw_i486 ? fixed(r.per_pixel(r.draw_i486), 3) : "") << ","
            << (r.draw_i486 ? std::to_string(r.draw_i486) : "");
        for (const TradeRow::Cycles* c : {&r.cycles_486, &r.cycles_pentium})
            out << "," << count_or_empty(c->draw) << "," << count_or_empty(c->inner) << "," << count_or_empty(c->frame[0]) << ","
                << count_or_empty(c->frame[1]) << "," << count_or_empty(c->frame[2]);
        for (const TradeRow::Cycles* c : {&r.cycles_486, &r.cycles_pentium})
            out << "," << count_or_empty(c->setup) << "," << count_or_empty(c->walk) << "," << count_or_empty(c->choose);
        for (const TradeRow::Cycles* c : {&r.cycles_486, &r.cycles_pentium}) 
            out << "," << count_or_empty(c->priced_draw) << "," << count_or_empty(c->priced_pixels) << "," << drawn_by_text(c->priced_by);
        out << "," << r.proven_whole << "," << r.proven_spans << "\n";
    }
}

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw HarnessError(path + ": cannot open (" + std::strerror(errno) + ")");
    std::vector<std::vector<std::string>> lines;
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> fields;
        std::stringstream ss(line);
        for (std::string f; std::getline(ss, f, ',');) fields.push_back(f);
        if (!line.empty() && line.back() == ',') fields.push_back("");
        lines.push_back(fields);
    }
    return lines;
}

size_t csv_column(const std::vector<std::string>& header, const std::string& name, const std::string& where) {
    for (size_t i = 0; i < header.size(); ++i)
        if (header[i] == name || header[i].rfind(name + "[", 0) == 0) return i;
    throw HarnessError(where + ": no column '" + name + "' (a trade.csv of an older make bench: run it again)");
}

std::vector<TradeRow> read_trade(const std::string& path) {
    const std::vector<std::vector<std::string>> lines = read_csv(path);
    if (lines.empty()) throw HarnessError(path + ": empty, not a trade.csv");
    const std::vector<std::string>& header = lines[0];
    auto column = [&](const std::string& name) { return csv_column(header, name, path); };
    std::vector<TradeRow> rows;
    for (size_t n = 1; n < lines.size(); ++n) {
        const std::vector<std::string>& f = lines[n];
        const std::string where = path + ": line " + std::to_string(n + 1) + ": ";
        if (f.size() != header.size())
            throw HarnessError(where + std::to_string(f.size()) + " fields, the header has " + std::to_string(header.size()));
        auto text = [&](const char* name) -> const std::string& { return f[column(name)]; };
        auto number = [&](const char* name) {
            const std::string& s = text(name);
            char* end = nullptr;
            const double v = std::strtod(s.c_str(), &end);
            if (s.empty() || *end) throw HarnessError(where + name + " '" + s + "' is not a number");
            return v;
        };
        auto count = [&](const char* name) {
            const std::string& s = text(name);
            char* end = nullptr;
            const unsigned long long v = std::strtoull(s.c_str(), &end, 10);
            if (s.empty() || *end || s[0] == '-') throw HarnessError(where + name + " '" + s + "' is not a count");
            return uint64_t(v);
        };
        auto flag = [&](const char* name) {
            const std::string& s = text(name);
            if (s != "true" && s != "false") throw HarnessError(where + name + " '" + s + "' is not true or false");
            return s == "true";
        };
        TradeRow r;
        r.scene = text("scene"), r.mapper = text("mapper"), r.family = text("family"), r.surface = text("surface");
        r.walker = text("walker"), r.loop = text("loop");
        r.frames = uint32_t(count("frames")), r.polygons = count("polygons"), r.rejected = count("rejected");
        r.spans = count("spans"), r.pixels = count("pixels");
        r.ticks = count("ticks_frame"), r.geometry = count("ticks_geometry"), r.clear = count("ticks_clear"), r.draw = count("ticks_draw");
        r.setup = count("ticks_setup"), r.walk = count("ticks_walk"), r.inner = count("ticks_inner"), r.choose = count("ticks_choose");
        r.blit = count("ticks_blit");
        r.host_ratio = text("host_cycles_ratio").empty() ? 0 : number("host_cycles_ratio");
        raster::AccuracyMetrics& a = r.accuracy;
        a.max_texel_error = uint32_t(count("max_texel_error")), a.mean_texel_error = number("mean_texel_error");
        a.p999_texel_error = uint32_t(count("p999_texel_error"));
        a.max_footprint_error = number("max_footprint_error"), a.mean_footprint_error = number("mean_footprint_error");
        a.p999_footprint_error = number("p999_footprint_error");
        a.folded = uint32_t(count("folded")), a.reference_pixels = uint32_t(count("reference_pixels"));
        a.gaps = uint32_t(count("gaps")), a.overdraw = uint32_t(count("overdraw")), a.overlaps = uint32_t(count("overlaps"));
        a.index_differs = uint32_t(count("index_differs"));
        a.compared = uint32_t(count("compared")), a.exact = uint32_t(count("exact")), a.within_one = uint32_t(count("within_one"));
        r.kernel_equals_host = flag("kernel_equals_host"), r.pareto = flag("pareto");
        const std::string& bound = text("max_bound");
        r.max_bound = bound.empty() ? -1 : bound == "none" ? raster::NO_BOUND : number("max_bound");
        r.bound_exact = !bound.empty() && flag("bound_exact_coverage");
        auto drawn_by = [&](const std::string& name, TradeRow::DrawnBy* to) {
            std::stringstream drawn(text(name.c_str()));
            for (std::string item; std::getline(drawn, item, ';');) {
                const size_t c1 = item.find(':'), c2 = item.rfind(':');
                if (c1 == std::string::npos || c2 == c1) throw HarnessError(where + name + " '" + item + "' is not mapper:polygons:pixels");
                to->emplace_back(item.substr(0, c1), std::stoull(item.substr(c1 + 1, c2 - c1 - 1)), std::stoull(item.substr(c2 + 1)));
            }
        };
        drawn_by("drawn_by", &r.drawn_by);
        r.enveloped = count("enveloped");
        r.budget_error = text("budget_error") == "any" ? raster::ANY_ERROR : number("budget_error");
        r.budget_exact = flag("budget_exact"), r.budget_given = flag("budget_given");
        r.budget = budget_words(raster::Budget{r.budget_given, r.budget_error, r.budget_exact});
        r.draw_i486 = text("ticks_draw_i486").empty() ? 0 : count("ticks_draw_i486");
        // the timing model's columns and the proofs' levels, where the CSV has them (a bench of an
        // earlier version has not)
        auto optional = [&](const std::string& name) {
            const bool has = std::find_if(header.begin(), header.end(), [&](const std::string& h) { return h.rfind(name + "[", 0) == 0; }) != header.end();
            return !has || text(name.c_str()).empty() ? 0 : count(name.c_str());
        };
        r.proven_whole = optional("proven_whole"), r.proven_spans = optional("proven_spans");
        r.levels_known = std::find_if(header.begin(), header.end(), [](const std::string& h) { return h.rfind("proven_whole[", 0) == 0; }) != header.end();
        auto cycles = [&](const std::string& target, TradeRow::Cycles* c) {
            const std::string p = "cycles_" + target + "_";
            c->draw = optional(p + "draw"), c->inner = optional(p + "inner");
            c->setup = optional(p + "setup"), c->walk = optional(p + "walk"), c->choose = optional(p + "choose");
            c->frame[0] = optional(p + "frame_zero-wait"), c->frame[1] = optional(p + "frame_isa"), c->frame[2] = optional(p + "frame_vlb");
            c->priced_draw = optional(p + "priced_draw"), c->priced_pixels = optional(p + "priced_pixels");
            if (c->priced_draw) drawn_by("drawn_by_priced_" + target, &c->priced_by);
        };
        cycles("486", &r.cycles_486);
        cycles("pentium", &r.cycles_pentium);
        rows.push_back(std::move(r));
    }
    return rows;
}

std::string isa_table(const std::vector<TradeRow>& rows) {
    struct Ratios {
        std::vector<double> of;
        double p6 = 0, i486 = 0;  // drawing ticks and pixels summed over the scenes
        uint64_t pixels = 0;
    };
    std::vector<std::pair<std::string, Ratios>> by_mapper;  // in the rows' order
    for (const TradeRow& r : rows) {
        if (!r.draw_i486 || !r.draw) continue;
        auto it = std::find_if(by_mapper.begin(), by_mapper.end(), [&](const auto& m) { return m.first == r.mapper; });
        if (it == by_mapper.end()) it = by_mapper.insert(by_mapper.end(), {r.mapper, Ratios{}});
        it->second.of.push_back(double(r.draw_i486) / double(r.draw));
        it->second.p6 += double(r.draw), it->second.i486 += double(r.draw_i486), it->second.pixels += r.pixels;
    }
    if (by_mapper.empty()) return "";
    std::string t = "| mapper | scenes | P6 build instr/px | 486 build instr/px | 486 / P6 | least | most |\n|---|--:|--:|--:|--:|--:|--:|\n";
    for (const auto& [mapper, m] : by_mapper) {
        const double px = double(m.pixels);
        t += "| " + mapper + " | " + std::to_string(m.of.size()) + " | " + fixed(m.p6 / px, 1) + " | " + fixed(m.i486 / px, 1) + " | " +
             fixed(m.i486 / m.p6, 3) + " | " + fixed(*std::min_element(m.of.begin(), m.of.end()), 3) + " | " +
             fixed(*std::max_element(m.of.begin(), m.of.end()), 3) + " |\n";
    }
    return t;
}

namespace {

// Whether the row's own bounds prove a budget on the whole scene before drawing: everything drawn,
// its largest bound within it, and exact coverage promised if it asks for it.
bool proves_budget(const TradeRow& r, double max_error, bool exact_coverage) {
    return r.draws_everything() && r.max_bound >= 0 && r.max_bound < raster::NO_BOUND && (max_error < 0 || r.max_bound <= max_error) &&
           (!exact_coverage || r.bound_exact);
}

}  // namespace

bool meets_budget(const TradeRow& r, double max_error, bool exact_coverage) {
    return r.draws_everything() && (max_error < 0 || r.accuracy.max_footprint_error <= max_error) &&
           (!exact_coverage || (r.accuracy.gaps == 0 && r.accuracy.overdraw == 0));
}

bool single_mapper(const TradeRow& r) {
    const raster::Mapper* m = raster::find_mapper(r.mapper.c_str());
    return m && !m->is_auto;
}

const TradeRow* fastest_within(const std::vector<TradeRow>& rows, const TradeRow& a) {
    const TradeRow* best = nullptr;
    for (const TradeRow& r : rows)
        if (r.scene == a.scene && single_mapper(r) && meets_budget(r, a.budget_error, a.budget_exact) &&
            (!best || r.draw_per_pixel() < best->draw_per_pixel()))
            best = &r;
    return best;
}

std::string proof_levels(const TradeRow& a) {
    if (!a.levels_known) return "-";
    return std::to_string(a.enveloped) + " / " + std::to_string(a.proven_whole) + " / " + std::to_string(a.proven_spans) + " / " +
           std::to_string(a.unasked());
}

namespace {

// An auto row (`auto`, or `auto@B` at a budget of B).
bool auto_row(const TradeRow& r) {
    const raster::Mapper* m = raster::find_mapper(r.mapper.substr(0, r.mapper.find('@')).c_str());
    return m && m->is_auto;
}

}  // namespace

// auto against the fastest single mapper that meets the same budget on the whole scene, by its
// measured error; and against the fastest single mapper whose own bounds prove it on every polygon
// (what auto proves of its own choice before drawing).
std::string auto_rows(const std::vector<TradeRow>& rows, bool scene_budget_only) {
    std::string table;
    for (const TradeRow& a : rows) {
        if (!auto_row(a) || !a.pixels || (scene_budget_only && a.mapper != "auto")) continue;
        const TradeRow *best = fastest_within(rows, a), *proven = nullptr;
        for (const TradeRow& r : rows)
            if (r.scene == a.scene && single_mapper(r) && proves_budget(r, a.budget_error, a.budget_exact) &&
                (!proven || r.draw_per_pixel() < proven->draw_per_pixel()))
                proven = &r;
        auto against = [&](const TradeRow* r) {
            return r ? r->mapper + " | " + fixed(r->draw_per_pixel(), 1) + " | " + fixed(r->draw_per_pixel() / a.draw_per_pixel(), 2) + "×"
                     : std::string("none | - | -");
        };
        // what auto draws at with its choosing aside (the choosing itself: Phase::Choose)
        const double choosing = a.per_pixel(a.choose), aside = a.draw_per_pixel() - choosing;
        const std::string share = a.draw ? fixed(100.0 * double(a.choose) / double(a.draw), 1) + "%" : std::string("-");
        table += "| " + a.scene + " | " + a.mapper + " | " + a.budget + " | " + fixed(a.draw_per_pixel(), 1) + " | " + fixed(choosing, 2) +
                 " | " + share + " | " + proof_levels(a) + " | " + fixed(a.accuracy.max_footprint_error, 3) + " | " +
                 (meets_budget(a, a.budget_error, a.budget_exact) ? "yes" : "**NO**") +
                 " | " + against(best) + " | " + (best && aside > 0 ? fixed(best->draw_per_pixel() / aside, 2) + "×" : std::string("-")) + " | " +
                 against(proven) + " |\n";
    }
    if (table.empty()) return "";
    return "| scene | row | budget | draw instr/px | choosing instr/px | choosing's share | polygons proven by object / polygon / "
           "spans / unasked | max footprint err | within | fastest single mapper within | its draw instr/px | speed-up | choosing aside | "
           "fastest single mapper proven within | its draw instr/px | speed-up |\n"
           "|---|---|---|--:|--:|--:|--:|--:|---|---|--:|--:|--:|---|--:|--:|\n" + table;
}

namespace {

// trade.md's auto section: every auto row.
void write_auto_table(std::ostream& out, const std::vector<TradeRow>& rows) {
    const std::string table = auto_rows(rows, false);
    if (table.empty()) return;
    out << "\n## auto against the single mappers\n\n"
        << "auto at the scene's budget and at budgets of 0 to 4 footprints (exact coverage), beside the fastest single mapper "
           "whose measured error meets the same budget on every benched frame of the scene, and the fastest whose own error "
           "bounds prove it on every polygon of those frames before drawing, as auto proves each of its choices (draw "
           "instructions per pixel: setup, walking, inner loops, and auto's choosing). Speed-up above 1: auto is faster. "
           "Choosing: what auto spends a pixel on choosing beyond setting each polygon up (its plans once a frame per object, "
           "the test for polygons too small to choose for, the bounds and the search: the bench's phase probe, "
           "`ticks_choose`); its setup of a polygon with every plane, which the chosen mapper draws from, counts as setup, "
           "and so do the envelope's guards, which run inside fast-affine's own call for the triangle. Choosing aside: the "
           "speed-up were the choosing free. Polygons by the level of their proof (summed over the frames): by their object's "
           "envelope, once a frame for all of them; by the whole polygon's bound or certificate; span by span; unasked: "
           "drawn by the reference's own definition where choosing cannot pay (docs/auto.md).\n\n"
        << table;
    std::string spent;
    for (const TradeRow& a : rows) {
        if (!auto_row(a) || !a.draw || !a.levels_known || double(a.choose) <= 0.03 * double(a.draw)) continue;
        const uint64_t searched = a.proven_whole + a.proven_spans, tested = searched + a.unasked();
        spent += "- " + a.scene + " " + a.mapper + ": " + fixed(100.0 * double(a.choose) / double(a.draw), 1) + "% of its draw, " +
                 fixed(double(a.choose) / double(tested ? tested : 1), 0) + " instructions a polygon it tested: the plans once a frame, "
                 "the test of " + std::to_string(tested) + " polygons (" + std::to_string(a.unasked()) + " then drawn unasked) and the "
                 "proofs and search on " + std::to_string(searched) + " (" + std::to_string(a.proven_spans) + " span by span)\n";
    }
    if (!spent.empty()) out << "\nWhere choosing is over 3% of auto's draw, what it is spent on:\n\n" << spent;
}

// Per polygon drawn, what the outer loops cost beside the inner ones (docs/bench.md): the frame's
// geometry (transform, cull, clip, project: the same for every mapper of a scene), the setup, the
// edge walking and the inner loops, for exact and fast-affine where each draws every polygon.
void write_outer_loops(std::ostream& out, const std::vector<TradeRow>& rows) {
    std::string table;
    for (const std::string& scene : scenes_in_order(rows))
        for (const char* mapper : {"exact", "fast-affine"})
            for (const TradeRow& r : rows) {
                if (r.scene != scene || r.mapper != mapper || !r.draws_everything() || r.polygons == 0 || r.frames == 0) continue;
                const double n = double(r.polygons);
                auto per = [&](uint64_t t) { return fixed(double(t) / n, 0); };
                table += "| " + scene + " | " + mapper + " | " + fixed(n / r.frames, 0) + " | " + fixed(double(r.pixels) / n, 1) + " | " +
                         per(r.geometry) + " | " + per(r.setup) + " | " + per(r.walk) + " | " + per(r.inner) + " | " +
                         per(r.geometry + r.setup + r.walk) + " |\n";
                break;
            }
    if (table.empty()) return;
    out << "\n## The outer loops, per polygon drawn\n\n"
        << "Instructions under QEMU icount per polygon drawn, summed over the benched frames: the frame's geometry (transform, "
           "cull, clip, project; the same whatever the mapper), the setup, the edge walking and the inner loops; outer = "
           "geometry + setup + walking.\n\n"
        << "| scene | mapper | polygons a frame | pixels a polygon | geometry | setup | walking | inner | outer |\n"
        << "|---|---|--:|--:|--:|--:|--:|--:|--:|\n" << table;
}

}  // namespace

std::string scene_table(const std::vector<TradeRow>& rows, const std::string& scene) {
    std::ostringstream out;
    out << "| mapper | surface | inner instr/px | draw instr/px | frame instr/px | setup instr/polygon | walk instr/span | host cycles (ratio) "
           "| texel err max / mean / p99.9 | footprint err max / mean / p99.9 | exact | gaps | overdraw | kernel = host | Pareto |\n";
    out << "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|---|\n";
    for (const TradeRow* r : drawing_rows_by_speed(rows, scene)) {
        const raster::AccuracyMetrics& a = r->accuracy;
        std::string front = r->pareto ? "**yes**" : r->rejected ? "partial: " + std::to_string(r->rejected) + " polygons refused" : "";
        out << "| " << r->mapper << " | " << r->surface << " | " << fixed(r->inner_per_pixel(), 1) << " | "
            << fixed(r->draw_per_pixel(), 1) << " | " << fixed(r->frame_per_pixel(), 1) << " | " << fixed(r->setup_per_polygon(), 0) << " | " << fixed(r->walk_per_span(), 1)
            << " | " << (r->host_ratio > 0 ? fixed(r->host_ratio, 2) : "-") << " | " << a.max_texel_error << " / "
            << fixed(a.mean_texel_error, 3) << " / " << a.p999_texel_error << " | " << fixed(a.max_footprint_error, 2) << " / "
            << fixed(a.mean_footprint_error, 3) << " / " << fixed(a.p999_footprint_error, 2) << " | " << fixed(100 * r->share_exact(), 1) << "% | " << a.gaps << " | " << a.overdraw
            << " | " << (r->kernel_equals_host ? "equal" : "DIFFERS") << " | " << front << " |\n";
    }
    std::string refused;
    for (const TradeRow& r : rows) {
        if (r.scene != scene || r.pixels != 0) continue;
        lib::Fmt needs;
        if (const raster::Mapper* m = raster::find_mapper(r.mapper.c_str())) raster::describe_needs(needs, m->needs & raster::SCENE_NEEDS);
        refused += (refused.empty() ? "" : "; ") + r.mapper + (*needs.c_str() ? std::string(" (needs ") + needs.c_str() + ")" : "");
    }
    if (!refused.empty()) out << "\nCannot draw this scene (every polygon refused): " << refused << ".\n";
    for (const TradeRow& r : rows) {
        if (r.scene != scene || r.drawn_by.size() < 2 || !r.pixels) continue;
        out << "\n" << r.mapper << " (" << r.budget << ") drew with:";
        for (size_t i = 0; i < r.drawn_by.size(); ++i)
            out << (i ? ";" : "") << " " << std::get<0>(r.drawn_by[i]) << " " << std::get<1>(r.drawn_by[i]) << " polygons, "
                << fixed(100.0 * double(std::get<2>(r.drawn_by[i])) / double(r.pixels), 1) << "% of the pixels";
        if (r.enveloped) out << "; " << r.enveloped << " of the polygons proven by their object's envelope";
        out << ".\n";
    }
    return out.str();
}

std::string same_work_table(const std::vector<TradeRow>& rows, const std::string& scene) {
    std::string table = "| mapper | inner instr/px | draw instr/px | setup instr/polygon | walk instr/span | footprint err max / mean |\n"
                        "|---|--:|--:|--:|--:|--:|\n";
    for (const TradeRow& r : rows)
        if (r.scene == scene && single_mapper(r) && !r.draws_everything()) return "";
    for (const TradeRow* r : drawing_rows_by_speed(rows, scene)) {
        if (!single_mapper(*r)) continue;
        table += "| " + r->mapper + " | " + fixed(r->inner_per_pixel(), 1) + " | " + fixed(r->draw_per_pixel(), 1) + " | " +
                 fixed(r->setup_per_polygon(), 0) + " | " + fixed(r->walk_per_span(), 1) + " | " + fixed(r->accuracy.max_footprint_error, 2) +
                 " / " + fixed(r->accuracy.mean_footprint_error, 3) + " |\n";
    }
    return table;
}

namespace {

// The scenes every single mapper draws whole (the same pictures and polygons for all), each
// mapper's figures side by side; the scenes left out, with how many mappers refuse some
// or all of their polygons.
void write_whole_scenes(std::ostream& out, const std::vector<TradeRow>& rows) {
    std::string tables, left_out;
    for (const std::string& scene : scenes_in_order(rows)) {
        int partial = 0, singles = 0;
        for (const TradeRow& r : rows) {
            if (r.scene != scene || !single_mapper(r)) continue;
            ++singles;
            partial += !r.draws_everything();
        }
        if (singles == 0) continue;
        if (partial) {
            left_out += (left_out.empty() ? "" : ", ") + scene + " (" + std::to_string(partial) + " of " + std::to_string(singles) + ")";
            continue;
        }
        tables += "\n### " + scene + "\n\n" + same_work_table(rows, scene);
    }
    out << "\n## Every mapper on the same work\n\n"
        << "Only the scenes where every single mapper draws every polygon (none refused for its texture or its coordinates), "
           "so that each row below is the same pictures from the same polygons; sorted by draw instructions a pixel.\n";
    if (tables.empty()) out << "\nNo scene of this run is drawn whole by every mapper.\n";
    out << tables;
    if (!left_out.empty()) out << "\nLeft out (mappers that refuse some or all of the polygons, of the single mappers): " << left_out << ".\n";
}

}  // namespace

void write_markdown(const std::string& path, const std::vector<TradeRow>& rows, const ReportInfo& info) {
    std::ofstream out = open_out(path);
    out << "# The speed/accuracy trade\n\n" << info.how << "\n\nRegenerate: `" << info.command << "`. The figures and how they are "
        << "measured: docs/bench.md.\n";
    write_auto_table(out, rows);
    for (const std::string& scene : scenes_in_order(rows)) {
        out << "\n## " << scene << "\n\n";
        std::string plot = "trade-" + scene + ".png";
        if (std::find(info.plots.begin(), info.plots.end(), plot) != info.plots.end()) out << "![" << scene << "](" << plot << ")\n\n";
        out << scene_table(rows, scene);
    }

    write_whole_scenes(out, rows);
    write_outer_loops(out, rows);
    const std::string isa = isa_table(rows);
    out << "\n## The 486's build beside the P6's\n\n"
        << "The kernel's C++ is built twice, for the 486 and for the P6 (CMOV, FCOMI), and runs the P6's where CPUID reports CMOV "
           "(docs/platform.md, \"The CPU\"). The bench runs the P6's (QEMU's default CPU), then boots again with `isa=i486` and draws "
           "every single mapper's rows and auto's at each scene's budget with the 486's: drawing instructions a pixel over all the "
           "scenes, their ratio, and the least and the most ratio of a scene. The pictures are the same.\n\n"
        << (isa.empty() ? std::string("(not measured)\n") : isa);
    const std::string cycles = cycles_table(rows), modex = modex_table(rows), fronts = pareto_by_target(rows), priced = auto_by_target(rows),
                      against = auto_against_singles_by_target(rows);
    out << "\n## Cycles on a 486 and a Pentium (the timing model)\n\n"
        << "The same frames run again in the kernel under QEMU's `-cpu 486` and `-cpu pentium` with the timing model's plugin "
           "(docs/cycles.md, \"Whole frames\"): estimated cycles a pixel over all the scenes a mapper drew, of its inner loops, of "
           "its drawing (setup, walking, inner loops, choosing), and of its frames (geometry, clearing, drawing, the blit) with the "
           "display on each bus model: zero-wait (the published counts' terms), isa (a 16-bit card at 8.33 MHz) and vlb. The 486 "
           "at 33 MHz, the Pentium at 90. Single mappers, and auto at each scene's budget.\n\n"
        << (cycles.empty() ? std::string("(not measured: make bench TARGET=486 or TARGET=pentium)\n") : cycles)
        << "\n### The Pareto front on each target\n\n"
        << "Scene by scene: the mappers no other beats both in drawing cycles a pixel on the target and in mean footprint error "
           "(those that draw the whole scene). Where it differs from the front in instructions (the scene tables above), the "
           "machine, not the count, decides.\n\n"
        << (fronts.empty() ? std::string("(not measured)\n") : fronts);
    std::string target_plots;
    for (const std::string& scene : scenes_in_order(rows))
        for (const char* target : {"486", "pentium"}) {
            const std::string plot = "trade-" + scene + "-" + target + ".png";
            if (std::find(info.plots.begin(), info.plots.end(), plot) != info.plots.end())
                target_plots += (target_plots.empty() ? "" : ", ") + std::string("[") + scene + " on the " + target + "](" + plot + ")";
        }
    if (!target_plots.empty()) out << "\nEach scene's plot on each target, drawing cycles a pixel against mean footprint error: " << target_plots << ".\n";
    out << "\n### auto priced for each target\n\n"
        << "auto at each scene's budget, run on the target twice: priced by icount's cost model (as every row above), and with "
           "the budget priced for the target (`budget ... 486|pentium`: the cost model fitted to that target's cycles, "
           "docs/auto.md, \"Per target\"). Drawing cycles a pixel, and what the priced runs drew with, by share of pixels.\n\n"
        << (priced.empty() ? std::string("(not measured)\n") : priced)
        << "\nOn each target, auto at each scene's budget against the fastest single mapper whose measured error meets it, in the "
           "target's drawing cycles a pixel, and choosing's share of auto's drawing cycles there (priced by icount).\n\n"
        << (against.empty() ? std::string("(not measured)\n") : against)
        << "\n### Straight into Mode X, or into RAM and a blit\n\n"
        << "On each scene, target and bus: the fastest whole frame (cycles a pixel drawn) of the mappers that draw straight into "
           "the VGA's page (surface vga), against the fastest that draw into RAM and blit the page (linear, planar). Which wins "
           "depends on the bus, as the Black Book and FastDoom found it depends on the card.\n\n"
        << (modex.empty() ? std::string("(not measured)\n") : modex);

    write_published(out, rows);
    if (!info.wall_clock.empty()) out << "\n" << info.wall_clock;
}

}  // namespace harness
