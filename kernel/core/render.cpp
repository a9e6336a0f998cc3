// The draw loop: one setup per polygon, one mapper call per span.
#include "kernel/core/render.h"

namespace raster {

SetupStatus draw_polygon(const Vertex* vertices, int count, const Texture& tex, const Mapper& named, Axis axis,
                         Target& target, RenderStats* stats, Variant variant, const Budget& budget) {
    Probe* probe = stats->probe;
    probe_lap(probe, Phase::Walk);  // what came before the polygon: the caller's loop
    const Mapper* chosen = &named;
    if (named.chooses) {  // the choice counts as setup; where none draws it, exact's setup says why
        chosen = choose_mapper(budget, vertices, count, tex, axis, target).mapper;
        if (!chosen) chosen = find_mapper("exact");
        probe_lap(probe, Phase::Setup);
    }
    const Mapper& mapper = *chosen;
    const uint32_t pixels_before = stats->pixels;
    if (!mapper_walks(mapper, axis) || !mapper_accepts(mapper, tex) || !mapper_targets(mapper, target, axis)) {
        ++stats->rejected;
        return SetupStatus::Unsupported;
    }
    LoopFn loop = mapper_loop(mapper, variant, target);
    SetupStatus status;
    if (mapper.draw) {
        status = mapper.draw(DrawContext{tex, axis, target, stats, loop}, vertices, count);
    } else {
        PolygonSetup setup;
        status = setup_polygon(vertices, count, &setup);
        if (status == SetupStatus::Ok) {
            EdgeWalker walker(setup, axis, target.clip);
            const SpanContext context{setup, tex, axis, loop};
            probe_lap(probe, Phase::Setup);
            Span span;
            while (walker.next(&span)) {
                int32_t stride;
                uint8_t* dst = span_start(target, axis, span, &stride);
                emit(probe, stats, 1, uint32_t(span.count), [&] { mapper.span(context, span, dst, stride); });
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

RenderStats render_scene(const Scene& scene, const Texture& tex, const Mapper& mapper, Axis axis, Target& target,
                         Variant variant, Probe* probe) {
    RenderStats stats;
    stats.probe = probe;
    const Vertex* v = scene.vertices;
    for (int32_t i = 0; i < scene.polygon_count; ++i) {
        draw_polygon(v, scene.polygon_size[i], tex, mapper, axis, target, &stats, variant);
        v += scene.polygon_size[i];
    }
    return stats;
}

}  // namespace raster
