// auto's choice (docs/auto.md): the cost model the bench measures, the candidates, their proofs and
// the plans per object (kept from frame to frame), with which auto draws each polygon with the
// cheapest mapper whose bound meets the scene's budget (kernel/core/budget.h).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/core/bound.h"
#include "kernel/core/budget.h"
#include "kernel/core/prepared.h"
#include "kernel/core/render.h"
#include "kernel/scene/world.h"

namespace raster {

// The cost model (kernel/mappers/auto/costs.cpp, written by `make bench` from its own figures): per
// target, the cost to set up a polygon, per span (walking and the loop's call), per pixel, in the
// target's unit. One row per registry row, in its order.
struct MapperCost {
    const char* mapper;
    float polygon, span, pixel;
};
extern const MapperCost MAPPER_COSTS[];  // icount's
extern const int MAPPER_COST_COUNT;
// A target's rows, and what an instruction of auto's own work (its proofs and pricing, whose
// costs below are in instructions) costs there: the bench's cycles over instructions of auto's
// choosing (1 for icount).
struct CostModel {
    const char* target;
    const MapperCost* rows;
    double proof_scale;
};
extern const CostModel COST_MODELS[int(CostTarget::Count)];
inline const CostModel& cost_model(CostTarget t) { return COST_MODELS[int(t)]; }

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
// The mappers auto's choices draw with: the choosable ones, and the row whose role is Oriented,
// which draws its oriented candidate (ORIENTED_GATE).
bool drawn_by_auto(const Mapper& m);
// The row that draws what no candidate may (role Fallback: exact).
const Mapper& auto_fallback();

struct Choice {
    const Mapper* mapper = nullptr;  // nullptr: no mapper draws the polygon (degenerate, or refused)
    Axis axis = Axis::Rows;          // the walker it draws with
    ErrorBound bound;
    bool by_spans = false;           // proven span by span (else by the whole polygon at once)
};

// auto's own costs below are instructions under icount; on a cycle target, times its proof_scale.
// What proving a bound span by span costs auto, in instructions a span of the polygon: its bounds'
// walk of the span (a line, the coarse bound, pieces where needed) in the kernel, from the bench's
// figures (docs/auto.md, "The rule").
constexpr double BOUND_SPAN_COST = 600;
// What asking a bound of the whole polygon costs: the polygon's spread from its vertices and the
// bound from it (docs/bench.md, "The cost model"); nothing for a mapper that promises the reference
// itself (exact: bound 0).
constexpr double BOUND_WHOLE_COST = 1400;
inline double whole_proof_cost(const Mapper& m) { return m.guarantee.max_error == 0 ? 0 : BOUND_WHOLE_COST; }
// Whether the mapper's bound runs its own walk again, with nothing for the whole polygon at once:
// the classics with a fill convention of their own (X-Sharp, Hecker, fatmap). auto asks them only
// span by span.
inline bool bound_walks(const Mapper& m) { return !m.guarantee.exact_coverage; }
// Whether auto asks the mapper's bound span by span: one whose bound walks, only so; another only
// where its whole-polygon bound is above the budget and its row says its spans' can be much tighter
// (SPANS_ASKED: constant-depth, whose error depends on each line's direction, and Quake's, whose
// clamps and evaluation depend on each span's place). The others' spans prove no more than their
// whole polygon's bound on the demo scenes (docs/auto.md, "The rule").
inline bool proven_by_spans(const Mapper& m) { return bound_walks(m) || m.span_proof == SPANS_ASKED; }
// A candidate's cost to auto with its first proof, as a cost row: its estimate and the
// whole-polygon bound (whole_proof_cost), or, for a mapper whose bound walks, its setup and walk
// again (its row without the pixels) and BOUND_SPAN_COST a line; the proofs' instructions times
// `proof_scale` (CostModel). A candidate proven span by span after its whole-polygon bound
// (proven_by_spans) costs BOUND_SPAN_COST a span more.
inline CostRow proven_cost(const Mapper& m, const CostRow& row, double proof_scale) {
    if (bound_walks(m)) return CostRow{2 * row.polygon, 2 * row.span + BOUND_SPAN_COST * proof_scale, row.pixel};
    return CostRow{row.polygon + whole_proof_cost(m) * proof_scale, row.span, row.pixel};
}
// The cheapest choosable mapper and walker by the cost model, its proof counted (proven_cost), that
// draws into targets like `target`, takes the texture and whose bound meets the budget on the
// polygon (docs/auto.md, "The rule"): the whole polygon asked first, the spans where proven_by_spans;
// ties to the cheaper per pixel, then rows, then registry order; exact, unasked, where nothing
// cheaper can be proven for less. Candidates are priced lazily, cheapest per pixel first. Set up
// once, into *prepared (`set_up`: there already, every plane), and walked only where a bound needs
// the spans (the choice draws from them). `input`: as setup_polygon takes it. `probe`: the bench's
// lap timer, which charges the setup to Phase::Setup (the caller laps the rest, Phase::Choose).
Choice choose_mapper(const Budget& budget, const Vertex* vertices, int count, const Texture& tex, const Target& target,
                     PreparedPolygon* prepared, Input input = Input::Any, Probe* probe = nullptr, bool set_up = false);

// Builds the candidate lists choose_mapper and plan_auto take for a texture at a budget, for
// either kind of target (linear, planar), into Budget::lists (nothing without), where they are not
// built yet: a scene's load and a change of budget call it, so that no polygon drawn pays for them
// (docs/auto.md, "What choosing costs").
void prepare_choice(const Budget& budget, const Texture& tex);

// What choosing costs beyond the bounds it asks, in instructions a polygon with some ten candidates
// priced: the setup's extra planes, the polygon's sizes and the pricing. Where exact costs no more
// than the others' least plus this, it is drawn unchosen (unchosen_mapper); the parts, and why not
// less: docs/auto.md, "Settled once per object".
constexpr double CHOICE_COST = 1800;

// From a budget of one footprint, auto's oriented candidate (choose_mapper: fast-adaptive-B, or
// fast-constant-depth, along fast-oriented-B's walker, proven from the setup) is taken without a
// search where its price is at most ORIENTED_GATE above the least any candidate could cost with
// its proof, or where affine_deviation is above the budget; elsewhere the search looks only for a
// proven candidate cheaper than it. The gate is wide because that least is loose (exact's setup
// with fast-table's pixels; docs/auto.md, "The rule", 4).
constexpr double ORIENTED_GATE = 20000;

// How much cheaper the certain candidate's setup a polygon may be than the enveloped mapper's for
// the envelope still to count as the cheaper on every triangle: exact's dearer lines and pixels
// make up its cheaper setup on any triangle of two lines and a pixel, and on smaller ones the cost
// model's straight lines are too coarse to choose by (docs/auto.md, "The object's envelope").
constexpr double ENVELOPE_SETUP_ALLOWANCE = 500;

// The box sizes where choosing cannot pay on any polygon inside (unchosen_mapper, before the
// polygon's area and estimates): the certain one's estimate is at most the others' least plus
// CHOICE_COST wherever fixed + line L + other_line M + pixel W H <= -1, with W and H the box's sides
// inside the clip (pixels), L its lines along the certain one's walker and M the longer side; each
// term the largest its part of the estimates' difference can be in such a box (docs/auto.md).
struct SmallBox {
    int64_t most_box;  // the largest W H (subpixels squared) where it can hold; -1: nowhere (one candidate, or no certain one)
    double fixed, line, other_line, pixel;
};

// What auto settles per object before drawing its polygons (AutoObject keeps it from frame to
// frame; docs/auto.md, "The object's envelope" and "Settled once per object"): the mapper the
// object's envelope proves on its uncut triangles (envelope_footprint, frame.h) and its walker,
// where exactly one candidate is enveloped and, with no proof to pay, costs no more than any other
// with its proof on every triangle the guards and limits below let through (draw_enveloped); the
// certain candidate (exact), its walkers and cost row, for unchosen_mapper; whether it is the only
// one (a budget of 0), else the least cost a polygon, a span and a pixel of any other with its
// first proof. No default member initialisers: plan_auto fills them.
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
    double choice_cost;  // CHOICE_COST in the budget's target's unit
    // twice the pixels (subpixels squared) above which unchosen_mapper gives nullptr at once, from
    // the corners' box and area in integers (no exact_below, and the certain one costs more a
    // pixel than the least of the others): there its estimate on either walker is above theirs on
    // the walker where they cost least, plus CHOICE_COST, by a pixel's difference at least; else
    // INT64_MAX
    int64_t choosing_pays_above2;
    SmallBox small_box;
};
// The candidates for a texture, a target and a budget, (mapper, walker) pairs (choose_mapper and
// plan_auto build them): what they depend on is a few bits (the texture's copies and shape, the
// target's kind, whether the budget asks for exact coverage, which only some mappers promise, and
// whether it asks for no error at all, which only the reference itself promises), so each set is
// built once, in the order of their cost per pixel (the term that dominates on all but the smallest
// polygons), so that a polygon prices them lazily: only while one not yet priced could cost less
// than the cheapest priced and not yet asked (the dearest per pixel are mostly never priced).
struct CandidateList {
    bool built = false;
    CostTarget priced_for = CostTarget::Icount;  // the cost model it was built with (rebuilt on a change)
    int count = 0;
    int certain = -1;  // the first that promises the reference itself (exact): its bound costs nothing and always holds
    int16_t row[2 * MAPPER_LIMIT] = {};
    Axis axis[2 * MAPPER_LIMIT] = {};
    CostRow cost[2 * MAPPER_LIMIT] = {};  // the cost model's row with the first proof (proven_cost)
    bool walks[2 * MAPPER_LIMIT] = {};    // bound_walks: proven span by span only
    bool spans[2 * MAPPER_LIMIT] = {};    // proven_by_spans: asked span by span (after the whole polygon)
    // the least cost a polygon, a span and a pixel of candidates k on: what any of them costs at least
    double least_polygon[2 * MAPPER_LIMIT] = {}, least_span[2 * MAPPER_LIMIT] = {}, least_pixel[2 * MAPPER_LIMIT] = {};
    // the candidates an object's envelope proves (Mapper::enveloped), whether every other one costs,
    // with its proof, at least as much as the first of them without on any triangle the guards let
    // through, and up to how many pixels where one costs less a pixel (AutoPlan::enveloped_area2)
    int enveloped_count = 0, enveloped_first = -1;
    bool envelope_cheapest = false;
    double envelope_pixels = 0, envelope_lines = 0;  // (AutoPlan::enveloped_area2, enveloped_extent)
    AutoPlan plan{};  // plan_auto's but the envelope's part
    // fast-adaptive-1 along each walker, and fast-oriented-1 (which draws it along the walker it
    // picks, with its own driver): the oriented candidate (choose_mapper); -1: none here
    int adaptive[2][2] = {{-1, -1}, {-1, -1}};  // [fast-adaptive-1, -2][Axis]
    int oriented_row = -1;                      // fast-oriented-1's registry row
    // fast-constant-depth along each walker: what the oriented candidate's certificate or spread
    // proves too (fast_chords_bound); -1: none here
    int constant_depth[2] = {-1, -1};  // [Axis]
};

// Room for a list built where no lists are prepared: untouched otherwise.
union ListRoom {
    ListRoom() {}
    CandidateList list;
};

// An object's plan, into `plan` (an AutoObject's: no copy of it on the way).
void plan_auto(const Budget& budget, const Texture& tex, const Target& target, double envelope_footprint, AutoPlan* plan);
inline AutoPlan plan_auto(const Budget& budget, const Texture& tex, const Target& target, double envelope_footprint) {
    AutoPlan plan;
    plan_auto(budget, tex, target, envelope_footprint, &plan);
    return plan;
}

// auto's oriented path for an object (docs/auto.md, "The oriented path"): choose_mapper's oriented
// candidate taken unsearched, proven by fast_oriented_guard, from a budget of 1 on, on a
// repeating texture whose corners' |u|, |v| are within `texel_most` (Frame::texel_most) where
// fast_oriented_guard_takes: fast-oriented-1 below 2, else fast-adaptive-2 along fast-oriented-2's
// walker (`walker_room`), and fast-constant-depth where measured (else nullptr), with the budget's
// fast_adaptive_room; the gate as choose_mapper's, and the budget affine_deviation is weighed
// against past it; else oriented nullptr. Made where an object's first polygon asks for it.
struct OrientedPlan {
    const Mapper* oriented;
    const Mapper* constant;
    double room;
    CostRow oriented_row, constant_row, least;
    double gate, budget;
    double walker_room;  // fast_adaptive_room(B): oriented_axis's
    double texel_most;   // (fast_oriented_guard's, for a polygon the clip cuts)
};
inline bool oriented_plan_wanted(const Budget& budget) { return budget.max_error >= 1; }
OrientedPlan plan_oriented(const Budget& budget, const Texture& tex, const Target& target, double texel_most);

// The extent inside the clip [first, end) (pixels) of a box's side from lo to hi, in subpixels:
// clamped in 32 bits (a vertex's coordinates are, and the clip's edges in subpixels are within 2^17).
inline int32_t box_inside(int32_t lo, int32_t hi, int32_t first, int32_t end) {
    first *= int32_t(SUBPIXEL_ONE), end *= int32_t(SUBPIXEL_ONE);
    lo = lo < first ? first : lo, hi = hi > end ? end : hi;
    return hi > lo ? hi - lo : 0;
}

// The box of a polygon's corners, as the setup finds it.
struct CornerBox {
    int32_t x_lo, x_hi, y_lo, y_hi;  // subpixels
};
inline CornerBox corner_box(const Vertex* vertices, int count) {
    CornerBox b{vertices[0].x.raw, vertices[0].x.raw, vertices[0].y.raw, vertices[0].y.raw};
    for (int i = 1; i < count; ++i) {
        const int32_t x = vertices[i].x.raw, y = vertices[i].y.raw;
        b.x_lo = x < b.x_lo ? x : b.x_lo, b.x_hi = x > b.x_hi ? x : b.x_hi, b.y_lo = y < b.y_lo ? y : b.y_lo, b.y_hi = y > b.y_hi ? y : b.y_hi;
    }
    return b;
}

// The footprint (texel_footprint) at a polygon's first corner, from the planes through its first
// three (1e300 where they are collinear): cheap, before any setup.
double corner_footprint(const Vertex* vertices);
// The certain mapper and its walker where choosing cannot pay on the polygon: where it is the only
// candidate; where the budget is below 1, the polygon inside the clip and the footprint at its
// first corner below 1 / budget (no other bound can meet the budget near that corner: a judgement
// of cost, not of accuracy); or where its estimate on its cheaper walker is at most the least any
// other candidate could cost with its proof, plus CHOICE_COST. Its walker as choose_mapper would
// take it; sizes from the corners (the box and area polygon_sizes would find), before any setup.
// Else nullptr: choose_mapper decides (docs/auto.md, "Settled once per object").
// (`box`: the corners' box where the caller has it, else nullptr.)
const Mapper* unchosen_mapper(const AutoPlan& plan, const Vertex* vertices, int count, const ClipRect& clip, Axis* axis, const CornerBox* box = nullptr);

// Whether auto's oriented path is to be tried on the polygon, from its corners before any setup:
// where its box inside the clip is not one unchosen_mapper gives the certain one at once
// (`small_box`: AutoPlan::small_box's most_box); then where the gate can hold (the picks' least
// estimate within it of the least any candidate could cost, from the box inside the clip and the
// area).
inline bool oriented_box(int64_t small_box, const CornerBox& b, const ClipRect& clip) {
    return int64_t(box_inside(b.x_lo, b.x_hi, clip.x0, clip.x1)) * box_inside(b.y_lo, b.y_hi, clip.y0, clip.y1) > small_box;
}
bool oriented_gate_may_hold(const OrientedPlan& plan, const CornerBox& box, const ClipRect& clip, const Vertex* vertices, int count);

// How far the affine planes (fast-affine's line) lie from the exact mapping, in footprints (either
// axis, the texel distance over the footprint), at the mean of the corners of a polygon inside the
// clip, or, reaching outside it, at the centre of the pixel in the middle of its box inside the
// clip; 0 (nothing known) where it covers fewer than AFFINE_DEVIATION_PIXELS, does not cover that
// pixel, or Q is not above 0 there. A floor, not a bound: no mapper that steps the polygon affinely
// has a bound below it (measured, not derived: docs/auto.md, "Where the search cannot pay"). Above
// the budget, the oriented candidate's gate skips the search: were it wrong, auto would miss a
// cheaper mapper, never its budget. Asked only where the gate's first test would search.
constexpr int64_t AFFINE_DEVIATION_PIXELS = 100;
double affine_deviation(const PolygonSetup& s, const ClipRect& clip);

// auto's own bound: its choice's under the default budget.
ErrorBound auto_bound(const BoundContext& c, const Vertex* vertices, int count);

// An object's oriented path: its plan, made at its first polygon, and its drawers, each made where
// first drawn with.
struct OrientedPath {
    bool planned;
    OrientedPlan plan;
    bool made[2][2];  // [Axis][the oriented pick, fast-constant-depth]
    Drawer drawer[2][2];
};

// What an object's plans and drawers are made from (auto_object_key): the texture (where it is and
// its fields), the budget, the target's kind and clip, the loops' variant and the object's texels.
struct AutoObjectKey {
    const Texture* tex;
    Texture texture;
    double max_error, texel_most;
    ClipRect clip;
    bool exact_coverage, planar, vga;
    CostTarget priced_for;
    Variant variant;
};
AutoObjectKey auto_object_key(const Budget& budget, const Texture& tex, const Target& target, Variant variant, double texel_most);
bool same_key(const AutoObjectKey& a, const AutoObjectKey& b);

// What auto_draw_frame keeps of an object from one frame to the next: its plan (with the mapper of
// its envelope where one of any bound would do: each frame decides by its envelope's), its oriented
// path, and the drawers of the envelope's mapper and of the certain one by walker, all made again
// where the key differs. The drawers' target and statistics are each frame's.
struct AutoObject {
    bool kept = false;
    AutoObjectKey key;
    AutoPlan plan;
    Drawer enveloped, certain[2];
    OrientedPath oriented;
};

// The lists for every texture and target kind a budget may meet (256 keys: the bits above), built
// where first needed (prepare_choice builds a texture's at its load), and what auto keeps of each
// object of a frame: the caller's memory, which a budget names (Budget::lists); without, choose_mapper
// and plan_auto build the list they need, and auto_draw_frame makes its objects' plans each frame.
struct ChoiceLists {
    CandidateList lists[256];
    AutoObject objects[MAX_WORLD_OBJECTS];
};
// Forgets the objects auto keeps: the next frame makes their plans and drawers again.
inline void forget_objects(ChoiceLists* lists) {
    for (AutoObject& o : lists->objects) o.kept = false;
}

}  // namespace raster
