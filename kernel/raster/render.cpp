// The draw loop: one setup per polygon, one mapper call per span.
#include "kernel/raster/render.h"

namespace raster {

SetupStatus draw_polygon(const Vertex* vertices, int count, const Texture& tex, const Mapper& mapper, Axis axis,
                         Target& target, RenderStats* stats, Variant variant) {
    PolygonSetup setup;
    SetupStatus status = setup_polygon(vertices, count, &setup);
    if (status == SetupStatus::Degenerate) ++stats->skipped;
    if (status != SetupStatus::Ok) {
        if (status != SetupStatus::Degenerate) ++stats->rejected;
        return status;
    }
    if (!target_supports(target, axis) || !mapper_walks(mapper, axis) || !mapper_accepts(mapper, tex)) {
        ++stats->rejected;
        return status;
    }
    ++stats->polygons;
    EdgeWalker walker(setup, axis, target.clip);
    const SpanContext context{setup, tex, axis, mapper_loop(mapper, variant)};
    Span span;
    while (walker.next(&span)) {
        int32_t stride;
        uint8_t* dst = span_start(target, axis, span, &stride);
        mapper.span(context, span, dst, stride);
        ++stats->spans;
        stats->pixels += uint32_t(span.count);
    }
    return status;
}

RenderStats render_scene(const Scene& scene, const Texture& tex, const Mapper& mapper, Axis axis, Target& target,
                         Variant variant) {
    RenderStats stats;
    const Vertex* v = scene.vertices;
    for (int32_t i = 0; i < scene.polygon_count; ++i) {
        draw_polygon(v, scene.polygon_size[i], tex, mapper, axis, target, &stats, variant);
        v += scene.polygon_size[i];
    }
    return stats;
}

}  // namespace raster
