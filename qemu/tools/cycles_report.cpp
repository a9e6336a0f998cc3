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
                    const TradeRow::Cycles& c = std::string(target) == "486" ? r.cycles_486 : r.cycles_pentium;
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
                const TradeRow::Cycles& c = std::string(target) == "486" ? r.cycles_486 : r.cycles_pentium;
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
