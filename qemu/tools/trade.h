// The speed/accuracy trade: one row per scene and mapper, the Pareto front, and the report files
// (CSV, Markdown, gnuplot plots). docs/bench.md says what every figure is and how it is measured.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "kernel/mappers/auto/choice.h"
#include "qemu/accuracy/metrics.h"

namespace harness {

// The budgets auto is benched (and shown in the gallery) at besides the scene's own: footprint
// errors, with exact coverage. A row at one is named auto@BUDGET (budget_text).
inline constexpr double AUTO_BUDGETS[] = {0, 0.5, 1, 2, 4};

// v with that many decimals: the report's figures.
std::string fixed(double v, int decimals);

// A budget's footprint error as the kernel's `budget` command and the report write it: 0.5, 2.
std::string budget_text(double max_error);
// A budget in words: "footprint error 1, exact coverage: the default".
std::string budget_words(const raster::Budget& b);

// The mappers a tool's --mappers option names, each checked against the registry (UsageError
// unknown_mapper's).
std::vector<std::string> known_mappers(std::vector<std::string> names);
// "unknown mapper 'X' (the mappers, the nearest first: ...)"; `also`: other names the tool takes
// there (the render tool's "reference"), listed among them.
std::string unknown_mapper(const std::string& name, const std::vector<std::string>& also = {});

struct TradeRow {
    using DrawnBy = std::vector<std::tuple<std::string, uint64_t, uint64_t>>;  // mapper, polygons, pixels
    std::string scene, mapper, family, surface, walker, loop;
    uint32_t frames = 0;
    // the kernel's drawing, summed over the frames: counts, and ticks (instructions under icount)
    uint64_t polygons = 0, rejected = 0, spans = 0, pixels = 0;
    // (choose: auto's choosing beyond its setup of each polygon, Phase::Choose; 0 for a single mapper)
    uint64_t ticks = 0, geometry = 0, clear = 0, draw = 0, setup = 0, walk = 0, inner = 0, choose = 0, blit = 0;
    raster::AccuracyMetrics accuracy;  // the host twin against the reference, summed over the same frames
    bool kernel_equals_host = false;   // at the last frame, by screendump
    double host_ratio = 0;             // host rdtsc cycles per pixel against the baseline mapper; 0: not measured
    bool pareto = false;
    // the kernel's polygons and pixels per mapper that drew them (auto draws with several), and the
    // scene's budget auto chose for, in words
    DrawnBy drawn_by;
    uint64_t enveloped = 0;  // of those, the polygons auto drew as their object's envelope proved
    uint64_t proven_whole = 0, proven_spans = 0;  // and as their whole polygon's bound, their spans' (the rest: unasked)
    bool levels_known = true;  // the two above measured (a trade.csv of an earlier bench has them not)
    // the polygons auto drew unasked: all it drew (drawn_by) but those proven at some level
    uint64_t unasked() const {
        uint64_t drawn = 0;
        for (const auto& by : drawn_by) drawn += std::get<1>(by);
        const uint64_t asked = enveloped + proven_whole + proven_spans;
        return drawn > asked ? drawn - asked : 0;
    }
    std::string budget;
    double budget_error = -1;   // the budget's footprint error (below 0: any), whether it asks for
    bool budget_exact = false;  // exact coverage, and whether the scene states it (else the default)
    bool budget_given = false;
    // A single mapper's proof on the same frames (world_frame_bound): the largest of its bounds over
    // the polygons it draws (NO_BOUND: one has none), and whether each promised exact coverage;
    // below 0: not computed (auto's rows: every polygon proven within the budget by its choice)
    double max_bound = -1;
    bool bound_exact = false;
    // The drawing's ticks with the 486's build of the kernel's C++ (booted isa=i486, docs/platform.md)
    // on the same frames: every single mapper's row and auto's at the scene's budget; 0: not measured
    uint64_t draw_i486 = 0;
    // The timing model's cycles on the same frames, a target each (the kernel under QEMU's -cpu 486
    // or pentium with the timing plugin: docs/cycles.md, "Whole frames"): the drawing's (setup,
    // walking, inner loops, choosing) and the inner loops', and the frame's (its plain drawing:
    // geometry, clearing, drawing, the blit) on each bus, zero-wait, isa and vlb; 0: not measured
    struct Cycles {  // draw = setup + walk + inner + choose (the probe's phases, net of the laps)
        uint64_t draw = 0, setup = 0, walk = 0, inner = 0, choose = 0, frame[3] = {};
        // auto's row (at the scene's budget) again with the budget priced for this target: its
        // drawing's cycles and what it chose (docs/auto.md, "Per target"); 0: not run
        uint64_t priced_draw = 0, priced_pixels = 0;
        DrawnBy priced_by;
    };
    Cycles cycles_486, cycles_pentium;
    // a target's ("486", else the Pentium's)
    Cycles& cycles_on(const std::string& target) { return target == "486" ? cycles_486 : cycles_pentium; }
    const Cycles& cycles_on(const std::string& target) const { return target == "486" ? cycles_486 : cycles_pentium; }

    bool draws_everything() const { return rejected == 0 && pixels > 0; }
    double per_pixel(uint64_t t) const { return pixels ? double(t) / double(pixels) : 0.0; }
    double inner_per_pixel() const { return per_pixel(inner); }
    double draw_per_pixel() const { return per_pixel(draw); }  // setup, walking, inner loops: the mapper's own cost
    double frame_per_pixel() const { return per_pixel(ticks); }
    double setup_per_polygon() const { return polygons ? double(setup) / double(polygons) : 0.0; }
    double walk_per_span() const { return spans ? double(walk) / double(spans) : 0.0; }
    double share_exact() const { return accuracy.compared ? double(accuracy.exact) / accuracy.compared : 0.0; }
};

// Marks the Pareto front among the rows that draw everything, scene by scene: a row is on it when
// no other row is at least as fast (drawing instructions per pixel) and at least as exact (mean
// texel error) and better in one of the two. Ties in both: all of them are on it.
void mark_pareto(std::vector<TradeRow>& rows);

// The front of (cost, error) points, both to be minimised: the indices on it (the rule above).
std::vector<size_t> pareto_front(const std::vector<std::pair<double, double>>& points);

// The rows' scenes, in the order they first appear.
std::vector<std::string> scenes_in_order(const std::vector<TradeRow>& rows);

// build/report/trade.csv: a header line naming each column with its unit, then one line a row.
void write_csv(const std::string& path, const std::vector<TradeRow>& rows);
std::vector<std::string> csv_header();
// Reads such a file back: a vector of fields a line (no quoting: no field holds a comma).
std::vector<std::vector<std::string>> read_csv(const std::string& path);
// Where the column `name` is in such a file's header, its unit in brackets aside (HarnessError
// naming `where` when it has none).
size_t csv_column(const std::vector<std::string>& header, const std::string& name, const std::string& where);
// The rows of a trade.csv, every figure as the file holds it (columns found by name; HarnessError
// naming the line and field where one is missing or malformed). The report and the docs' tables
// are written from these, so that both show the CSV's figures.
std::vector<TradeRow> read_trade(const std::string& path);

struct ReportInfo {
    std::string how;       // how the figures were measured (QEMU icount, frames, ...)
    std::string command;   // the command that regenerates the report
    std::vector<std::string> plots;  // plot files written (for the links)
    std::string wall_clock;          // the Markdown of the wall-clock table, if measured
};

// Whether the row is a single mapper's (a registry row that does not choose; auto's rows are
// "auto" and "auto@BUDGET").
bool single_mapper(const TradeRow& r);
// Whether the row meets a budget on the whole scene: everything drawn, the measured max footprint
// error within it, and exact coverage if it asks for it.
bool meets_budget(const TradeRow& r, double max_error, bool exact_coverage);
// The fastest single mapper on a's scene whose measured error meets a's budget on every frame
// (everything drawn, its max footprint error within, exact coverage where asked); nullptr: none.
const TradeRow* fastest_within(const std::vector<TradeRow>& rows, const TradeRow& a);

// The Markdown that trade.md and the docs share (docs/results.md, the README): a scene's table,
// sorted by speed, with the mappers that cannot draw it and what auto drew it with; the table of
// the single mappers on a scene every one of them draws whole ("" where one refuses a polygon);
// auto's rows against the fastest single mappers within their budget (only the rows at the
// scene's own budget: scene_budget_only).
std::string scene_table(const std::vector<TradeRow>& rows, const std::string& scene);
std::string same_work_table(const std::vector<TradeRow>& rows, const std::string& scene);
std::string auto_rows(const std::vector<TradeRow>& rows, bool scene_budget_only);
// An auto row's polygons by the level of their proof: "object / polygon / spans / unasked" (the
// reference's definition, drawn where choosing cannot pay); "-" where the row does not say.
std::string proof_levels(const TradeRow& a);

// The rows measured with the 486's build beside the P6's (draw_i486), a line a mapper: drawing
// instructions a pixel of each over all the scenes, their ratio, and the least and most of a scene's.
std::string isa_table(const std::vector<TradeRow>& rows);

// build/report/trade.md: per scene, a table sorted by speed; the mappers that cannot draw it; the
// classics' published figures beside ours.
void write_markdown(const std::string& path, const std::vector<TradeRow>& rows, const ReportInfo& info);

// A file of the report opened for writing, its directory made (HarnessError where it cannot be).
std::ofstream open_out(const std::string& path);
// A scene's rows that drew, by drawing instructions a pixel, fastest first.
std::vector<const TradeRow*> drawing_rows_by_speed(const std::vector<TradeRow>& rows, const std::string& scene);

// A plot's point and where its name went, in the picture's pixels (y up): the label's box, and
// whether a leader line joins it to a point it had to move away from. `placed` false: no room left
// within reach of the point (the plot's note lists it).
struct PlotLabel {
    double x = 0, y = 0;  // the point
    std::string text;
    bool front = false;
    bool placed = false, leader = false;
    double left = 0, bottom = 0, right = 0, top = 0;
};
// The plot area in pixels, and a label's size: a character's width and a line's height.
struct PlotArea {
    double left, bottom, right, top, char_width = 7, line_height = 12;
};
// Names the points (pixels) with boxes that overlap neither each other nor a point's marker, inside
// the area: the front's first, then in the order given; each at the nearest free place around its
// point, rings further out with a leader line.
void place_labels(std::vector<PlotLabel>& labels, const PlotArea& area);

// trade-SCENE.gp and, when gnuplot is installed, trade-SCENE.png: speed (log scale) against mean
// footprint error (log scale), each point named where no other name or point is (place_labels),
// the Pareto front joined and its points named in its colour. Returns the PNG's path, or "" when not drawn.
// `target` 486 or pentium: trade-SCENE-TARGET.*, the timing model's drawing cycles a pixel there
// (the rows run on it, its own front), "" where none was.
std::string write_plot(const std::string& dir, const std::string& scene, const std::vector<TradeRow>& rows, const std::string& target = "");

}  // namespace harness
