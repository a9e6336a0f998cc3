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
    std::vector<std::string> scenes;
    for (const TradeRow& r : rows)
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    for (const std::string& scene : scenes)
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

}  // namespace harness
