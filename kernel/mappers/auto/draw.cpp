// auto's polygon and frame drivers (draw.h).
#include "kernel/mappers/auto/draw.h"

#include "kernel/mappers/auto/choice.h"

namespace raster {

namespace {

SetupStatus choose_and_draw(const Vertex* vertices, int count, const Texture& tex, Axis axis, Target& target, RenderStats* stats,
                            Variant variant, const Budget& budget, Input input) {
    PreparedPolygon prepared;
    Choice c = choose_mapper(budget, vertices, count, tex, target, &prepared, input, stats->probe);
    probe_lap(stats->probe, Phase::Choose);
    if (!c.mapper) {
        const Axis any = target_supports(target, axis) ? axis : Axis::Columns;  // a walker the target takes
        return Drawer::of(auto_fallback(), tex, any, target, stats, variant).draw_set_up(vertices, count, nullptr, nullptr);
    }
    const bool set_up = prepared.status == SetupStatus::Ok;
    // (a candidate: its walker, texture and target checked when the list was built)
    const SetupStatus status = Drawer::of(*c.mapper, tex, c.axis, target, stats, variant, true)
                                   .draw_set_up(vertices, count, set_up ? &prepared.setup : nullptr, &prepared.walked[int(c.axis)]);
    if (status == SetupStatus::Ok) ++(c.by_spans ? stats->proven_spans : stats->proven_whole);
    return status;
}

// unchosen_mapper, its time charged to auto's choosing (the loop's before it to walking)
const Mapper* timed_unchosen(const AutoPlan& plan, const Vertex* vertices, int count, const ClipRect& clip, Axis* axis, const RenderStats& stats) {
    probe_lap(stats.probe, Phase::Walk);
    const Mapper* m = unchosen_mapper(plan, vertices, count, clip, axis);
    probe_lap(stats.probe, Phase::Choose);
    return m;
}

}  // namespace

SetupStatus draw_unproven(const Drawer& enveloped, const Vertex* vertices, Variant variant, const Budget& budget) {
    return choose_and_draw(vertices, 3, *enveloped.tex, enveloped.axis, *enveloped.target, enveloped.stats, variant, budget, Input::InRange);
}

SetupStatus auto_draw(const DrawContext& c, const Vertex* vertices, int count) {
    return choose_and_draw(vertices, count, c.tex, c.axis, c.target, c.stats, c.variant, c.budget ? *c.budget : DEFAULT_BUDGET, c.input);
}

RenderStats auto_draw_frame(const Frame& frame, const TextureSet& textures, const Mapper& mapper, Axis axis, Target& target,
                            Variant variant, Probe* probe, const Watch* watch) {
    RenderStats stats;
    stats.probe = probe;
    // what auto settles once a frame per object (choice.h, AutoPlan), and the drawers of the mapper
    // its envelope proves and of its certain mapper by walker (what unchosen_mapper gives)
    AutoPlan plans[MAX_WORLD_OBJECTS];
    Drawer enveloped[MAX_WORLD_OBJECTS];
    Drawer certain[MAX_WORLD_OBJECTS][2];
    for (int32_t o = 0; o < MAX_WORLD_OBJECTS && o < frame.object_count; ++o) {
        const Texture& tex = textures.objects[o];
        plans[o] = plan_auto(frame.budget, tex, target, frame.envelope[o].footprint);
        if (plans[o].enveloped) {  // (plan_auto checked what Drawer::of would)
            enveloped[o] = Drawer::of(*plans[o].enveloped, tex, plans[o].enveloped_axis, target, &stats, variant, true);
            enveloped[o].limits.area2 = plans[o].enveloped_area2;
            (plans[o].enveloped_axis == Axis::Rows ? enveloped[o].limits.extent_y : enveloped[o].limits.extent_x) = plans[o].enveloped_extent;
        }
        if (plans[o].certain)
            for (int a = 0; a < 2; ++a) certain[o][a] = Drawer::of(*plans[o].certain, tex, Axis(a), target, &stats, variant);
        probe_lap(stats.probe, Phase::Choose);  // (the plans)
    }
    each_frame_polygon(frame, mapper, watch, &stats, [&](const Vertex* v, int n, int object, Input input) {
        const AutoPlan& plan = plans[object];
        Axis unchosen_axis;
        if (plan.enveloped && input == Input::InRange && n == 3)  // (an uncut triangle)
            draw_enveloped(enveloped[object], v, variant, frame.budget);
        else if (timed_unchosen(plan, v, n, target.clip, &unchosen_axis, stats))  // (the certain one, or none)
            certain[object][int(unchosen_axis)].draw(v, n, input);
        else
            choose_and_draw(v, n, textures.objects[object], axis, target, &stats, variant, frame.budget, input);
    });
    if (watch) watch->drawn();
    return stats;
}

}  // namespace raster
