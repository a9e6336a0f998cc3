// The docs' generated figures.
#include "qemu/tools/trade_docs.h"

#include <algorithm>

#include "qemu/lib/error.h"

namespace harness {

namespace {

const std::string BEGIN = "<!-- make bench: ", BEGIN_END = " -->", END = "<!-- end make bench -->";

}  // namespace

std::string headline_table(const std::vector<TradeRow>& rows) {
    std::string table;
    for (const TradeRow& a : rows) {
        if (a.mapper != "auto" || !a.pixels) continue;
        const TradeRow *best = fastest_within(rows, a), *exact = nullptr;
        for (const TradeRow& r : rows)
            if (r.scene == a.scene && r.mapper == "exact" && r.draws_everything()) exact = &r;
        table += "| " + a.scene + " | " + (a.budget_error < 0 ? std::string("any") : budget_text(a.budget_error)) +
                 (a.budget_exact ? ", exact coverage" : "") + " | " + fixed(a.draw_per_pixel(), 1) + " | " +
                 fixed(a.accuracy.max_footprint_error, 2) + " | " + (best ? best->mapper + " | " + fixed(best->draw_per_pixel(), 1) : "none | -") +
                 " | " + (exact ? fixed(exact->draw_per_pixel(), 1) : "-") + " |\n";
    }
    if (table.empty()) return "";
    return "| scene | budget (footprints) | auto instr/px | auto's max error | fastest single mapper within | its instr/px | exact instr/px |\n"
           "|---|---|--:|--:|---|--:|--:|\n" + table;
}

std::string choices_list(const std::vector<TradeRow>& rows) {
    std::string list;
    for (const TradeRow& a : rows) {
        if (a.mapper != "auto" || !a.pixels || a.drawn_by.empty()) continue;
        list += "- **" + a.scene + "** (" + a.budget + "):";
        for (size_t i = 0; i < a.drawn_by.size(); ++i)
            list += std::string(i ? ";" : "") + " " + std::get<0>(a.drawn_by[i]) + " " + std::to_string(std::get<1>(a.drawn_by[i])) +
                    " polygons, " + fixed(100.0 * double(std::get<2>(a.drawn_by[i])) / double(a.pixels), 1) + "% of the pixels";
        if (a.enveloped) list += "; " + std::to_string(a.enveloped) + " of the polygons proven by their object's envelope";
        list += ".\n";
    }
    return list;
}

std::string generated_block(const std::string& name, const std::vector<TradeRow>& rows) {
    auto scene_of = [&](const std::string& prefix) { return name.substr(prefix.size()); };
    std::string s;
    if (name == "headline") s = headline_table(rows);
    else if (name == "auto") s = auto_rows(rows, false);
    else if (name == "auto at scene budgets") s = auto_rows(rows, true);
    else if (name == "choices") s = choices_list(rows);
    else if (name == "isa") s = isa_table(rows);
    else if (name.rfind("scene ", 0) == 0) {
        bool known = false;
        for (const TradeRow& r : rows) known = known || r.scene == scene_of("scene ");
        if (known) s = scene_table(rows, scene_of("scene "));
    } else if (name.rfind("same-work ", 0) == 0) s = same_work_table(rows, scene_of("same-work "));
    else throw HarnessError("unknown generated block '" + name + "' (headline, scene S, same-work S, auto, auto at scene budgets, choices, isa)");
    if (s.empty()) throw HarnessError("the bench's rows cannot fill the block '" + name + "'");
    return s;
}

std::string refresh_generated(const std::string& text, const std::vector<TradeRow>& rows, const std::string& where, int* blocks) {
    std::string out;
    size_t at = 0;
    int count = 0;
    auto line_of = [&](size_t pos) { return std::to_string(1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(pos), '\n')); };
    for (size_t b; (b = text.find(BEGIN, at)) != std::string::npos;) {
        const size_t name_end = text.find(BEGIN_END, b + BEGIN.size());
        const size_t eol = text.find('\n', b);
        if (name_end == std::string::npos || eol == std::string::npos || name_end > eol)
            throw HarnessError(where + ": line " + line_of(b) + ": a generated block's marker without its ' -->'");
        const size_t e = text.find(END, eol);
        if (e == std::string::npos) throw HarnessError(where + ": line " + line_of(b) + ": a generated block without '" + END + "'");
        const std::string name = text.substr(b + BEGIN.size(), name_end - b - BEGIN.size());
        out += text.substr(at, eol + 1 - at) + generated_block(name, rows);
        at = e;
        ++count;
    }
    out += text.substr(at);
    if (blocks) *blocks = count;
    return out;
}

}  // namespace harness
