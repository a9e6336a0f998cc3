// The draw loop: one setup per polygon, one mapper call per span.
#include "kernel/core/render.h"

namespace raster {

namespace {

// Draws the polygon with the mapper: its own driver, or setup, the walker (or the spans of the
// polygon as auto prepared it) and its span function on each span. Counts the polygon.
SetupStatus draw_with(const Vertex* vertices, int count, const Texture& tex, const Mapper& mapper, Axis axis, Target& target,
                      RenderStats* stats, Variant variant, const PreparedPolygon* prepared) {
    Probe* probe = stats->probe;
    const uint32_t pixels_before = stats->pixels;
    if (!mapper_walks(mapper, axis) || !mapper_accepts(mapper, tex) || !mapper_targets(mapper, target, axis)) {
        ++stats->rejected;
        return SetupStatus::Unsupported;
    }
    LoopFn loop = mapper_loop(mapper, variant, target);
    SetupStatus status;
    if (mapper.draw) {
        const bool set_up = prepared && prepared->status == SetupStatus::Ok;
        status = mapper.draw(DrawContext{tex, axis, target, stats, loop, set_up ? &prepared->setup : nullptr}, vertices, count);
    } else {
        auto draw_spans = [&](const PolygonSetup& setup, auto&& next) {
            const SpanContext context{setup, tex, axis, loop};
            probe_lap(probe, Phase::Setup);
            Span span;
            while (next(&span)) {
                int32_t stride;
                uint8_t* dst = span_start(target, axis, span, &stride);
                emit(probe, stats, 1, uint32_t(span.count), [&] { mapper.span(context, span, dst, stride); });
            }
        };
        if (prepared && prepared->status == SetupStatus::Ok) {  // set up with every plane (and maybe walked) already
            status = prepared->status;
            int32_t i = 0;
            const PreparedSpans& w = prepared->walked[int(axis)];
            if (w.count >= 0) draw_spans(prepared->setup, [&](Span* s) { return i < w.count && (*s = w.spans[i++], true); });
            else {
                EdgeWalker walker(prepared->setup, axis, target.clip);
                draw_spans(prepared->setup, [&](Span* s) { return walker.next(s); });
            }
        } else {
            PolygonSetup setup;
            status = setup_polygon(vertices, count, &setup);
            if (status == SetupStatus::Ok) {
                EdgeWalker walker(setup, axis, target.clip);
                draw_spans(setup, [&](Span* s) { return walker.next(s); });
            }
        }
    }
    probe_lap(probe, Phase::Walk);
    if (status == SetupStatus::Ok) {
        ++stats->polygons;
        const int row = int(&mapper - MAPPERS);
        ++stats->mapper_polygons[row];
        stats->mapper_pixels[row] += stats->pixels - pixels_before;
    } else if (status == SetupStatus::Degenerate) ++stats->skipped;
    else ++stats->rejected;
    return status;
}

}  // namespace

SetupStatus draw_polygon(const Vertex* vertices, int count, const Texture& tex, const Mapper& mapper, Axis axis,
                         Target& target, RenderStats* stats, Variant variant, const Budget& budget) {
    probe_lap(stats->probe, Phase::Walk);  // what came before the polygon: the caller's loop
    if (!mapper.chooses) return draw_with(vertices, count, tex, mapper, axis, target, stats, variant, nullptr);
    // auto: the mapper and the walker chosen (the choice counts as setup); where no mapper draws
    // the polygon, exact's setup says why
    PreparedPolygon prepared;
    Choice c = choose_mapper(budget, vertices, count, tex, target, &prepared);
    probe_lap(stats->probe, Phase::Setup);
    if (!c.mapper) {
        const Axis any = target_supports(target, axis) ? axis : Axis::Columns;  // a walker the target takes
        return draw_with(vertices, count, tex, *find_mapper("exact"), any, target, stats, variant, nullptr);
    }
    return draw_with(vertices, count, tex, *c.mapper, c.axis, target, stats, variant, &prepared);
}

RenderStats render_scene(const Scene& scene, const Texture& tex, const Mapper& mapper, Axis axis, Target& target,
                         Variant variant, Probe* probe, const Watch* watch) {
    RenderStats stats;
    stats.probe = probe;
    const Vertex* v = scene.vertices;
    for (int32_t i = 0; i < scene.polygon_count; ++i) {
        if (watch && watch->stops(uint32_t(i), uint32_t(scene.polygon_count), &stats)) break;
        if (watch) watch->drawing(mapper, uint32_t(i));
        draw_polygon(v, scene.polygon_size[i], tex, mapper, axis, target, &stats, variant);
        v += scene.polygon_size[i];
    }
    if (watch) watch->drawn();
    return stats;
}

}  // namespace raster
