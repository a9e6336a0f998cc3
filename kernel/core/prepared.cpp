// Auto's prepared polygon: its setup, its walk and its spread, each once (prepared.h).
#include "kernel/core/prepared.h"

namespace raster {

void prepare_setup(const Vertex* vertices, int count, PreparedPolygon* out, Input input) {
    for (PreparedSpans& w : out->walked) w.count = PreparedSpans::NOT_WALKED, w.pixels = 0, w.first = 0;
    out->status = setup_polygon(vertices, count, &out->setup, PLANES_ALL, input);
    out->spread_known = false;
}

void walk_polygon(PreparedPolygon* p, Axis axis, const ClipRect& clip) {
    PreparedSpans& w = p->walked[int(axis)];
    w.count = 0, w.pixels = 0, w.first = 0;
    if (p->status != SetupStatus::Ok) return;
    EdgeWalker walker(p->setup, axis, clip);
    Span span;
    while (walker.next(&span)) {
        if (w.count == PreparedSpans::MAX_SPANS) {
            w.count = -1;
            return;
        }
        w.spans[w.count++] = span;
        w.pixels += span.count;
    }
}

void prepare_polygon(const Vertex* vertices, int count, Axis axis, const ClipRect& clip, PreparedPolygon* out) {
    prepare_setup(vertices, count, out);
    walk_polygon(out, axis, clip);
}

PolygonSpread& prepared_spread(PreparedPolygon* p, const ClipRect& clip) {
    if (!p->spread_known) polygon_spread(p->setup, clip, &p->spread);
    p->spread_known = true;
    return p->spread;
}

}  // namespace raster
