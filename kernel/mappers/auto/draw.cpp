// auto's polygon and frame drivers (draw.h).
#include "kernel/mappers/auto/draw.h"

#include "kernel/mappers/auto/choice.h"
#include "kernel/mappers/fastsubdiv.h"

namespace raster {

namespace {

// (`set_up`: `prepared` holds the polygon's setup already, as choose_mapper takes it)
SetupStatus choose_and_draw(const Vertex* vertices, int count, const Texture& tex, Axis axis, Target& target, RenderStats* stats,
                            Variant variant, const Budget& budget, Input input, PreparedPolygon& prepared, bool set_up = false) {
    Choice c = choose_mapper(budget, vertices, count, tex, target, &prepared, input, stats->probe, set_up);
    probe_lap(stats->probe, Phase::Choose);
    if (!c.mapper) {
        const Axis any = target_supports(target, axis) ? axis : Axis::Columns;  // a walker the target takes
        return Drawer::of(auto_fallback(), tex, any, target, stats, variant).draw_set_up(vertices, count, nullptr, nullptr);
    }
    const bool ok = prepared.status == SetupStatus::Ok;
    // (a candidate: its walker, texture and target checked when the list was built)
    const SetupStatus status = Drawer::of(*c.mapper, tex, c.axis, target, stats, variant, true)
                                   .draw_set_up(vertices, count, ok ? &prepared.setup : nullptr, &prepared.walked[int(c.axis)]);
    if (status == SetupStatus::Ok) ++(c.by_spans ? stats->proven_spans : stats->proven_whole);
    return status;
}

// unchosen_mapper, its time charged to auto's choosing (the loop's before it to walking)
const Mapper* timed_unchosen(const AutoPlan& plan, const Vertex* vertices, int count, const ClipRect& clip, Axis* axis, const RenderStats& stats,
                             const CornerBox* box) {
    probe_lap(stats.probe, Phase::Walk);
    const Mapper* m = unchosen_mapper(plan, vertices, count, clip, axis, box);
    probe_lap(stats.probe, Phase::Choose);
    return m;
}

// Whether a polygon lies at one depth, its corners' w all the same: the affine planes are then its
// mapping, and it is the choice's (choose_mapper's one_depth).
bool one_depth(const Vertex* vertices, int count) {
    for (int i = 1; i < count; ++i)
        if (vertices[i].w != vertices[0].w) return false;
    return true;
}

// auto's oriented path (OrientedPlan), along the walker fast-oriented-B picks (a planar target:
// columns), where fast_oriented_guard holds: fast-constant-depth where the same proof bounds its
// chords within the budget and its row is the cheaper, else the plan's oriented pick, where the
// pick's estimate is within the gate or affine_deviation is above the budget (choose_mapper's
// tests). Set up into `prepared`: the perspective planes where the gate may hold (the corners'
// test), else every plane, affine_deviation asked first. Else Unproven, nothing drawn, and
// `prepared` set up with every plane for the choice (status Ok), or not at all. The setup and the
// walker are Phase::Setup as in fast-oriented-1's own driver, the rest Phase::Choose.
SetupStatus draw_oriented(OrientedPath& path, const Texture& tex, Variant variant, const Vertex* vertices, int count, Input input, Target& target,
                          RenderStats* stats, bool gate_may_hold, PreparedPolygon* prepared) {
    const OrientedPlan& plan = path.plan;
    const ClipRect& clip = target.clip;
    Probe* probe = stats->probe;
    PolygonSetup& s = prepared->setup;
    bool affine = !gate_may_hold;  // the affine planes set up
    prepared->status = setup_polygon(vertices, count, &s, affine ? PLANES_ALL : PLANES_PERSPECTIVE, input);
    if (prepared->status != SetupStatus::Ok) return SetupStatus::Unproven;
    PolygonSize size[2];
    polygon_sizes(s, clip, size);
    const Axis axis = target.planar ? Axis::Columns : oriented_axis(s, size, plan.walker_room);
    probe_lap(probe, Phase::Setup);
    auto set_up_affine = [&] {
        affine = true;
        prepared->status = setup_polygon(vertices, count, &s, PLANES_AFFINE, input);
        probe_lap(probe, Phase::Setup);
        return prepared->status == SetupStatus::Ok;
    };
    // (where the gate cannot hold, an affine stepping that may meet the budget leaves it to the choice)
    const bool guarded = gate_may_hold || affine_deviation(s, clip) > plan.budget;
    const double q_min = guarded ? fast_oriented_guard(s, clip, axis, plan.texel_most) : 0;
    // (fast-constant-depth where the cheaper by its row, as choose_mapper takes it)
    const double oriented = estimate_cost(plan.oriented_row, size[int(axis)]), constant_at = estimate_cost(plan.constant_row, size[int(axis)]);
    const bool constant = q_min > 0 && plan.constant && constant_at < oriented && fast_constant_within(s, clip, axis, q_min, plan.room);
    bool taken = false;
    if (q_min > 0) {
        const double rows = size[int(Axis::Rows)].spans, columns = size[int(Axis::Columns)].spans;
        const double least_lines = (plan.least.span < 0) == (rows < columns) ? columns : rows;  // (the fewer; below 0 a line, the more)
        taken = !gate_may_hold || (constant ? constant_at : oriented) <= estimate_cost(plan.least, PolygonSize{least_lines, size[0].pixels}) + plan.gate;
        // past the gate, where no affine stepping could meet the budget
        if (!taken && set_up_affine()) taken = affine_deviation(s, clip) > plan.budget;
    }
    probe_lap(probe, Phase::Choose);
    if (!taken) {
        if (!affine) set_up_affine();  // (the choice's)
        return SetupStatus::Unproven;
    }
    Drawer& d = path.drawer[int(axis)][constant];
    if (!path.made[int(axis)][constant]) {
        path.made[int(axis)][constant] = true;
        d = Drawer::of(constant ? *plan.constant : *plan.oriented, tex, axis, target, stats, variant);
    }
    if (!d.usable) {
        if (!affine) set_up_affine();
        return SetupStatus::Unproven;
    }
    const SetupStatus status = d.draw_set_up(vertices, count, &s, nullptr);
    if (status == SetupStatus::Ok) ++stats->proven_whole;
    return status;
}

// The oriented path's try on a polygon of an object whose box oriented_box takes, not at one depth
// (one_depth): the object's plan where it is the first to ask, the gate from the corners, then
// draw_oriented. (Out of line: off the way of the frame's loop and of the envelope's triangles.)
[[gnu::noinline]] SetupStatus try_oriented(OrientedPath& path, const CornerBox& box, const Frame& frame, const Texture& tex, Variant variant,
                                           const Vertex* vertices, int count, int32_t object, Input input, Target& target, RenderStats* stats,
                                           PreparedPolygon* prepared) {
    probe_lap(stats->probe, Phase::Walk);
    if (!path.planned) {
        path.planned = true;
        path.plan = plan_oriented(frame.budget, tex, target, frame.texel_most[object]);
        path.made[0][0] = path.made[0][1] = path.made[1][0] = path.made[1][1] = false;
    }
    if (!path.plan.oriented) return SetupStatus::Unproven;
    const bool gate_may_hold = oriented_gate_may_hold(path.plan, box, target.clip, vertices, count);
    probe_lap(stats->probe, Phase::Choose);
    return draw_oriented(path, tex, variant, vertices, count, input, target, stats, gate_may_hold, prepared);
}

// An object's plans and drawers for the frame: kept from the frames before where its key is the
// same (ChoiceLists::objects), else made; the drawers pointed at this frame's target and statistics.
AutoObject& frame_object(AutoObject& k, bool keep, const Budget& budget, const Texture& tex, Target& target, Variant variant, double texel_most,
                         RenderStats* stats) {
    const AutoObjectKey key = auto_object_key(budget, tex, target, variant, texel_most);
    if (!keep || !k.kept || !same_key(k.key, key)) {
        k.kept = true, k.key = key;
        plan_auto(budget, tex, target, 0, &k.plan);  // (the envelope's mapper where any bound would do)
        k.oriented.planned = false;
        if (k.plan.enveloped) {  // (plan_auto checked what Drawer::of would)
            k.enveloped = Drawer::of(*k.plan.enveloped, tex, k.plan.enveloped_axis, target, stats, variant, true);
            k.enveloped.limits.area2 = k.plan.enveloped_area2;
            (k.plan.enveloped_axis == Axis::Rows ? k.enveloped.limits.extent_y : k.enveloped.limits.extent_x) = k.plan.enveloped_extent;
        }
        if (k.plan.certain)
            for (int a = 0; a < 2; ++a) k.certain[a] = Drawer::of(*k.plan.certain, tex, Axis(a), target, stats, variant);
    }
    k.enveloped.target = k.certain[0].target = k.certain[1].target = &target;
    k.enveloped.stats = k.certain[0].stats = k.certain[1].stats = stats;
    if (k.oriented.planned)
        for (Drawer* d = &k.oriented.drawer[0][0]; d != &k.oriented.drawer[0][0] + 4; ++d) d->target = &target, d->stats = stats;
    return k;
}

}  // namespace

SetupStatus draw_unproven(const Drawer& enveloped, const Vertex* vertices, Variant variant, const Budget& budget) {
    PreparedPolygon prepared;
    return choose_and_draw(vertices, 3, *enveloped.tex, enveloped.axis, *enveloped.target, enveloped.stats, variant, budget, Input::InRange, prepared);
}

SetupStatus auto_draw(const DrawContext& c, const Vertex* vertices, int count) {
    PreparedPolygon prepared;
    return choose_and_draw(vertices, count, c.tex, c.axis, c.target, c.stats, c.variant, c.budget ? *c.budget : DEFAULT_BUDGET, c.input, prepared);
}

RenderStats auto_draw_frame(const Frame& frame, const TextureSet& textures, const Mapper& mapper, Axis axis, Target& target,
                            Variant variant, Probe* probe, const Watch* watch) {
    RenderStats stats;
    stats.probe = probe;
    // what auto settles per object (choice.h, AutoPlan and AutoObject): kept in the lists' memory
    // from frame to frame, else this frame's own; and whether its envelope's mapper draws its uncut
    // triangles in this frame (its envelope's bound within the budget)
    union Own {
        Own() {}
        AutoObject objects[MAX_WORLD_OBJECTS];
    } own;
    const bool keep = frame.budget.lists != nullptr;
    AutoObject* objects = keep ? frame.budget.lists->objects : own.objects;
    bool envelope[MAX_WORLD_OBJECTS];
    const bool oriented_wanted = oriented_plan_wanted(frame.budget);
    for (int32_t o = 0; o < MAX_WORLD_OBJECTS && o < frame.object_count; ++o) {
        const AutoObject& k = frame_object(objects[o], keep, frame.budget, textures.objects[o], target, variant, frame.texel_most[o], &stats);
        envelope[o] = k.plan.enveloped && budget_allows(frame.budget, ErrorBound{true, true, frame.envelope[o].footprint});
        probe_lap(stats.probe, Phase::Choose);  // (the plans)
    }
    PreparedPolygon prepared;  // (each polygon's in turn, for the path and the choice)
    // every polygon but the envelope's (out of line: the envelope's triangles' loop stays as small)
    auto unproven = [&](const Vertex* v, int n, int object, Input input) __attribute__((noinline)) {
        AutoObject& k = objects[object];
        const AutoPlan& plan = k.plan;
        Axis unchosen_axis;
        CornerBox box;
        bool set_up = false;  // (by the oriented path, for the choice)
        if (oriented_wanted) {
            box = corner_box(v, n);
            if (!one_depth(v, n) && oriented_box(plan.small_box.most_box, box, target.clip)) {
                prepared.status = SetupStatus::Degenerate;
                if (try_oriented(k.oriented, box, frame, textures.objects[object], variant, v, n, object, input, target, &stats, &prepared) !=
                    SetupStatus::Unproven)
                    return;
                set_up = prepared.status == SetupStatus::Ok;
            }
        }
        if (timed_unchosen(plan, v, n, target.clip, &unchosen_axis, stats, oriented_wanted ? &box : nullptr))  // (the certain one, or none)
            k.certain[int(unchosen_axis)].draw(v, n, input);
        else
            choose_and_draw(v, n, textures.objects[object], axis, target, &stats, variant, frame.budget, input, prepared, set_up);
    };
    each_frame_polygon(frame, mapper, watch, &stats, [&](const Vertex* v, int n, int object, Input input) {
        if (envelope[object] && input == Input::InRange && n == 3)  // (an uncut triangle)
            draw_enveloped(objects[object].enveloped, v, variant, frame.budget);
        else
            unproven(v, n, object, input);
    });
    if (watch) watch->drawn();
    return stats;
}

}  // namespace raster
