// The timing model's tables of the report (cycles_report.h).
#include "qemu/tools/cycles_report.h"

#include <algorithm>
#include <utility>

namespace harness {

std::string cycles_table(const std::vector<TradeRow>& rows) {
    struct Sums {
        double c486[5] = {}, pentium[5] = {};  // inner, draw, frame on each bus; summed over the scenes
        double pixels486 = 0, pixels_pentium = 0;
    };
    std::vector<std::pair<std::string, Sums>> by_mapper;  // in the rows' order
    for (const TradeRow& r : rows) {
        if (!r.pixels || (!r.cycles_486.draw && !r.cycles_pentium.draw)) continue;
        auto it = std::find_if(by_mapper.begin(), by_mapper.end(), [&](const auto& m) { return m.first == r.mapper; });
        if (it == by_mapper.end()) it = by_mapper.insert(by_mapper.end(), {r.mapper, Sums{}});
        auto add = [&](const TradeRow::Cycles& c, double* to, double* pixels) {
            if (!c.draw) return;
            const uint64_t v[5] = {c.inner, c.draw, c.frame[0], c.frame[1], c.frame[2]};
            for (int k = 0; k < 5; ++k) to[k] += double(v[k]);
            *pixels += double(r.pixels);
        };
        add(r.cycles_486, it->second.c486, &it->second.pixels486);
        add(r.cycles_pentium, it->second.pentium, &it->second.pixels_pentium);
    }
    if (by_mapper.empty()) return "";
    std::string t =
        "| mapper | 486 inner | 486 draw | 486 frame zero-wait | isa | vlb | Pentium inner | Pentium draw | Pentium frame zero-wait | isa | vlb |\n"
        "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (const auto& [mapper, m] : by_mapper) {
        t += "| " + mapper;
        for (int k = 0; k < 5; ++k) t += " | " + (m.pixels486 ? fixed(m.c486[k] / m.pixels486, 1) : std::string("-"));
        for (int k = 0; k < 5; ++k) t += " | " + (m.pixels_pentium ? fixed(m.pentium[k] / m.pixels_pentium, 1) : std::string("-"));
        t += " |\n";
    }
    return t;
}

std::string modex_table(const std::vector<TradeRow>& rows) {
    static const char* const BUSES[3] = {"zero-wait", "isa", "vlb"};
    std::string t = "| scene | target | bus | straight into Mode X | into RAM, then the blit | faster |\n|---|---|---|---|---|---|\n";
    bool any = false;
    for (const std::string& scene : scenes_in_order(rows))
        for (const char* target : {"486", "pentium"})
            for (int b = 0; b < 3; ++b) {
                // the fastest straight and through RAM: cycles a pixel, mapper
                std::pair<double, std::string> straight{0, ""}, ram{0, ""};
                for (const TradeRow& r : rows) {
                    const TradeRow::Cycles& c = r.cycles_on(target);
                    if (r.scene != scene || !c.frame[b] || !r.draws_everything()) continue;
                    auto& best = r.surface == "vga" ? straight : ram;
                    const double per = r.per_pixel(c.frame[b]);
                    if (best.second.empty() || per < best.first) best = {per, r.mapper};
                }
                if (straight.second.empty() || ram.second.empty()) continue;
                any = true;
                t += "| " + scene + " | " + target + " | " + BUSES[b] + " | " + straight.second + " " + fixed(straight.first, 1) + " | " +
                     ram.second + " " + fixed(ram.first, 1) + " | " + (straight.first < ram.first ? "straight" : "RAM and blit") + " |\n";
            }
    return any ? t : "";
}

std::string pareto_by_target(const std::vector<TradeRow>& rows) {
    std::string t = "| scene | target | the front: mapper (drawing cycles a pixel, mean footprint error), fastest first |\n|---|---|---|\n";
    bool any = false;
    for (const std::string& scene : scenes_in_order(rows))
        for (const char* target : {"486", "pentium"}) {
            std::vector<const TradeRow*> measured;
            std::vector<std::pair<double, double>> points;
            for (const TradeRow& r : rows) {
                const TradeRow::Cycles& c = r.cycles_on(target);
                if (r.scene != scene || !c.draw || !r.draws_everything()) continue;
                measured.push_back(&r);
                points.emplace_back(r.per_pixel(c.draw), r.accuracy.mean_footprint_error);
            }
            std::vector<size_t> front = pareto_front(points);
            if (front.empty()) continue;
            std::sort(front.begin(), front.end(), [&](size_t a, size_t b) { return points[a].first < points[b].first; });
            any = true;
            t += "| " + scene + " | " + target + " | ";
            for (size_t k = 0; k < front.size(); ++k)
                t += (k ? ", " : "") + measured[front[k]]->mapper + " (" + fixed(points[front[k]].first, 1) + ", " +
                     fixed(points[front[k]].second, 3) + ")";
            t += " |\n";
        }
    return any ? t : "";
}

}  // namespace harness

namespace harness {

namespace {

// "mapper share%, ..." by pixels, most first
std::string shares(const TradeRow::DrawnBy& d) {
    uint64_t total = 0;
    for (const auto& m : d) total += std::get<2>(m);
    TradeRow::DrawnBy sorted = d;
    std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return std::get<2>(a) > std::get<2>(b); });
    std::string out;
    for (const auto& m : sorted)
        out += (out.empty() ? "" : ", ") + std::get<0>(m) + " " + fixed(total ? 100.0 * double(std::get<2>(m)) / double(total) : 0.0, 1) + "%";
    return out.empty() ? "nothing" : out;
}

}  // namespace

std::string auto_by_target(const std::vector<TradeRow>& rows) {
    std::string t =
        "| scene | budget | 486: priced by icount | for the 486 | Pentium: priced by icount | for the Pentium | drawn for the 486 | drawn for the Pentium |\n"
        "|---|---|--:|--:|--:|--:|---|---|\n";
    bool any = false;
    for (const TradeRow& r : rows) {
        if (r.mapper != "auto" || !r.pixels || (!r.cycles_486.priced_draw && !r.cycles_pentium.priced_draw)) continue;
        any = true;
        auto per = [&](const TradeRow::Cycles& c, bool priced) {
            if (!c.draw) return std::string("-");
            return priced ? (c.priced_pixels ? fixed(double(c.priced_draw) / double(c.priced_pixels), 1) : std::string("-")) : fixed(r.per_pixel(c.draw), 1);
        };
        const TradeRow::Cycles &a = r.cycles_486, &p = r.cycles_pentium;
        const bool same = a.priced_by == p.priced_by;
        t += "| " + r.scene + " | " + budget_text(r.budget_error) + (r.budget_exact ? " exact" : " any") + " | " + per(a, false) + " | " + per(a, true) + " | " +
             per(p, false) + " | " + per(p, true) + " | " + (a.priced_draw ? shares(a.priced_by) : "-") + " | " +
             (p.priced_draw ? (same && a.priced_draw ? "the same" : shares(p.priced_by)) : "-") + " |\n";
    }
    return any ? t : "";
}

std::string auto_against_singles_by_target(const std::vector<TradeRow>& rows) {
    std::string t;
    for (const bool i486 : {true, false})
        for (const TradeRow& a : rows) {
            auto on = [&](const TradeRow& r) -> const TradeRow::Cycles& { return i486 ? r.cycles_486 : r.cycles_pentium; };
            const TradeRow::Cycles& c = on(a);
            if (a.mapper != "auto" || !a.pixels || !c.draw) continue;
            const TradeRow* best = nullptr;
            for (const TradeRow& r : rows)
                if (r.scene == a.scene && single_mapper(r) && on(r).draw && meets_budget(r, a.budget_error, a.budget_exact) &&
                    (!best || r.per_pixel(on(r).draw) < best->per_pixel(on(*best).draw)))
                    best = &r;
            const double mine = a.per_pixel(c.draw), priced = c.priced_pixels ? double(c.priced_draw) / double(c.priced_pixels) : 0;
            const double theirs = best ? best->per_pixel(on(*best).draw) : 0;
            auto against = [&](double auto_px) { return best && auto_px > 0 ? fixed(theirs / auto_px, 2) + "×" : std::string("-"); };
            t += "| " + a.scene + " | " + budget_text(a.budget_error) + (a.budget_exact ? " exact" : " any") + " | " + (i486 ? "486" : "Pentium") +
                 " | " + (priced > 0 ? fixed(priced, 1) : std::string("-")) + " | " + fixed(mine, 1) + " | " +
                 fixed(100.0 * double(c.choose) / double(c.draw), 1) + "% | " + (best ? best->mapper + " | " + fixed(theirs, 1) : std::string("none | -")) +
                 " | " + against(priced) + " | " + against(mine) + " |\n";
        }
    if (t.empty()) return "";
    return "| scene | budget | target | auto priced for it | priced by icount | choosing's share | fastest single mapper within | its cycles/px | "
           "speed-up (priced for it) | speed-up (by icount) |\n|---|---|---|--:|--:|--:|---|--:|--:|--:|\n" + t;
}

}  // namespace harness
