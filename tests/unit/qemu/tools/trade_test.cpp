// Under test: qemu/tools/trade.h, trade_docs.h; qemu/accuracy/measure.h.
// The bench's pieces on the host: the Pareto front on hand-made points, the report files, the
// phase probe (it must not change a picture, and its phases add up), and the 3D accuracy measure
// (the exact mapper measures as exact; the pixels a mapper counts are the pixels the reference
// covers for every mapper that promises exact coverage).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "kernel/core/footprint.h"
#include "kernel/core/policy.h"
#include "kernel/scene/frame.h"
#include "kernel/core/render.h"
#include "qemu/accuracy/measure.h"
#include "qemu/tools/cycles_report.h"
#include "qemu/tools/published.h"
#include "qemu/tools/trade.h"
#include "qemu/tools/trade_docs.h"
#include "qemu/lib/error.h"
#include "qemu/lib/paths.h"

namespace {

using namespace harness;
using namespace raster;

TEST(Trade, ParetoFrontOfHandMadePoints) {
    //                 0       1       2       3       4       5         6         7
    std::vector<std::pair<double, double>> p = {{1, 5}, {2, 3}, {3, 3}, {4, 1}, {2, 6}, {5, 0.5}, {5, 0.5}, {6, 0.5}};
    // 2 is beaten by 1 (as exact, faster); 4 by 0 (faster and more exact); 7 by 5 and 6; 5 and 6 tie
    EXPECT_EQ(pareto_front(p), (std::vector<size_t>{0, 1, 3, 5, 6}));
    EXPECT_EQ(pareto_front({}), std::vector<size_t>{});
    EXPECT_EQ(pareto_front({{3, 3}}), std::vector<size_t>{0});
}

TradeRow row(const std::string& scene, const std::string& mapper, uint64_t draw, double mean_error, uint64_t rejected = 0) {
    TradeRow r;
    r.scene = scene, r.mapper = mapper;
    r.pixels = 100, r.polygons = 4, r.spans = 10, r.rejected = rejected;
    r.draw = draw, r.ticks = draw + 500, r.inner = draw / 2, r.setup = draw / 4, r.walk = draw - draw / 2 - draw / 4;
    r.accuracy.compared = 100, r.accuracy.mean_texel_error = mean_error, r.accuracy.mean_footprint_error = mean_error;
    return r;
}

// trade.md of these rows, written into `path` and read back.
std::string markdown_of(const std::string& path, const std::vector<TradeRow>& rows, const ReportInfo& info = ReportInfo{}) {
    write_markdown(path, rows, info);
    std::ifstream md(path);
    std::stringstream text;
    text << md.rdbuf();
    return text.str();
}

TEST(Trade, ParetoIsPerSceneAndLeavesOutMappersThatRefusePolygons) {
    std::vector<TradeRow> rows = {row("a", "slow-exact", 9000, 0), row("a", "fast-rough", 1000, 5), row("a", "middle", 5000, 6),
                                  row("a", "fastest-partial", 500, 0, 3), row("b", "slow-exact", 9000, 0), row("b", "fast-rough", 1000, 0)};
    rows.push_back(row("b", "nothing", 0, 0));
    rows.back().pixels = 0;
    mark_pareto(rows);
    EXPECT_TRUE(rows[0].pareto);
    EXPECT_TRUE(rows[1].pareto);
    EXPECT_FALSE(rows[2].pareto);  // slower and less exact than fast-rough
    EXPECT_FALSE(rows[3].pareto);  // refuses polygons: not comparable
    EXPECT_FALSE(rows[4].pareto);  // in scene b, fast-rough is as exact and faster
    EXPECT_TRUE(rows[5].pareto);
    EXPECT_FALSE(rows[6].pareto);
}


TEST(Trade, TheCsvHasAUnitForEveryColumnAndAFieldForEveryColumn) {
    std::vector<TradeRow> rows = {row("a", "exact", 9000, 0), row("a", "affine", 3000, 2.5)};
    rows[1].host_ratio = 0.5;
    mark_pareto(rows);
    std::string dir = testing::TempDir() + "/trade_csv";
    write_csv(dir + "/trade.csv", rows);
    auto lines = read_csv(dir + "/trade.csv");
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0], csv_header());
    for (size_t i = 6; i < lines[0].size(); ++i) EXPECT_NE(lines[0][i].find('['), std::string::npos) << lines[0][i];
    std::map<std::string, size_t> column;
    for (size_t i = 0; i < lines[0].size(); ++i) column[lines[0][i]] = i;
    for (size_t r = 1; r < lines.size(); ++r) ASSERT_EQ(lines[r].size(), lines[0].size()) << "row " << r;
    EXPECT_EQ(lines[2][column["mapper"]], "affine");
    EXPECT_DOUBLE_EQ(std::stod(lines[2][column["draw_per_pixel[instructions/pixel]"]]), 30.0);
    EXPECT_DOUBLE_EQ(std::stod(lines[2][column["frame_per_pixel[instructions/pixel]"]]), 35.0);
    EXPECT_DOUBLE_EQ(std::stod(lines[2][column["host_cycles_ratio[ratio]"]]), 0.5);
    EXPECT_EQ(lines[1][column["host_cycles_ratio[ratio]"]], "");  // not measured
    EXPECT_EQ(lines[1][column["pareto[bool]"]], "true");
    EXPECT_EQ(lines[2][column["pareto[bool]"]], "true");

    ReportInfo info;
    info.how = "by hand";
    info.command = "make bench";
    const std::string md_text = markdown_of(dir + "/trade.md", rows, info);
    // sorted by speed: affine (30 per pixel) before exact (90)
    size_t affine = md_text.find("\n| affine |"), exact = md_text.find("\n| exact |");
    ASSERT_NE(affine, std::string::npos);
    ASSERT_NE(exact, std::string::npos);
    EXPECT_LT(affine, exact);

    // the classics' published figures: every row of the table has its ten cells, the counted
    // listing beside ours (a row of quake-subdiv16 says both)
    size_t table = md_text.find(
        "| loop | published cycles/px | machine | model: listing | model: ours | listing instr/px | ours | ours counted | ours measured instr/px | scene |");
    ASSERT_NE(table, std::string::npos);
    std::istringstream lines_after(md_text.substr(table));
    std::string line;
    int published_rows = 0;
    while (std::getline(lines_after, line) && line.rfind("|", 0) == 0) {
        EXPECT_EQ(std::count(line.begin(), line.end(), '|'), 11) << line;
        published_rows += line.find("quake-subdiv16") != std::string::npos && line.find("6 + 68/16") != std::string::npos &&
                          line.find("9 + 98/16") != std::string::npos;
    }
    EXPECT_EQ(published_rows, 1);
}

// The outer loops per polygon drawn: each phase's ticks over the polygons, outer the sum of the
// first three; only exact and fast-affine, only where they draw every polygon.
TEST(Trade, TheOuterLoopsArePerPolygonDrawn) {
    std::vector<TradeRow> rows = {row("a", "exact", 9000, 0), row("a", "fast-affine", 3000, 1), row("a", "affine", 3000, 1)};
    for (TradeRow& r : rows) r.frames = 2, r.polygons = 10, r.geometry = 1000, r.setup = 2000, r.walk = 500, r.inner = 70;
    rows[1].rejected = 1;  // fast-affine refused one: no row
    std::string dir = testing::TempDir() + "/trade_outer";
    const std::string t = markdown_of(dir + "/trade.md", rows);
    EXPECT_NE(t.find("| a | exact | 5 | " + fixed(double(rows[0].pixels) / 10, 1) + " | 100 | 200 | 50 | 7 | 350 |"), std::string::npos) << t;
    EXPECT_EQ(t.find("| a | fast-affine |"), std::string::npos);
    EXPECT_EQ(t.find("| a | affine | 5 |"), std::string::npos);
}

// "Every mapper on the same work": only scenes no single mapper refuses a polygon of (auto does not
// count), each mapper's row; the others named with how many single mappers refuse some.
TEST(Trade, EveryMapperOnTheSameWorkListsOnlyScenesNoMapperRefuses) {
    std::vector<TradeRow> rows = {row("whole", "exact", 9000, 0),   row("whole", "fast-affine", 3000, 1), row("whole", "auto", 2000, 1),
                                  row("split", "exact", 9000, 0),   row("split", "fast-affine", 3000, 1), row("split", "affine", 3000, 1),
                                  row("split", "auto", 2000, 1)};
    rows[4].rejected = 1;  // fast-affine refused one polygon of "split"
    rows[2].rejected = 1;  // auto's refusals do not count (it is not a single mapper)
    std::string dir = testing::TempDir() + "/trade_whole";
    const std::string t = markdown_of(dir + "/trade.md", rows);
    const size_t at = t.find("## Every mapper on the same work");
    ASSERT_NE(at, std::string::npos) << t;
    const std::string section = t.substr(at, t.find("\n## ", at + 1) - at);
    EXPECT_NE(section.find("### whole"), std::string::npos) << section;
    EXPECT_NE(section.find("| fast-affine | "), std::string::npos) << section;
    EXPECT_EQ(section.find("| auto | "), std::string::npos) << section;
    EXPECT_EQ(section.find("### split"), std::string::npos) << section;
    EXPECT_NE(section.find("Left out (mappers that refuse some or all of the polygons, of the single mappers): split (1 of 3)"), std::string::npos)
        << section;
}

// auto's table: beside the fastest single mapper whose measured error meets the budget, the fastest
// whose own bounds prove it (its largest bound within it, exact coverage promised where asked, every
// polygon drawn); a mapper measured within but not proven, or proven only with its coverage its
// own, is not the second. Beside auto's draw, its choosing a pixel, and the first speed-up were it free.
TEST(Trade, AutoIsSetAgainstTheFastestMeasuredAndTheFastestProven) {
    std::vector<TradeRow> rows = {row("a", "exact", 9000, 0), row("a", "fast-affine", 2000, 1), row("a", "fast-table", 1000, 1),
                                  row("a", "xsharp-dda", 1500, 1), row("a", "auto", 2500, 0)};
    for (TradeRow& r : rows) r.accuracy.max_footprint_error = 0.5, r.budget_error = 1, r.budget_exact = true, r.budget = "1";
    rows[0].max_bound = 0, rows[0].bound_exact = true;
    rows[1].max_bound = 1, rows[1].bound_exact = true;         // proven within 1
    rows[2].max_bound = 2, rows[2].bound_exact = true;         // measured within, its bound above the budget
    rows[3].max_bound = 0.5, rows[3].bound_exact = false;      // within, but no exact coverage promised
    rows[4].max_bound = -1;
    rows[4].choose = 1000;  // 10 of its 25 a pixel
    // its 5 polygons: 1 by the envelope, 2 by their whole bound, 1 span by span, 1 unasked
    rows[4].drawn_by = {{"fast-affine", 3, 50}, {"exact", 2, 50}}, rows[4].enveloped = 1, rows[4].proven_whole = 2, rows[4].proven_spans = 1;
    std::string dir = testing::TempDir() + "/trade_auto";
    const std::string t = markdown_of(dir + "/trade.md", rows);
    EXPECT_NE(t.find("| a | auto | 1 | 25.0 | 10.00 | 40.0% | 1 / 2 / 1 / 1 | 0.500 | yes | fast-table | 10.0 | 0.40× | 0.67× | fast-affine | 20.0 | "
                     "0.80× |"),
              std::string::npos)
        << t;
    EXPECT_NE(t.find("- a auto: 40.0% of its draw, 250 instructions a polygon it tested: the plans once a frame, the test of 4 polygons "
                     "(1 then drawn unasked) and the proofs and search on 3 (1 span by span)"),
              std::string::npos)
        << t;
    rows[1].max_bound = raster::NO_BOUND;  // one polygon without a bound: not proven; then only exact is
    const std::string t2 = markdown_of(dir + "/trade.md", rows);
    EXPECT_NE(t2.find("| fast-table | 10.0 | 0.40× | 0.67× | exact | 90.0 | 3.60× |"), std::string::npos) << t2;
}

// On each target auto (at its scene's budget) is set against the fastest single mapper run there
// whose measured error meets the budget, in that target's cycles; choosing's share is of auto's.
TEST(Trade, AutoAgainstTheFastestSingleMapperOnEachTarget) {
    std::vector<TradeRow> rows = {row("a", "exact", 9000, 0), row("a", "fast-affine", 2000, 1), row("a", "fast-table", 1000, 1),
                                  row("a", "auto", 2500, 0)};
    for (TradeRow& r : rows) r.accuracy.max_footprint_error = 0.5, r.budget_error = 1, r.budget_exact = true;
    rows[2].accuracy.max_footprint_error = 2;  // fast-table: not within
    auto cycles = [](uint64_t draw, uint64_t choose) {
        TradeRow::Cycles c;
        c.draw = draw, c.choose = choose;
        return c;
    };
    rows[0].cycles_486 = cycles(9000, 0), rows[1].cycles_486 = cycles(3000, 0), rows[2].cycles_486 = cycles(1000, 0);
    rows[3].cycles_486 = cycles(2500, 500), rows[3].cycles_486.priced_draw = 2000, rows[3].cycles_486.priced_pixels = 100;
    rows[1].cycles_pentium = cycles(800, 0), rows[3].cycles_pentium = cycles(1000, 100);
    const std::string t = auto_against_singles_by_target(rows);
    EXPECT_NE(t.find("| a | 1 exact | 486 | 20.0 | 25.0 | 20.0% | fast-affine | 30.0 | 1.50× | 1.20× |"), std::string::npos) << t;
    EXPECT_NE(t.find("| a | 1 exact | Pentium | - | 10.0 | 10.0% | fast-affine | 8.0 | - | 0.80× |"), std::string::npos) << t;
    rows[3].cycles_486 = rows[3].cycles_pentium = TradeRow::Cycles{};
    EXPECT_EQ(auto_against_singles_by_target(rows), "") << "auto not run on a target";
}

// The CSV read back holds every figure the report and the docs show: written again, it is the same
// file, byte for byte; a malformed field is named with its line.
TEST(Trade, TheCsvReadBackIsTheSameRows) {
    std::vector<TradeRow> rows = {row("a", "exact", 9000, 0), row("a", "fast-affine", 3000, 1.25), row("a", "auto", 2500, 0.5)};
    rows[0].max_bound = 0, rows[0].bound_exact = true;
    rows[1].max_bound = raster::NO_BOUND, rows[1].host_ratio = 0.625, rows[1].accuracy.max_footprint_error = 3.5;
    rows[2].drawn_by = {{"exact", 3, 40}, {"fast-affine", 17, 60}}, rows[2].enveloped = 12, rows[2].choose = 77;
    rows[2].proven_whole = 5, rows[2].proven_spans = 2;
    rows[2].budget_error = 0.5, rows[2].budget_exact = true, rows[2].budget_given = true;
    rows[1].budget_error = raster::ANY_ERROR;
    for (TradeRow& r : rows) r.accuracy.exact = 61, r.accuracy.within_one = 90, r.accuracy.gaps = 2, r.frames = 8;
    mark_pareto(rows);
    const std::string dir = testing::TempDir() + "/trade_back";
    write_csv(dir + "/trade.csv", rows);
    const std::vector<TradeRow> back = read_trade(dir + "/trade.csv");
    ASSERT_EQ(back.size(), rows.size());
    write_csv(dir + "/again.csv", back);
    EXPECT_EQ(read_whole_file(dir + "/again.csv"), read_whole_file(dir + "/trade.csv"));
    EXPECT_EQ(back[2].budget, "footprint error 0.5, exact coverage");
    EXPECT_EQ(back[1].budget_error, raster::ANY_ERROR);
    EXPECT_EQ(back[1].max_bound, raster::NO_BOUND);
    EXPECT_EQ(back[2].drawn_by, rows[2].drawn_by);
    EXPECT_EQ(back[2].proven_whole, 5u);
    EXPECT_EQ(back[2].proven_spans, 2u);

    std::vector<std::vector<std::string>> lines = read_csv(dir + "/trade.csv");
    // the timing model's columns: read back where measured, and a CSV without them (an earlier
    // bench's) still reads, its cycles not measured
    {
        std::vector<TradeRow> timed = rows;
        auto cycles = [](uint64_t draw, uint64_t inner, uint64_t zero_wait, uint64_t isa, uint64_t vlb) {
            TradeRow::Cycles c;
            c.draw = draw, c.inner = inner, c.frame[0] = zero_wait, c.frame[1] = isa, c.frame[2] = vlb;
            return c;
        };
        timed[1].cycles_pentium = cycles(300, 200, 500, 900, 600);
        timed[1].cycles_pentium.setup = 60, timed[1].cycles_pentium.walk = 30, timed[1].cycles_pentium.choose = 10;
        timed[1].cycles_486 = cycles(700, 450, 1100, 1300, 1150);
        write_csv(dir + "/timed.csv", timed);
        const std::vector<TradeRow> t = read_trade(dir + "/timed.csv");
        EXPECT_EQ(t[1].cycles_pentium.draw, 300u);
        EXPECT_EQ(t[1].cycles_pentium.frame[1], 900u);
        EXPECT_EQ(t[1].cycles_486.inner, 450u);
        EXPECT_EQ(t[1].cycles_pentium.setup, 60u);
        EXPECT_EQ(t[1].cycles_pentium.walk, 30u);
        EXPECT_EQ(t[1].cycles_pentium.choose, 10u);
        EXPECT_EQ(t[0].cycles_486.draw, 0u) << "not measured";
        // auto priced for each target: its cycles there both ways, and what each drew with
        timed[2].cycles_486 = cycles(2000, 1000, 3000, 4000, 3500);
        timed[2].cycles_486.priced_draw = 1800, timed[2].cycles_486.priced_pixels = 100;
        timed[2].cycles_486.priced_by = {{"exact", 2, 30}, {"fast-table", 10, 70}};
        timed[2].cycles_pentium = cycles(900, 500, 1500, 2500, 1700);
        timed[2].cycles_pentium.priced_draw = 800, timed[2].cycles_pentium.priced_pixels = 100;
        timed[2].cycles_pentium.priced_by = {{"fast-subdiv-16", 12, 100}};
        write_csv(dir + "/priced.csv", timed);
        const std::vector<TradeRow> priced = read_trade(dir + "/priced.csv");
        EXPECT_EQ(priced[2].cycles_486.priced_by, timed[2].cycles_486.priced_by);
        EXPECT_EQ(priced[2].cycles_pentium.priced_pixels, 100u);
        const std::string by_target = auto_by_target(priced);
        EXPECT_NE(by_target.find("| a | 0.5 exact | 20.0 | 18.0 | 9.0 | 8.0 | fast-table 70.0%, exact 30.0% | fast-subdiv-16 100.0% |"), std::string::npos)
            << by_target;
        EXPECT_EQ(auto_by_target(t), "") << "no row priced";
        // the plot on a target: the rows run there, at its cycles a pixel, its own front
        const std::string plots = dir + "/plots";
        std::filesystem::create_directories(plots);
        write_plot(plots, "a", t, "pentium");
        const std::string gp = read_whole_file(plots + "/trade-a-pentium.gp");
        EXPECT_NE(gp.find("timing model, Pentium"), std::string::npos) << gp;
        EXPECT_NE(gp.find("\n3.000 1.2500\n"), std::string::npos) << gp;
        EXPECT_NE(gp.find("'fast-affine' at screen"), std::string::npos) << gp;
        EXPECT_EQ(gp.find("'exact'"), std::string::npos) << "exact was not run on the Pentium: " << gp;
        write_plot(plots, "a", t, "486");
        EXPECT_NE(read_whole_file(plots + "/trade-a-486.gp").find("\n7.000 1.2500\n"), std::string::npos);
        EXPECT_EQ(write_plot(plots, "a", rows, "486"), "") << "nothing run on the 486";
        const std::string table = cycles_table(t);
        EXPECT_NE(table.find("| fast-affine | 4.5 | 7.0 | 11.0 | 13.0 | 11.5 | 2.0 | 3.0 | 5.0 | 9.0 | 6.0 |"), std::string::npos)
            << "100 pixels a row: " << table;
        // straight into Mode X against RAM and the blit: each bus picks its own winner
        timed[0].surface = "vga", timed[0].cycles_pentium = cycles(300, 200, 700, 800, 650);
        const std::string modex = modex_table(timed);
        EXPECT_NE(modex.find("| a | pentium | zero-wait | exact 7.0 | fast-affine 5.0 | RAM and blit |"), std::string::npos) << modex;
        EXPECT_NE(modex.find("| a | pentium | isa | exact 8.0 | fast-affine 9.0 | straight |"), std::string::npos) << modex;
        EXPECT_EQ(modex.find("| 486 |"), std::string::npos) << "no 486 row drawn straight";
        // the front on the Pentium: exact draws in 3.0 cycles a pixel with no error, fast-affine in the
        // same 3.0 with 1.25: exact alone is on it
        const std::string fronts = pareto_by_target(timed);
        EXPECT_NE(fronts.find("| a | pentium | exact (3.0, 0.000) |"), std::string::npos) << fronts;
        std::ofstream old(dir + "/old.csv");
        for (const auto& fields : lines) {
            size_t n = 0;
            for (size_t i = 0; i < fields.size(); ++i)
                if (lines[0][i].rfind("cycles_", 0) != 0 && lines[0][i].rfind("drawn_by_priced_", 0) != 0) old << (n++ ? "," : "") << fields[i];
            old << "\n";
        }
    }
    EXPECT_EQ(read_trade(dir + "/old.csv").size(), rows.size());
    const size_t frames = size_t(std::find(lines[0].begin(), lines[0].end(), "frames[count]") - lines[0].begin());
    lines[3].at(frames) = "x";
    {
        std::ofstream bad(dir + "/bad.csv");
        for (const auto& fields : lines)
            for (size_t i = 0; i < fields.size(); ++i) bad << fields[i] << (i + 1 < fields.size() ? "," : "\n");
    }
    try {
        read_trade(dir + "/bad.csv");
        ADD_FAILURE() << "a bad count was read";
    } catch (const HarnessError& e) {
        EXPECT_NE(std::string(e.what()).find("line 4: frames 'x' is not a count"), std::string::npos) << e.what();
    }
}

// A generated block is the generator's output for its name, between its markers; the text around it
// stays; an unknown name or a block without its end is an error, not a silent skip.
TEST(TradeDocs, BlocksAreRegeneratedBetweenTheirMarkers) {
    std::vector<TradeRow> rows = {row("a", "exact", 9000, 0), row("a", "fast-affine", 2000, 1), row("a", "auto", 2500, 0)};
    for (TradeRow& r : rows) r.accuracy.max_footprint_error = 0.5, r.budget_error = 1, r.budget_exact = true;
    const std::string text = "before\n<!-- make bench: headline -->\nstale figures\n<!-- end make bench -->\nbetween\n"
                             "<!-- make bench: scene a -->\n<!-- end make bench -->\nafter\n";
    int blocks = 0;
    const std::string fresh = refresh_generated(text, rows, "t.md", &blocks);
    EXPECT_EQ(blocks, 2);
    EXPECT_EQ(fresh.find("stale"), std::string::npos) << fresh;
    EXPECT_NE(fresh.find("<!-- make bench: headline -->\n" + headline_table(rows) + "<!-- end make bench -->\nbetween\n"), std::string::npos) << fresh;
    EXPECT_NE(fresh.find("| a | 1, exact coverage | 25.0 | 0.50 | fast-affine | 20.0 | 90.0 |"), std::string::npos) << fresh;
    EXPECT_NE(fresh.find("<!-- make bench: scene a -->\n" + scene_table(rows, "a") + "<!-- end make bench -->\nafter\n"), std::string::npos);
    EXPECT_EQ(refresh_generated(fresh, rows, "t.md", nullptr), fresh);
    EXPECT_THROW(refresh_generated("<!-- make bench: nonsense -->\n<!-- end make bench -->\n", rows, "t.md", nullptr), HarnessError);
    EXPECT_THROW(refresh_generated("<!-- make bench: scene b -->\n<!-- end make bench -->\n", rows, "t.md", nullptr), HarnessError);
    EXPECT_THROW(refresh_generated("x\n<!-- make bench: headline -->\nno end\n", rows, "t.md", nullptr), HarnessError);
}

// The figures in README.md and docs/results.md are the generator's, from the committed CSV of the
// last full make bench: a typed or stale figure in a generated table fails here.
TEST(TradeDocs, TheCommittedDocsHoldTheGeneratorsFigures) {
    const std::vector<TradeRow> rows = read_trade(DOCS_TRADE_CSV);
    ASSERT_FALSE(rows.empty());
    for (const std::string& path : GENERATED_DOCS) {
        const std::string text = read_whole_file(path);
        int blocks = 0;
        const std::string fresh = refresh_generated(text, rows, path, &blocks);
        EXPECT_GT(blocks, 0) << path << " has no generated table";
        if (fresh == text) continue;
        size_t at = 0;
        while (at < text.size() && at < fresh.size() && text[at] == fresh[at]) ++at;
        const size_t line = 1 + size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n'));
        ADD_FAILURE() << path << ": line " << line << " differs from what make bench generates from " << DOCS_TRADE_CSV
                      << " (run `build/host/modexlab-bench --refresh-docs " << DOCS_TRADE_CSV << "`):\n"
                      << text.substr(text.rfind('\n', at) + 1, 300);
    }
}

LoadedWorld demo(const char* name) { return load_world_file(std::string("scenes/") + name + ".scene"); }


// A clock that counts its own reads: deterministic phases.
uint64_t g_clock = 0;
uint64_t counting_clock() { return g_clock += 7; }

TEST(Probe, ChangesNoPictureAndItsPhasesAddUp) {
    LoadedWorld w = demo("cube");
    auto frame = world_frame(w, 40);
    int probed = 0;
    for (int i = 0; i < MAPPER_COUNT; ++i) {
        const Mapper& m = MAPPERS[i];
        Axis axis = home_axis(m);
        RenderStats plain;
        IndexImage want = render_world_frame(w, *frame, m, axis, &plain);
        // the same drawing through the probe, on the same kind of surface
        std::vector<uint8_t> surface(SCREEN_PIXELS, 0);
        bool planar = ram_planar(m, axis);
        Target t = ram_target(surface.data(), planar);
        Probe probe;
        probe.clock = counting_clock;
        probe.calibrate();
        EXPECT_EQ(probe.lap_cost, 7u);
        probe.start();
        const uint64_t start = probe.last;
        RenderStats stats = render_frame(*frame, *w.textures, m, axis, t, Variant::Twin, &probe);
        EXPECT_EQ(stats.pixels, plain.pixels) << m.name;
        std::vector<uint8_t> mine = surface;
        if (planar) linear_from_planar(surface.data(), mine.data());
        EXPECT_EQ(mine, want.index) << m.name;
        uint64_t sum = 0;
        for (uint64_t ticks : probe.ticks) sum += ticks;
        EXPECT_EQ(sum, probe.last - start) << m.name;
        // only auto laps its choosing
        EXPECT_EQ(probe.laps[int(Phase::Choose)] > 0, m.is_auto) << m.name;
        EXPECT_EQ(probe.net(Phase::Choose), 0u) << m.name;
        if (stats.polygons) {
            ++probed;
            EXPECT_GT(probe.laps[int(Phase::Setup)], 0u) << m.name;
            EXPECT_GT(probe.laps[int(Phase::Inner)], 0u) << m.name << ": its per-span code is never timed";
            // each lap read the clock once: with the cost taken off, nothing is left
            EXPECT_EQ(probe.net(Phase::Setup), 0u) << m.name;
            EXPECT_EQ(probe.net(Phase::Inner), 0u) << m.name;
        }
    }
    EXPECT_GE(probed, 10);
}

TEST(Measure3d, TheExactMapperMeasuresAsExact) {
    for (const char* name : {"ball", "corridor", "cube"}) {
        LoadedWorld w = demo(name);
        auto frame = world_frame(w, 25);
        AccuracyMetrics m = measure_world_frame(w, *frame, *find_mapper("exact"), Axis::Rows);
        EXPECT_GT(m.reference_pixels, 1000u) << name;
        EXPECT_EQ(m.compared, m.exact) << name;
        EXPECT_EQ(m.max_texel_error, 0u) << name;
        EXPECT_EQ(m.gaps + m.overdraw + m.overlaps + m.index_differs, 0u) << name;
    }
}

TEST(Measure3d, MappersThatPromiseExactCoverageCountThePixelsTheReferenceCovers) {
    for (const char* name : {"corridor", "mesh", "rotozoom"}) {
        LoadedWorld w = demo(name);
        auto frame = world_frame(w, 60);
        // the reference's pixels, polygon by polygon (what a frame's pixel count adds up)
        uint64_t covered = 0;
        Picture p(SCREEN_WIDTH, SCREEN_HEIGHT);
        const Vertex* v = frame->vertices;
        for (int32_t i = 0; i < frame->polygon_count; ++i) {
            clear_pixel_image(p.view, 0);
            reference_polygon(v, frame->polygon_size[i], w.textures->objects[frame->polygon_object[i]], p.view);
            for (uint8_t c : p.coverage) covered += c;
            v += frame->polygon_size[i];
        }
        ASSERT_GT(covered, 0u);
        for (int i = 0; i < MAPPER_COUNT; ++i) {
            const Mapper& m = MAPPERS[i];
            if (!m.guarantee.exact_coverage) continue;
            RenderStats stats;
            render_world_frame(w, *frame, m, home_axis(m), &stats);
            if (stats.rejected) continue;  // textures it cannot take
            EXPECT_EQ(stats.pixels, covered) << name << " " << m.name;
            AccuracyMetrics a = measure_world_frame(w, *frame, m, home_axis(m));
            EXPECT_EQ(a.gaps + a.overdraw + a.overlaps, 0u) << name << " " << m.name;
        }
    }
}

TEST(Measure3d, AffineIsWorseThanSubdividedPerspectiveOnTheCorridor) {
    LoadedWorld w = demo("corridor");
    auto frame = world_frame(w, 0);
    AccuracyMetrics affine = measure_world_frame(w, *frame, *find_mapper("affine"), Axis::Rows);
    AccuracyMetrics subdiv = measure_world_frame(w, *frame, *find_mapper("persp-subdiv-8"), Axis::Rows);
    EXPECT_GT(affine.mean_texel_error, 10 * subdiv.mean_texel_error);
    EXPECT_GT(subdiv.exact, affine.exact);
}

// The goals' last rows: on the corridor, our fastest perspective mapper within one footprint (on the
// Pentium, the whole scene drawn) over our fastest affine one; a classic, auto, a mapper above one
// footprint or one not run on the Pentium do not count.
TEST(Trade, TheGoalsSetOurFastestPerspectiveAgainstOurFastestAffine) {
    auto pentium = [](TradeRow r, uint64_t draw, double max_error, const char* family = "ours") {
        r.cycles_pentium.draw = draw, r.accuracy.max_footprint_error = max_error, r.family = family;
        return r;
    };
    const std::vector<TradeRow> rows = {pentium(row("corridor", "fast-table", 100, 1.5), 250, 2.5),
                                        pentium(row("corridor", "fast-affine", 100, 1.5), 400, 2.5),
                                        pentium(row("corridor", "fast-subdiv-16", 100, 0.2), 300, 0.9),
                                        pentium(row("corridor", "fast-subdiv-32", 100, 0.4), 280, 1.2),
                                        pentium(row("corridor", "quake-d_draw16", 100, 0.2), 100, 0.5, "classic"),
                                        pentium(row("corridor", "auto", 100, 0.2), 90, 0.5),
                                        row("corridor", "exact", 100, 0)};
    std::ostringstream out;
    write_goals(out, rows);
    EXPECT_NE(out.str().find("| corridor: fastest perspective within one footprint over fastest affine | Pentium | 1.3 | fast-subdiv-16 3.0 / "
                             "fast-table 2.5 = 1.20 | yes |"),
              std::string::npos)
        << out.str();
    EXPECT_NE(out.str().find("| freedoom: fastest perspective within one footprint over fastest affine | Pentium | 1.3 | - | - |"), std::string::npos)
        << out.str();
}

// Names never overprint each other or a point, the front's are placed first, and a crowd is named
// around it with leader lines: here twenty points within a few pixels of each other and one far off
// (freedoom's plot had one classic at 2600 instructions a pixel and the rest near 5).
TEST(TradePlot, NamesNeitherOverlapNorCoverAPoint) {
    const PlotArea area{90, 64, 970, 589};
    std::vector<PlotLabel> labels;
    for (int i = 0; i < 20; ++i) {
        PlotLabel l;
        l.x = 200 + 3 * (i % 5), l.y = 300 + 4 * (i / 5), l.text = "mapper-number-" + std::to_string(i), l.front = i == 7;
        labels.push_back(l);
    }
    PlotLabel far;
    far.x = 960, far.y = 580, far.text = "hecker-steptable";
    labels.push_back(far);
    place_labels(labels, area);
    for (size_t i = 0; i < labels.size(); ++i) {
        const PlotLabel& a = labels[i];
        ASSERT_TRUE(a.placed) << a.text;
        EXPECT_TRUE(a.left >= area.left && a.right <= area.right && a.bottom >= area.bottom && a.top <= area.top) << a.text << ": inside the area";
        EXPECT_GE(a.right - a.left, 7 * double(a.text.size())) << "room for the text";
        for (size_t j = 0; j < labels.size(); ++j) {
            const PlotLabel& b = labels[j];
            const bool over = i != j && a.left < b.right && b.left < a.right && a.bottom < b.top && b.bottom < a.top;
            EXPECT_FALSE(over) << a.text << " over " << b.text;
            EXPECT_FALSE(b.x + 7 > a.left && b.x - 7 < a.right && b.y + 7 > a.bottom && b.y - 7 < a.top) << a.text << " covers " << b.text << "'s point";
        }
    }
    EXPECT_FALSE(labels[7].leader) << "the front's name placed first, beside its point";
    EXPECT_TRUE(std::any_of(labels.begin(), labels.end(), [](const PlotLabel& l) { return l.leader; })) << "a crowd needs leader lines";
}

// The plot of a scene whose speeds span decades: both axes logarithmic over positive ranges, every
// mapper named (or listed as without room), the front's names in its colour.
TEST(TradePlot, ALogSpeedAxisAndEveryMapperNamed) {
    const std::vector<TradeRow> rows = read_trade("docs/data/trade.csv");
    const std::string dir = build_dir() + "/test-tmp/plot";
    std::filesystem::create_directories(dir);
    write_plot(dir, "freedoom", rows, "");
    const std::string gp = read_whole_file(dir + "/trade-freedoom.gp");
    EXPECT_NE(gp.find("set logscale xy\n"), std::string::npos);
    const size_t range = gp.find("set xrange [");
    ASSERT_NE(range, std::string::npos);
    EXPECT_GT(std::stod(gp.substr(range + 12)), 0.0) << "no negative or zero speed axis";
    size_t named = 0, front = 0;
    for (const TradeRow* r : drawing_rows_by_speed(rows, "freedoom")) {
        const bool labelled = gp.find("'" + r->mapper + "' at screen") != std::string::npos;
        const size_t note = gp.find("no room to name:");
        EXPECT_TRUE(labelled || (note != std::string::npos && gp.find(r->mapper, note) != std::string::npos)) << r->mapper;
        named += labelled;
        if (r->pareto) front += gp.find("'" + r->mapper + "' at screen") != std::string::npos &&
                                gp.find("tc rgb '#c03030'", gp.find("'" + r->mapper + "' at screen")) < gp.find("\n", gp.find("'" + r->mapper + "' at screen"));
    }
    EXPECT_GE(named, drawing_rows_by_speed(rows, "freedoom").size() - 2) << gp;
    EXPECT_GE(front, 2u) << "the front's points named in its colour";
}

}  // namespace
