// The budgeted choice of mapper (docs/auto.md): a scene's budget, the cost model
// the bench measures, and `auto`, which draws each polygon with the cheapest mapper whose bound
// meets the budget.
#pragma once

#include <stdint.h>

#include "kernel/core/bound.h"
#include "kernel/core/prepared.h"

namespace raster {

// What a scene requires of a mapper: the largest footprint error, and whether the pixels drawn
// must be exactly the reference's.
constexpr double ANY_ERROR = -1;
struct Budget {
    bool given = false;          // from the scene's budget line (else the default)
    double max_error = 1;        // footprints (docs/accuracy.md); ANY_ERROR: any
    bool exact_coverage = true;  // no gaps, no overdraw
};
// Scenes without a budget line: within one footprint, exact coverage.
constexpr Budget DEFAULT_BUDGET{};

inline bool budget_allows(const Budget& b, const ErrorBound& e) {
    return e.draws && (e.exact_coverage || !b.exact_coverage) && (b.max_error < 0 || e.footprint <= b.max_error);
}

// The cost model (kernel/mappers/costs.cpp, written by `make bench` from its own figures):
// instructions under QEMU icount to set up a polygon, per span (walking and the loop's call), per
// pixel. One row per registry row, in its order.
struct MapperCost {
    const char* mapper;
    float polygon, span, pixel;
};
extern const MapperCost MAPPER_COSTS[];
extern const int MAPPER_COST_COUNT;

// A polygon's size as the cost model counts it, from its setup (before any walk): its lines along
// the walker (rows or columns, from the bounding box inside the clip) and its pixels (its area, at
// most the box's inside the clip: the same along either walker).
struct PolygonSize {
    double spans, pixels;
};
void polygon_sizes(const PolygonSetup& s, const ClipRect& clip, PolygonSize size[2]);  // [Axis]
// A row of the model as the estimate computes with it: not measured (-1), dearer than any measured
// mapper in every part (so the least any candidate costs a span or a pixel, and the envelope's
// comparisons, are the measured ones').
struct CostRow {
    double polygon, span, pixel;  // (no initialisers: AutoPlan is kept a possible object)
};
inline CostRow cost_row(const MapperCost& c) { return c.polygon < 0 ? CostRow{1e30, 1e30, 1e30} : CostRow{c.polygon, c.span, c.pixel}; }
inline double estimate_cost(const CostRow& c, const PolygonSize& s) { return c.polygon + c.span * s.spans + c.pixel * s.pixels; }
inline double estimate_cost(const MapperCost& c, const PolygonSize& s) { return estimate_cost(cost_row(c), s); }

// Whether auto may choose the mapper: not auto itself, not one that picks its own walker
// (Mapper::own_walker: auto picks the walker of each of its candidates itself, and fast-oriented-1
// draws what fast-adaptive-1 does along one of them), and a derived bound (not `unbounded`, the
// placeholder a new mapper's row starts with).
bool choosable(const Mapper& m);
// The mappers auto's choices draw with: the choosable ones, and fast-oriented-1, which draws its
// oriented candidate (ORIENTED_GATE).
bool drawn_by_auto(const Mapper& m);

struct Choice {
    const Mapper* mapper = nullptr;  // nullptr: no mapper draws the polygon (degenerate, or refused)
    Axis axis = Axis::Rows;          // the walker it draws with
    ErrorBound bound;
    bool by_spans = false;           // proven span by span (else by the whole polygon at once)
};

// What proving a bound span by span costs auto, per span of the polygon: the instructions its
// bounds take to walk a span (a line, the coarse bound, pieces where needed) in the kernel,
// 400 to 900 under QEMU icount (make bench, setup per polygon of auto against the mappers it
// chose, over the spans it proved; docs/auto.md, "The rule").
constexpr double BOUND_SPAN_COST = 600;
// What asking a bound of the whole polygon costs: the polygon's spread from its vertices and the
// bound from it, about 1400 instructions (1430 for fast-affine's on the mesh, callgrind on the
// 32-bit host build); nothing for a mapper that promises the reference itself (exact: bound 0).
constexpr double BOUND_WHOLE_COST = 1400;
inline double whole_proof_cost(const Mapper& m) { return m.guarantee.max_error == 0 ? 0 : BOUND_WHOLE_COST; }
// Whether the mapper's bound runs its own walk again, with nothing for the whole polygon at once:
// the classics with a fill convention of their own (X-Sharp, Hecker, fatmap). auto asks them only
// span by span.
inline bool bound_walks(const Mapper& m) { return !m.guarantee.exact_coverage; }
// Whether auto asks the mapper's bound span by span: one whose bound walks, only so; another only
// where its whole-polygon bound is above the budget and its row says its spans' can be much tighter
// (SPANS_ASKED: constant-depth, whose error depends on each line's direction, and Quake's, whose
// clamps and evaluation depend on each span's place). The others' spans, asked 15000 times on the
// demo scenes at budgets 0.5 to 4, never proved what their whole polygon's bound did not.
inline bool proven_by_spans(const Mapper& m) { return bound_walks(m) || m.span_proof == SPANS_ASKED; }
// A candidate's cost to auto with its first proof, as a cost row: its estimate and the
// whole-polygon bound (whole_proof_cost), or, for a mapper whose bound walks, its setup and walk
// again (its row without the pixels) and BOUND_SPAN_COST a line. A candidate proven span by span
// after its whole-polygon bound (proven_by_spans) costs BOUND_SPAN_COST a span more.
inline CostRow proven_cost(const Mapper& m, const CostRow& row) {
    if (bound_walks(m)) return CostRow{2 * row.polygon, 2 * row.span + BOUND_SPAN_COST, row.pixel};
    return CostRow{row.polygon + whole_proof_cost(m), row.span, row.pixel};
}
// The cheapest choosable mapper and walker, by the cost model, that draws into targets like
// `target`, takes the texture and whose bound meets the budget on the polygon: rows or columns,
// whichever the target and the mapper take (floors by rows, walls by columns); a mapper that does
// not promise exact coverage only where the budget allows any, and at budget 0 only exact. The
// proof counts (proven_cost): a candidate is asked for the whole polygon at once first
// (PolygonSpread, from the vertices), so one proven that way costs its estimate plus
// whole_proof_cost, one proven span by span (proven_by_spans) that plus BOUND_SPAN_COST a span; one
// whose bound walks is asked span by span only, at its own price; the choice is the least of these (ties: the
// one cheaper per pixel, then rows first, in registry order): where the reference costs less
// than proving anything cheaper, exact, unasked. Candidates are priced only as the search needs
// them: in the order of their cost per pixel, while the least any of the rest could cost (the least
// per polygon, span and pixel among them) is below the cheapest priced and not yet asked; so none
// that cannot cost less than exact is priced. The polygon is set up once, into *prepared, and walked along a
// walker only when a bound needs its spans (the chosen mapper draws from its setup, and from its
// spans when walked). `input`: as setup_polygon takes it. `probe`: the bench's lap timer, which
// charges the setup to Phase::Setup (the caller laps the rest, Phase::Choose).
Choice choose_mapper(const Budget& budget, const Vertex* vertices, int count, const Texture& tex, const Target& target,
                     PreparedPolygon* prepared, Input input = Input::Any, Probe* probe = nullptr);

// Builds the candidate lists choose_mapper and plan_auto take for a texture at a budget, for
// either kind of target (linear, planar), where they are not built yet: a scene's load and a change
// of budget call it, so that the first polygon drawn does not pay for them (about 36000
// instructions a list in the kernel, QEMU icount: the first frame of a bench row had counted it
// as drawing).
void prepare_choice(const Budget& budget, const Texture& tex);

// What choosing costs beyond the bounds it asks (the setup's extra planes, the polygon's sizes, the
// pricing of the candidates): at a budget of 0, where exact is the only candidate, 295 a triangle
// (the mesh, make bench, QEMU icount, before unchosen_mapper); above it, with some ten candidates
// priced, about 1800 a polygon (the ball at 1, callgrind on the 32-bit host build: the search's own
// work 1280, the sizes and the candidates 260, the affine planes' setup about 300). At 300 the mesh
// at budget 0.5 chose on triangles of 20 pixels or so, and drew at 0.95 times exact's speed; at
// 1800, 0.98 (4 bench frames, QEMU icount).
constexpr double CHOICE_COST = 1800;

// From a budget of one footprint to below four, auto's oriented candidate: fast-adaptive-B (B = 1
// below two, 2 from two) along the walker fast-oriented-B would pick, proven by its certificate
// from the setup alone (fast_adaptive_certain: some 550 instructions, against 1100 for the spread a
// proof starts with), or fast-constant-depth along that walker where the same proof bounds its one
// chord a line within the budget (fast_chords_bound). It is taken without a search where, priced
// by its row (fast-adaptive-1's by fast-oriented-1's, which draws it), it costs no more than
// ORIENTED_GATE above the least any candidate could
// cost with its proof (the least polygon, span and pixel costs of all of them: loose, exact's
// setup with fast-table's pixels), or where affine_deviation is above the budget (no affine-stepping
// candidate can be within it, and the others share its core: the search's finds there had not
// paid for it on the ball, the corridor and freedoom); elsewhere the search looks only for a
// proven candidate cheaper than it. Why so wide a gate: on the ball at one footprint (facets of
// some 620 pixels, 25 lines) the search cost about 4000 instructions a facet beyond the oriented
// candidate's path and its choices saved about 1260 in the loops, while the least's gap there is
// about 9000; on the rotozoom's quad (40000 pixels, a gap of about 285000) it found fast-affine at
// less than two thirds of the oriented price. At four and above none: there the search finds
// fast-affine and fast-table on much of the ball, which fast-adaptive-2 unsearched lost.
constexpr double ORIENTED_GATE = 20000;

// How much cheaper the certain candidate's setup a polygon may be than the enveloped mapper's for
// the envelope still to count as the cheaper on every triangle: exact's setup takes only the
// perspective planes and is some 360 instructions below fast-affine's, which its dearer lines and
// pixels make up on any triangle of two lines and a pixel. On smaller ones the cost model's
// straight lines are not to be trusted that finely: weighed triangle by triangle, exact took about
// one triangle in nine of the mesh where the model put it cheaper, and auto drew the mesh at budget
// 1 at 265 draw instructions a pixel against fast-affine's 238 (QEMU icount; 240 with this).
constexpr double ENVELOPE_SETUP_ALLOWANCE = 500;

// What auto settles once a frame per object, before drawing its polygons (render_frame):
// - the mapper the object's envelope proves on its uncut triangles (envelope_footprint: the
//   object's envelope bound in the frame, frame.h), and its walker: where that bound meets the
//   budget, exactly one candidate is enveloped (Mapper::enveloped), and with no proof to pay it
//   costs no more than any other candidate with its proof on any triangle the guards let through
//   (1 to ENVELOPE_REACH + 1 lines, or where one costs less a line, as many as take at most half
//   of what its setup costs more: enveloped_extent) without its pixels (the certain one's setup
//   taken ENVELOPE_SETUP_ALLOWANCE higher), nor a pixel more, or where one costs less a pixel
//   (fast-table), no more on a triangle of up to enveloped_area2 / 2 pixels (its area, subpixels
//   squared): the choice choose_mapper would make on every such triangle were that proof free. A
//   triangle is drawn so only where it passes the envelope's guards and is no larger
//   (draw_enveloped, render.h);
// - the candidate proven for nothing (exact: it promises the reference itself), with its walkers
//   and cost row, for unchosen_mapper; and whether it is the only one (a budget of 0: every other
//   bound counts some rounding), and else the least cost a polygon, a span and a pixel of any
//   other candidate with its first proof.
// No default member initialisers: render_frame keeps one a possible object, and plan_auto sets
// every field (from a value-initialised plan) of the ones it uses.
struct AutoPlan {
    const Mapper* enveloped;
    Axis enveloped_axis;
    int64_t enveloped_area2;  // the largest doubled area (subpixels squared) of a triangle drawn so
    int32_t enveloped_extent;  // and its largest extent across the walker's lines (subpixels: its box's height for rows)
    const Mapper* certain;
    int certain_walkers;
    Axis certain_axes[2];  // in the candidates' order
    CostRow certain_row;
    bool sole;
    CostRow others;
    double exact_below;  // a budget below 1: the footprint (corner_footprint) below which only the certain one can meet it; else 0
    // twice the pixels (subpixels squared) above which unchosen_mapper gives nullptr at once, from
    // the corners' box and area in integers (no exact_below, and the certain one costs more a
    // pixel than the least of the others): there its estimate on either walker is above theirs on
    // the walker where they cost least, plus CHOICE_COST, by a pixel's difference at least; else
    // INT64_MAX
    int64_t choosing_pays_above2;
};
AutoPlan plan_auto(const Budget& budget, const Texture& tex, const Target& target, double envelope_footprint);

// The footprint (texel_footprint) at a polygon's first corner, from the planes through its first
// three (1e300 where they are collinear): cheap, before any setup.
double corner_footprint(const Vertex* vertices);
// The certain mapper and its walker where choosing cannot pay on the polygon: where it is the only
// candidate; where the budget is below 1, the polygon inside the clip and the footprint at its
// first corner below 1 / budget
// (every other bound is at least 1 / max(1, F) where F is least, so none can meet the budget near
// that corner: a judgement of cost, not of accuracy, since the certain one meets every budget); or
// where its estimate on its cheaper walker is no more than the least any other candidate could cost
// with its proof, plus CHOICE_COST. Its walker as choose_mapper would take it
// (its estimates differ only in the lines along each). Sizes from the corners (the box and the
// area the setup would find: polygon_sizes), before any setup. Else nullptr: choose_mapper decides.
const Mapper* unchosen_mapper(const AutoPlan& plan, const Vertex* vertices, int count, const ClipRect& clip, Axis* axis);

// How far the affine planes (fast-affine's line) lie from the exact mapping at the mean of the
// corners of a polygon inside the clip, or, reaching outside it, at the centre of the pixel in the
// middle of its box inside the clip, in footprints there (either axis, the texel distance over the
// footprint); 0 (nothing known) where it covers fewer than AFFINE_DEVIATION_PIXELS, does not cover
// that pixel, or Q is not above 0 there. Not a bound, a floor: no mapper that steps
// the polygon affinely (affine, fast-affine, fast-columns, fast-table, fast-table-columns) has a
// bound below it. That is measured, not derived: their bounds take the deviation over the part of
// the polygon their spread covers, which holds the corners' mean on all but small polygons (at the
// edges' midpoints instead, the bound was up to three times below on triangles of up to 15 pixels,
// and 0.75 times on one of 24000 random polygons of 100 pixels or more); the test asks it of every
// such mapper's tightest bound on 24000 random triangles and planar quads, some reaching outside
// the clip (least ratio 1.015).
// Where it is above the budget, the oriented candidate's gate (choose_mapper, ORIENTED_GATE) skips
// the search: were it wrong, auto would miss a cheaper mapper, never its budget. About 280
// instructions (callgrind, 32-bit host), asked only where the gate's first test would search.
constexpr int64_t AFFINE_DEVIATION_PIXELS = 100;
double affine_deviation(const PolygonSetup& s, const ClipRect& clip);

// auto's own bound: its choice's under the default budget.
ErrorBound auto_bound(const BoundContext& c, const Vertex* vertices, int count);

}  // namespace raster
