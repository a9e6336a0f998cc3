// The gallery's maps, speeds and pages (gallery.h).
#include "qemu/tools/gallery.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>

#include "kernel/mappers/auto/choice.h"
#include "qemu/lib/error.h"
#include "qemu/tools/trade.h"

namespace harness {

// Every error above 0 stands out from 0's grey and the black background (a contrast of 3 or more,
// gallery_test), the smallest as much as the largest; none is the gap's blue or the overdraw's yellow.
const ErrorBin ERROR_BINS[] = {
    {0, {48, 48, 48}, "0: the reference's texel"},
    {0.25, {0, 170, 170}, "up to 0.25"},
    {0.5, {0, 200, 90}, "up to 0.5"},
    {1, {150, 220, 0}, "up to 1"},
    {2, {255, 170, 0}, "up to 2"},
    {4, {255, 100, 0}, "up to 4"},
    {8, {240, 40, 40}, "up to 8"},
    {1e300, {255, 80, 220}, "more than 8"},
};
const int ERROR_BIN_COUNT = sizeof ERROR_BINS / sizeof ERROR_BINS[0];

const Colour& error_colour(double footprint_error) {
    for (const ErrorBin& b : ERROR_BINS)
        if (footprint_error <= b.limit) return b.colour;
    return ERROR_BINS[ERROR_BIN_COUNT - 1].colour;
}

Colour mapper_colour(const raster::Mapper& m) {
    // Tableau's twenty colours, told apart easily, then twenty more saturated ones: one for each row
    // the registry may have (MAPPER_LIMIT; gallery_test checks they differ), none black
    static const Colour COLOURS[] = {{31, 119, 180},  {255, 127, 14},  {44, 160, 44},   {214, 39, 40},   {148, 103, 189},
                                     {140, 86, 75},   {227, 119, 194}, {127, 127, 127}, {188, 189, 34},  {23, 190, 207},
                                     {174, 199, 232}, {255, 187, 120}, {152, 223, 138}, {255, 152, 150}, {197, 176, 213},
                                     {196, 156, 148}, {247, 182, 210}, {199, 199, 199}, {219, 219, 141}, {158, 218, 229},
                                     {0, 0, 160},     {160, 0, 0},     {0, 120, 0},     {255, 255, 0},   {0, 255, 255},
                                     {255, 0, 255},   {255, 255, 255}, {80, 80, 80},    {128, 128, 0},   {0, 128, 128},
                                     {128, 0, 128},   {255, 215, 160}, {64, 0, 128},    {0, 64, 128},    {128, 64, 0},
                                     {0, 200, 100},   {200, 0, 100},   {100, 200, 0},   {64, 64, 200},   {200, 64, 64}};
    static_assert(sizeof COLOURS / sizeof COLOURS[0] >= raster::MAPPER_LIMIT, "a colour for every registry row");
    return COLOURS[size_t(&m - raster::MAPPERS) % (sizeof COLOURS / sizeof COLOURS[0])];
}

namespace {

RgbImage map_image(const std::function<Colour(size_t)>& colour) {
    RgbImage out{raster::SCREEN_WIDTH, raster::SCREEN_HEIGHT, std::vector<uint8_t>(size_t(raster::SCREEN_PIXELS) * 3)};
    for (size_t p = 0; p < size_t(raster::SCREEN_PIXELS); ++p) {
        Colour c = colour(p);
        out.rgb[3 * p] = c.r, out.rgb[3 * p + 1] = c.g, out.rgb[3 * p + 2] = c.b;
    }
    return out;
}

}  // namespace

RgbImage error_map_image(const FrameMap& map) {
    return map_image([&](size_t p) {
        switch (map.kind[p]) {
        case FrameMap::COMPARED: return error_colour(map.footprint_error[p]);
        case FrameMap::GAP: return GAP_COLOUR;
        case FrameMap::OVERDRAW: return OVERDRAW_COLOUR;
        default: return BACKGROUND_COLOUR;
        }
    });
}

RgbImage mapper_map_image(const FrameMap& map) {
    return map_image([&](size_t p) {
        const raster::Mapper* m = map.mapper_at(p);
        return m ? mapper_colour(*m) : BACKGROUND_COLOUR;
    });
}

const MeasuredSpeeds::Row* MeasuredSpeeds::find(const std::string& scene, const std::string& mapper) const {
    for (const Row& r : rows)
        if (r.scene == scene && r.mapper == mapper) return &r;
    return nullptr;
}

MeasuredSpeeds read_speeds(const std::string& report_dir) {
    MeasuredSpeeds s;
    s.path = report_dir + "/trade.csv";
    if (!std::filesystem::exists(s.path)) return s;
    s.found = true;
    auto lines = read_csv(s.path);
    if (lines.empty()) throw HarnessError(s.path + ": empty, not a bench report");
    auto column = [&](const std::string& name) {
        auto at = std::find(lines[0].begin(), lines[0].end(), name);
        if (at == lines[0].end()) throw HarnessError(s.path + ": not a bench report (no column " + name + ")");
        return size_t(at - lines[0].begin());
    };
    const size_t scene = column("scene"), mapper = column("mapper"), speed = column("draw_per_pixel[instructions/pixel]"),
                 pixels = column("pixels[count]"), frames = column("frames[count]");
    for (size_t i = 1; i < lines.size(); ++i) {
        const auto& f = lines[i];
        const std::string where = s.path + ":" + std::to_string(i + 1) + ": ";
        if (f.size() != lines[0].size())
            throw HarnessError(where + std::to_string(f.size()) + " fields, the header has " + std::to_string(lines[0].size()));
        try {
            s.rows.push_back({f[scene], f[mapper], std::stod(f[speed]), std::stoull(f[pixels]), std::stoull(f[frames])});
        } catch (const std::logic_error&) {
            throw HarnessError(where + "not a number where the bench writes one");
        }
    }
    return s;
}

double estimated_speed(const FrameMap& map) {
    double instructions = 0, pixels = 0;
    for (const FrameMap::Polygon& p : map.polygons) {
        if (!p.mapper) continue;
        const raster::MapperCost& c = raster::MAPPER_COSTS[p.mapper - raster::MAPPERS];
        if (c.polygon < 0) return -1;
        instructions += raster::estimate_cost(c, raster::PolygonSize{double(p.spans), double(p.pixels)});
        pixels += p.pixels;
    }
    return pixels > 0 ? instructions / pixels : -1;
}

void rank_cards(GalleryPage& page, const MeasuredSpeeds& speeds) {
    bool measured = speeds.found;
    for (const GalleryCard& c : page.cards) measured = measured && (!c.mapper || speeds.find(page.scene, c.title));
    uint64_t frames = 0;
    for (GalleryCard& c : page.cards) {
        if (!c.mapper) continue;
        if (measured) {
            const MeasuredSpeeds::Row* r = speeds.find(page.scene, c.title);
            c.speed = r->pixels ? r->draw_per_pixel : -1;
            frames = r->frames;
        } else {
            c.speed = estimated_speed(c.map);
        }
    }
    page.measured = measured;
    if (measured)
        page.speed_source = "measured: draw instructions per pixel (setup, walking, inner loops) in the kernel under QEMU icount, "
                            "from " + speeds.path + " (make bench; " + std::to_string(frames) + (frames == 1 ? " frame" : " frames") +
                            " of the scene, a figure their average, not this frame's alone)";
    else
        page.speed_source = "estimated: draw instructions per pixel by the cost model auto chooses by (kernel/mappers/auto/costs.cpp), "
                            "from the polygons, spans and pixels each mapper drew of this frame; auto's own choosing is not in it (" +
                            (speeds.found ? speeds.path + " has no row for some of this page's pictures"
                                          : "no bench report at " + speeds.path) + ": make bench measures them)";
    auto rank = [](const GalleryCard& c) { return !c.mapper ? 0 : c.at_budget ? 3 : c.speed < 0 ? 2 : 1; };
    std::stable_sort(page.cards.begin(), page.cards.end(), [&](const GalleryCard& a, const GalleryCard& b) {
        if (rank(a) != rank(b)) return rank(a) < rank(b);
        return rank(a) == 1 && a.speed < b.speed;
    });
}

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

namespace {

std::string hex(const Colour& c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
    return buf;
}

std::string swatch(const Colour& c) { return "<span class=\"swatch\" style=\"background:" + hex(c) + "\"></span>"; }

std::ofstream open_page(const std::string& path) {
    std::ofstream out(path);
    if (!out) throw HarnessError(path + ": cannot write");
    return out;
}

void close_page(std::ofstream& out, const std::string& path) {
    out.close();
    if (!out) throw HarnessError(path + ": cannot write");
}

const char* STYLE =
    "body{font-family:sans-serif;background:#eee;color:#111;margin:.5em}\n"
    ".card{background:#fff;border:1px solid #bbb;margin:.5em 0;padding:0 4px 4px}\n"
    ".card h3{margin:.4em 0}\n"
    ".maps{display:flex;flex-wrap:wrap;gap:4px;background:#222;padding:2px}\n"
    "figure{margin:0}\n"
    "figcaption{font-size:90%;color:#ddd}\n"
    "img.x1{image-rendering:pixelated;display:block}\n"
    ".swatch{display:inline-block;width:1.1em;height:1.1em;border:1px solid #777;vertical-align:middle;margin-right:.3em}\n"
    "table{border-collapse:collapse}\n"
    "td,th{padding:.1em .7em;text-align:left}\n"
    "td.n{text-align:right}\n"
    ".refused{color:#a00}\n";

std::string head(const std::string& title) {
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escape(title) + "</title>\n<style>\n" +
           STYLE + TOOLS_STYLE + "</style>\n</head>\n<body>\n";
}

std::string figure(const std::string& src, const std::string& caption) {
    return "<figure><img class=\"x1\" src=\"" + escape(src) + "\" width=\"320\" height=\"240\" alt=\"" + escape(caption) +
           "\"><figcaption>" + escape(caption) + "</figcaption></figure>\n";
}

std::string legend() {
    std::string s = "<div class=\"legend\"><p><b>Footprint-error map</b> (docs/accuracy.md: the texel error over max(1, the "
                    "pixel's footprint in texels), each polygon against the exact reference). Each pixel shows the last polygon "
                    "drawn there, as the picture does; the figures count every polygon's pixels.</p>\n<table>\n";
    for (const ErrorBin& b : ERROR_BINS)
        s += "<tr><td>" + swatch(b.colour) + "</td><td>" + escape(b.label) + (b.limit > 0 ? " footprints" : "") + "</td></tr>\n";
    s += "<tr><td>" + swatch(GAP_COLOUR) + "</td><td>gap: the reference covers it, the mapper did not draw it</td></tr>\n";
    s += "<tr><td>" + swatch(OVERDRAW_COLOUR) + "</td><td>overdraw: drawn, the reference does not cover it</td></tr>\n";
    s += "<tr><td>" + swatch(BACKGROUND_COLOUR) + "</td><td>background: covered by neither</td></tr>\n</table>\n";
    s += "<p><b>Mapper map</b> (auto): each pixel in the colour of the mapper auto chose for the polygon that drew it; "
         "the colours are listed on each card with the mappers' shares. Black: not drawn.</p></div>\n";
    return s;
}

std::string speed_text(const GalleryPage& page, const GalleryCard& c) {
    return c.speed < 0 ? std::string("-") : fixed(c.speed, 1) + " draw instr/px, " + (page.measured ? "measured (make bench)" : "estimated (cost model)");
}

std::string card_html(const GalleryPage& page, const GalleryCard& c) {
    const raster::AccuracyMetrics& m = c.metrics;
    const char* kind = !c.mapper ? "reference" : c.at_budget ? "budget" : "mapper";
    std::string s = "<section class=\"card\" id=\"card-" + c.file + "\" data-kind=\"" + kind + "\" data-title=\"" + escape(c.title) + "\"";
    if (c.mapper) {
        s += " data-mapper=\"" + escape(c.mapper->name) + "\" data-speed=\"" + (c.speed < 0 ? "-" : fixed(c.speed, 3)) +
             "\" data-compared=\"" + std::to_string(m.compared) + "\" data-exact=\"" +
             std::to_string(m.exact) + "\" data-drawn=\"" + std::to_string(m.drawn_pixels) + "\" data-gaps=\"" +
             std::to_string(m.gaps) + "\" data-overdraw=\"" + std::to_string(m.overdraw) + "\" data-max-footprint=\"" +
             fixed(m.max_footprint_error, 6) + "\"";
        if (c.mapper->is_auto) s += " data-budget=\"" + (c.budget.max_error < 0 ? "any" : budget_text(c.budget.max_error)) + "\"";
    }
    s += ">\n<h3>" + escape(c.title) + "</h3>\n<div class=\"maps\">\n";
    if (!c.mapper) {
        s += figure(image_path(page, c, ""), "the exact reference");
        s += "</div>\n<p>" + std::to_string(c.reference_pixels) + " pixels covered: what every mapper is measured against.</p>\n";
        return s + "</section>\n";
    }
    s += figure(image_path(page, c, "frame"), c.title + ": the frame");
    s += figure(image_path(page, c, "error"), c.title + ": footprint error");
    if (c.mapper->is_auto) s += figure(image_path(page, c, "mappers"), c.title + ": the mapper of each pixel");
    s += "</div>\n<table class=\"figures\">\n";
    auto row = [&](const std::string& name, const std::string& value) { s += "<tr><th>" + name + "</th><td>" + value + "</td></tr>\n"; };
    row("speed", speed_text(page, c));
    if (c.mapper->is_auto) row("budget", escape(budget_words(c.budget)));
    const bool compared = m.compared > 0;
    row("footprint error max / p99.9 / mean", compared ? fixed(m.max_footprint_error, 3) + " / " + fixed(m.p999_footprint_error, 3) + " / " +
                                                             fixed(m.mean_footprint_error, 4)
                                                       : "- (no pixel compared)");
    row("max texel error", compared ? std::to_string(m.max_texel_error) : "-");
    row("compared pixels, exact", std::to_string(m.compared) + ", " + std::to_string(m.exact));
    row("gaps / overdraw", std::to_string(m.gaps) + " / " + std::to_string(m.overdraw));
    s += "</table>\n";
    if (!c.refused.empty()) s += "<p class=\"refused\">" + escape(c.refused) + "</p>\n";
    if (c.mapper->is_auto) {
        // the mappers auto drew with: polygons, and the pixels each shows (the mapper map's)
        std::map<const raster::Mapper*, std::pair<uint32_t, uint32_t>> share;
        for (const FrameMap::Polygon& p : c.map.polygons)
            if (p.mapper) ++share[p.mapper].first;
        uint32_t shown = 0;
        for (size_t p = 0; p < size_t(raster::SCREEN_PIXELS); ++p)
            if (const raster::Mapper* by = c.map.mapper_at(p)) ++share[by].second, ++shown;
        s += "<table class=\"shares\">\n<tr><th>drew with</th><th>polygons</th><th>pixels shown</th><th>share</th></tr>\n";
        for (const auto& [mapper, counts] : share)
            s += "<tr data-share-mapper=\"" + escape(mapper->name) + "\" data-colour=\"" + hex(mapper_colour(*mapper)) +
                 "\" data-pixels=\"" + std::to_string(counts.second) + "\"><td>" + swatch(mapper_colour(*mapper)) + escape(mapper->name) +
                 "</td><td class=\"n\">" + std::to_string(counts.first) + "</td><td class=\"n\">" + std::to_string(counts.second) +
                 "</td><td class=\"n\">" + fixed(shown ? 100.0 * counts.second / shown : 0.0, 1) + "%</td></tr>\n";
        s += "</table>\n";
    }
    return s + "</section>\n";
}

}  // namespace

std::string image_path(const GalleryPage& page, const GalleryCard& card, const char* what) {
    return "img/" + page.scene + "-" + card.file + (*what ? "-" : "") + what + ".png";
}

void write_page(const std::string& dir, const GalleryPage& page, const raster::Palette& palette) {
    std::filesystem::create_directories(dir + "/img");
    for (const GalleryCard& c : page.cards) {
        if (!c.mapper) {
            save_png(dir + "/" + image_path(page, c, ""), colourise(c.picture, palette));
            continue;
        }
        save_png(dir + "/" + image_path(page, c, "frame"), colourise(c.picture, palette));
        save_png(dir + "/" + image_path(page, c, "error"), error_map_image(c.map));
        if (c.mapper->is_auto) save_png(dir + "/" + image_path(page, c, "mappers"), mapper_map_image(c.map));
    }
    const std::string path = dir + "/" + page.scene + ".html";
    std::ofstream out = open_page(path);
    out << head("modexlab gallery: " + page.scene) << "<p><a href=\"index.html\">all scenes</a></p>\n<h1>" << escape(page.scene)
        << ", frame " << page.frame << " of " << page.frames << "</h1>\n";
    if (!page.exercises.empty()) out << "<p>" << escape(page.exercises) << ".</p>\n";
    out << "<p>The scene's budget: " << escape(page.budget) << ". Speeds " << escape(page.speed_source) << ".</p>\n" << legend();
    out << "<h2>Summary</h2>\n<p>Click a column's name to sort by it.</p>\n" << summary_html(page) << plot_svg(page) << compare_html(page);
    std::vector<const GalleryCard*> mappers, budgets;
    for (const GalleryCard& c : page.cards)
        if (c.mapper) (c.at_budget ? budgets : mappers).push_back(&c);
    auto links = [&](const std::vector<const GalleryCard*>& cards) {
        std::string s;
        for (const GalleryCard* c : cards) s += (s.empty() ? "" : ", ") + ("<a href=\"#card-" + c->file + "\">" + escape(c->title) + "</a>");
        return s;
    };
    out << "<p class=\"listed\" data-count=\"" << mappers.size() << "\">" << mappers.size() << " mappers, fastest first: " << links(mappers) << ".</p>\n";
    if (!budgets.empty())
        out << "<p class=\"listed-budgets\" data-count=\"" << budgets.size() << "\">auto at " << budgets.size()
            << " budgets of its own (exact coverage): " << links(budgets) << ".</p>\n";
    for (const GalleryCard& c : page.cards)
        if (!c.mapper) out << card_html(page, c);
    out << "<h2>The mappers, fastest first</h2>\n<div class=\"cards\">\n";
    for (const GalleryCard* c : mappers) out << card_html(page, *c);
    out << "</div>\n";
    if (!budgets.empty()) out << "<h2>auto at budgets of its own</h2>\n<div class=\"cards\">\n";
    for (const GalleryCard* c : budgets) out << card_html(page, *c);
    if (!budgets.empty()) out << "</div>\n";
    out << PAGE_SCRIPT << "</body>\n</html>\n";
    close_page(out, path);
}

void write_index(const std::string& dir, const std::vector<GalleryPage>& pages) {
    const std::string path = dir + "/index.html";
    std::ofstream out = open_page(path);
    out << head("modexlab gallery") << "<h1>modexlab gallery</h1>\n<p>Every mapper's frame beside its footprint-error map, "
        << "fastest first, and auto at budgets with the mapper that drew each pixel: one page a scene (make gallery; "
        << "docs/bench.md, \"The gallery\").</p>\n<table>\n";
    for (const GalleryPage& p : pages) {
        size_t cards = 0;
        for (const GalleryCard& c : p.cards) cards += c.mapper != nullptr;
        out << "<tr><td><a href=\"" << escape(p.scene) << ".html\"><img class=\"x1\" src=\"img/" << escape(p.scene)
            << "-reference.png\" width=\"320\" height=\"240\" alt=\"" << escape(p.scene) << "\"></a></td><td><a href=\""
            << escape(p.scene) << ".html\">" << escape(p.scene) << "</a>: frame " << p.frame << ", " << cards << " pictures. "
            << escape(p.exercises) << "</td></tr>\n";
    }
    out << "</table>\n</body>\n</html>\n";
    close_page(out, path);
}

}  // namespace harness
