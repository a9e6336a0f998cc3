// Drawing a polygon (render.h): a mapper's own driver, or setup, the walker and the mapper per span,
// or a driver that chooses the mapper; a screen-space scene polygon by polygon.
#include "kernel/core/render.h"

#include "kernel/core/prepared.h"

namespace raster {

namespace {

// Draws the polygon with the drawer's mapper: its own driver, or setup, the walker (or the spans
// of the polygon as auto walked it) and its span function on each span. Counts the polygon.
// `setup`: the polygon set up already (every plane, for a mapper without its own driver), or
// nullptr; `walked`: its spans along the axis when auto walked them (count below 0: not), or
// nullptr. `input`: as setup.h says, for the setup done here or by the mapper's driver.
[[gnu::always_inline]] inline SetupStatus draw_with(const Drawer& d, const Vertex* vertices, int count, const PolygonSetup* setup,
                                                    const PreparedSpans* walked, Input input) {
    RenderStats* stats = d.stats;
    if (!d.usable) {
        ++stats->rejected;
        return SetupStatus::Unsupported;
    }
    Probe* probe = stats->probe;
    const uint32_t pixels_before = stats->pixels;
    const Mapper& mapper = *d.mapper;
    const Axis axis = d.axis;
    Target& target = *d.target;
    SetupStatus status;
    if (mapper.draw) {
        status = mapper.draw(DrawContext{*d.tex, axis, target, stats, d.loop, setup, input}, vertices, count);
    } else {
        auto draw_spans = [&](const PolygonSetup& set_up, auto&& next) {
            const SpanContext context{set_up, *d.tex, axis, d.loop};
            probe_lap(probe, Phase::Setup);
            Span span;
            while (next(&span)) {
                int32_t stride;
                uint8_t* dst = span_start(target, axis, span, &stride);
                emit(probe, stats, 1, uint32_t(span.count), [&] { mapper.span(context, span, dst, stride); });
            }
        };
        if (setup) {  // set up with every plane (and maybe walked) already
            status = SetupStatus::Ok;
            int32_t i = 0;
            if (walked && walked->count >= 0) draw_spans(*setup, [&](Span* s) { return i < walked->count && (*s = walked->spans[i++], true); });
            else {
                EdgeWalker walker(*setup, axis, target.clip);
                draw_spans(*setup, [&](Span* s) { return walker.next(s); });
            }
        } else {
            PolygonSetup own;
            status = setup_polygon(vertices, count, &own, mapper.span_planes, input);
            if (status == SetupStatus::Ok) {
                EdgeWalker walker(own, axis, target.clip);
                draw_spans(own, [&](Span* s) { return walker.next(s); });
            }
        }
    }
    probe_lap(probe, Phase::Walk);
    count_polygon(stats, d.row, status, pixels_before);
    return status;
}

}  // namespace

Drawer Drawer::of(const Mapper& mapper, const Texture& tex, Axis axis, Target& target, RenderStats* stats, Variant variant, bool checked) {
    Drawer d;
    d.mapper = &mapper, d.tex = &tex, d.target = &target, d.stats = stats, d.axis = axis;
    d.limits = EnvelopeLimits{INT64_MAX, INT32_MAX, INT32_MAX};
    d.loop = mapper_loop(mapper, variant, target);
    d.row = int32_t(&mapper - MAPPERS);
    d.usable = checked || (mapper_walks(mapper, axis) && mapper_accepts(mapper, tex) && mapper_targets(mapper, target, axis));
    d.own = d.usable && mapper.draw;
    return d;
}

SetupStatus Drawer::draw(const Vertex* vertices, int count, Input input) const {
    probe_lap(stats->probe, Phase::Walk);  // what came before the polygon: the caller's loop
    return draw_with(*this, vertices, count, nullptr, nullptr, input);
}

SetupStatus Drawer::draw_set_up(const Vertex* vertices, int count, const PolygonSetup* setup, const PreparedSpans* walked) const {
    return draw_with(*this, vertices, count, setup, walked, Input::Any);
}

SetupStatus draw_polygon(const Vertex* vertices, int count, const Texture& tex, const Mapper& mapper, Axis axis,
                         Target& target, RenderStats* stats, Variant variant, const Budget& budget, Input input) {
    if (!mapper.chooses) return Drawer::of(mapper, tex, axis, target, stats, variant).draw(vertices, count, input);
    probe_lap(stats->probe, Phase::Walk);  // what came before the polygon: the caller's loop
    return mapper.chooses(DrawContext{tex, axis, target, stats, nullptr, nullptr, input, nullptr, &budget, variant}, vertices, count);
}

RenderStats render_scene(const Scene& scene, const Texture& tex, const Mapper& mapper, Axis axis, Target& target,
                         Variant variant, Probe* probe, const Watch* watch, const Budget& budget) {
    RenderStats stats;
    stats.probe = probe;
    const Vertex* v = scene.vertices;
    for (int32_t i = 0; i < scene.polygon_count; ++i) {
        if (watch && watch->stops(uint32_t(i), uint32_t(scene.polygon_count), &stats)) break;
        if (watch) watch->drawing(mapper, uint32_t(i));
        draw_polygon(v, scene.polygon_size[i], tex, mapper, axis, target, &stats, variant, budget);
        v += scene.polygon_size[i];
    }
    if (watch) watch->drawn();
    return stats;
}

}  // namespace raster
