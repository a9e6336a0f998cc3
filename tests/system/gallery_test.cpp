// modexlab-gallery narrowed to the corridor: its pages and images exist and agree with the figures
// they print; speeds from a report or the cost model, fastest first; bad input refused clearly.
// (make test-gallery opens every page of a whole gallery in a browser: tests/browser.)
#include "tests/system/system.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <cmath>
#include <set>

#include "kernel/core/mapper.h"
#include "qemu/lib/host_image.h"
#include "qemu/tools/gallery.h"
#include "qemu/tools/trade.h"
#include "tests/html.h"

namespace {

using namespace systest;
using htmltest::Attributes;

std::string tmp(const std::string& name) {
    std::string dir = build_dir() + "/test-tmp/gallery/" + name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

ToolRun gallery(const std::string& args) { return run_command(build_dir() + "/host/modexlab-gallery " + args); }

// The corridor has no polygon in front of another: a map pixel is a polygon's pixel, so the maps'
// counts are the figures'.
const char* MAPPERS = "exact,affine,persp-subdiv-16,xsharp-dda,auto";

std::string read(const std::string& path) { return read_whole_file(path); }

uint32_t number(const Attributes& a, const char* key) { return uint32_t(std::stoul(a.at(key))); }

TEST(Gallery, PagesImagesAndFiguresAgree) {
    const std::string out = tmp("corridor");
    ToolRun r = gallery(std::string("--scenes corridor --mappers ") + MAPPERS + " --report " + out + "/no-report --out " + out);
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("corridor affine: footprint error max"), std::string::npos) << "a progress line a picture: " << r.out;
    EXPECT_NE(r.out.find("gallery: " + out + "/index.html"), std::string::npos) << r.out;

    const std::string index = read(out + "/index.html");
    std::set<std::string> links;
    for (const Attributes& a : htmltest::tags(index, "a")) links.insert(a.at("href"));
    EXPECT_EQ(links, std::set<std::string>{"corridor.html"});
    const std::string page = read(out + "/corridor.html");
    for (const std::string* html : {&index, &page})
        for (const Attributes& img : htmltest::tags(*html, "img")) {
            const std::string src = img.at("src");
            EXPECT_EQ(src.find(".."), std::string::npos) << src;
            ASSERT_TRUE(std::filesystem::is_regular_file(out + "/" + src)) << src;
            RgbImage png = load_image(out + "/" + src);
            EXPECT_EQ(png.width, 320) << src;
            EXPECT_EQ(png.height, 240) << src;
        }
    EXPECT_EQ(page.find("http"), std::string::npos) << "nothing from outside";
    EXPECT_NE(page.find("no bench report at " + out + "/no-report/trade.csv"), std::string::npos) << "says where speeds come from";

    std::vector<Attributes> cards = htmltest::tags(page, "section");
    std::map<std::string, int> kinds;
    double last_speed = 0;
    bool last_unknown = false;
    for (const Attributes& card : cards) {
        ++kinds[card.at("data-kind")];
        if (card.at("data-kind") == "reference") continue;
        const std::string title = card.at("data-title"), mapper = card.at("data-mapper");
        SCOPED_TRACE(title);
        ASSERT_NE(raster::find_mapper(mapper.c_str()), nullptr);
        if (card.at("data-kind") == "mapper") {  // fastest first, those without a speed last
            const bool unknown = card.at("data-speed") == "-";
            EXPECT_TRUE(unknown || (!last_unknown && std::stod(card.at("data-speed")) >= last_speed));
            if (!unknown) last_speed = std::stod(card.at("data-speed"));
            last_unknown = unknown;
        }
        const std::string stem = out + "/img/corridor-" + card.at("id").substr(5);
        // the error map: every pixel in a colour of the legend, counted as the figures count
        RgbImage errors = load_image(stem + "-error.png");
        uint32_t gaps = 0, overdraw = 0, zero = 0, nonzero = 0;
        int worst_bin = -1;
        for (size_t p = 0; p < errors.rgb.size(); p += 3) {
            Colour c{errors.rgb[p], errors.rgb[p + 1], errors.rgb[p + 2]};
            if (c == GAP_COLOUR) ++gaps;
            else if (c == OVERDRAW_COLOUR) ++overdraw;
            else if (c == BACKGROUND_COLOUR) continue;
            else {
                int bin = 0;
                while (bin < ERROR_BIN_COUNT && !(ERROR_BINS[bin].colour == c)) ++bin;
                ASSERT_LT(bin, ERROR_BIN_COUNT) << "a colour off the scale";
                (bin ? nonzero : zero)++;
                worst_bin = std::max(worst_bin, bin);
            }
        }
        EXPECT_EQ(gaps, number(card, "data-gaps"));
        EXPECT_EQ(overdraw, number(card, "data-overdraw"));
        EXPECT_EQ(zero, number(card, "data-exact"));
        EXPECT_EQ(zero + nonzero, number(card, "data-compared"));
        const double max = std::stod(card.at("data-max-footprint"));
        if (number(card, "data-compared")) {
            EXPECT_EQ(&ERROR_BINS[worst_bin].colour, &error_colour(max)) << "the worst pixel's colour is the max's";
        }
        if (mapper == "exact" || title == "auto@0") {
            EXPECT_EQ(nonzero, 0u);
            EXPECT_EQ(max, 0.0);
        }
        if (mapper == "xsharp-dda") {
            EXPECT_EQ(gaps, 76800u) << "refuses the corridor: all gaps";
            EXPECT_NE(page.find("Cannot draw this scene: refuses every polygon (it needs texture coordinates inside the texture)"),
                      std::string::npos);
        }
        if (card.count("data-budget") && card.at("data-budget") != "any") {
            EXPECT_LE(max, std::stod(card.at("data-budget")) + 1e-9);
        }
        if (!raster::find_mapper(mapper.c_str())->is_auto) continue;
        // auto's mapper map: only the mappers listed, each with the pixels it says, adding up to those drawn
        ASSERT_TRUE(card.count("data-budget"));
        RgbImage by = load_image(stem + "-mappers.png");
        std::map<std::string, uint32_t> seen;
        for (size_t p = 0; p < by.rgb.size(); p += 3) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "#%02x%02x%02x", by.rgb[p], by.rgb[p + 1], by.rgb[p + 2]);
            if (std::string(hex) != "#000000") ++seen[hex];
        }
        std::map<std::string, uint32_t> listed;
        uint32_t sum = 0;
        const std::string section = page.substr(page.find("id=\"card-" + card.at("id").substr(5) + "\""));
        for (const Attributes& row : htmltest::tags(section.substr(0, section.find("</section>")), "tr")) {
            if (!row.count("data-share-mapper")) continue;
            const raster::Mapper* m = raster::find_mapper(row.at("data-share-mapper").c_str());
            ASSERT_NE(m, nullptr);
            EXPECT_TRUE(raster::drawn_by_auto(*m)) << m->name;
            listed[row.at("data-colour")] = number(row, "data-pixels");
            sum += number(row, "data-pixels");
        }
        EXPECT_EQ(seen, listed);
        EXPECT_EQ(sum, number(card, "data-drawn"));
    }
    EXPECT_EQ(kinds["reference"], 1);
    EXPECT_EQ(kinds["mapper"], 5);
    EXPECT_EQ(kinds["budget"], 5) << "auto at 0, 0.5, 1, 2 and 4";
}

TEST(Gallery, SpeedsFromABenchReportWhenItCoversTheScene) {
    const std::string out = tmp("report");
    std::filesystem::create_directories(out + "/report");
    std::vector<std::string> header = csv_header();
    std::ofstream csv(out + "/report/trade.csv");
    for (size_t i = 0; i < header.size(); ++i) csv << (i ? "," : "") << header[i];
    csv << "\n";
    // made-up speeds: exact fastest, affine slowest
    for (auto [mapper, speed] : std::vector<std::pair<std::string, std::string>>{{"affine", "90"}, {"exact", "10"}, {"constant-depth", "50"}}) {
        std::vector<std::string> row(header.size(), "0");
        for (size_t i = 0; i < header.size(); ++i) {
            if (header[i] == "scene") row[i] = "corridor";
            if (header[i] == "mapper") row[i] = mapper;
            if (header[i] == "draw_per_pixel[instructions/pixel]") row[i] = speed;
            if (header[i] == "pixels[count]") row[i] = "1000";
            if (header[i] == "frames[count]") row[i] = "8";
        }
        for (size_t i = 0; i < row.size(); ++i) csv << (i ? "," : "") << row[i];
        csv << "\n";
    }
    csv.close();
    ToolRun r = gallery("--scenes corridor --mappers affine,exact,constant-depth --report " + out + "/report --out " + out);
    ASSERT_EQ(r.status, 0) << r.out;
    const std::string page = read(out + "/corridor.html");
    EXPECT_NE(page.find("measured: draw instructions per pixel"), std::string::npos);
    EXPECT_NE(page.find("8 frames of the scene"), std::string::npos);
    std::vector<std::string> order;
    for (const Attributes& card : htmltest::tags(page, "section"))
        if (card.at("data-kind") == "mapper") order.push_back(card.at("data-mapper"));
    EXPECT_EQ(order, (std::vector<std::string>{"exact", "constant-depth", "affine"}));

    // a mapper the report lacks: the cost model for the whole page, and it says why
    r = gallery("--scenes corridor --mappers affine,fast-affine --report " + out + "/report --out " + out);
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(read(out + "/corridor.html").find("has no row for some of this page's pictures"), std::string::npos);

    std::ofstream(out + "/report/trade.csv") << "scene,mapper\ncorridor,exact\n";
    r = gallery("--scenes corridor --mappers exact --report " + out + "/report --out " + out);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find("trade.csv: not a bench report (no column draw_per_pixel[instructions/pixel])"), std::string::npos) << r.out;
}

TEST(Gallery, BadInputGetsAClearError) {
    const std::string out = tmp("bad");
    ToolRun r = gallery("--scenes corridor --mappers marble --out " + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.out.find("unknown mapper 'marble'"), std::string::npos) << r.out;
    r = gallery("--scenes hall --out " + out);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find("no demo scene or scene file 'hall'"), std::string::npos) << r.out;
    r = gallery("--scenes corridor --mappers exact --frame 400 --out " + out);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find("frame 400 is beyond its 360 frames"), std::string::npos) << r.out;
}

TEST(Gallery, EveryMapperHasAColourOfItsOwn) {
    std::set<std::string> colours;
    for (int i = 0; i < raster::MAPPER_COUNT; ++i) {
        Colour c = mapper_colour(raster::MAPPERS[i]);
        EXPECT_FALSE(c == BACKGROUND_COLOUR);
        colours.insert(std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b));
    }
    EXPECT_EQ(colours.size(), size_t(raster::MAPPER_COUNT));
}

// The error scale: every error above 0, the smallest too, stands out from 0's colour and from the
// background by a contrast ratio of 3 or more (WCAG's for graphics), and no bin looks like a gap,
// overdraw or another bin.
TEST(Gallery, TheSmallestErrorsStandOutOnTheErrorMap) {
    auto luminance = [](const Colour& c) {
        auto linear = [](uint8_t v) {
            const double x = v / 255.0;
            return x <= 0.03928 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
        };
        return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
    };
    auto contrast = [&](const Colour& a, const Colour& b) {
        const double la = luminance(a), lb = luminance(b);
        return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
    };
    const Colour& zero = ERROR_BINS[0].colour;
    for (int i = 1; i < ERROR_BIN_COUNT; ++i) {
        const Colour& c = ERROR_BINS[i].colour;
        EXPECT_GE(contrast(c, zero), 3.0) << ERROR_BINS[i].label << " against 0";
        EXPECT_GE(contrast(c, BACKGROUND_COLOUR), 3.0) << ERROR_BINS[i].label << " against the background";
        EXPECT_FALSE(c == GAP_COLOUR || c == OVERDRAW_COLOUR) << ERROR_BINS[i].label;
        for (int j = 0; j < i; ++j) EXPECT_FALSE(c == ERROR_BINS[j].colour) << ERROR_BINS[i].label;
    }
}

}  // namespace
