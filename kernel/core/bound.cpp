// The mappers' bound helpers: the affine planes' lines, the classics' exact setup and drawn lines,
// whether setup takes a polygon, and the unbounded mappers' promise.
#include "kernel/core/bound.h"

#include "kernel/core/spanline.h"

namespace raster {

void affine_lines(const PolygonSetup& s, Axis axis, const Span& span, double* a, double* step) {
    double x = span_centre_x(s, span.x), y = span_centre_y(s, span.y);
    const Plane* plane[2] = {&s.u, &s.v};
    for (int t = 0; t < 2; ++t) {
        a[t] = plane[t]->at(x, y);
        step[t] = (axis == Axis::Rows ? plane[t]->gx : plane[t]->gy) * double(SUBPIXEL_ONE);
    }
}

const PolygonSetup* exact_setup(const BoundContext& c, const Vertex* vertices, int count, PolygonSetup* own, ErrorBound* b) {
    b->draws = true;
    b->footprint = NO_BOUND;
    if (c.whole_only) return nullptr;
    if (c.prepared && c.prepared->status == SetupStatus::Ok) return &c.prepared->setup;
    return setup_polygon(vertices, count, own, PLANES_PERSPECTIVE) == SetupStatus::Ok ? own : nullptr;
}

double drawn_line_bound(const PolygonSetup& s, Axis axis, const Span& span, const double* a, const double* b, double extra) {
    const SpanLine l = span_line(s, axis, span);
    const double last = double(span.count - 1);
    if (!(l.q0 > 0) || !(l.q0 + l.qm * last > 0)) return NO_BOUND;
    double worst = 0;
    for (double k0 = 0; k0 <= last; k0 += BOUND_PIECE) worst = larger(worst, lines_bound(l, a, b, k0, k0 + BOUND_PIECE - 1 < last ? k0 + BOUND_PIECE - 1 : last, extra));
    return worst;
}

bool within_border(double a, double b, double last, double size, double* extra) {
    const double end = a + b * last, lo = a < end ? a : end, hi = larger(a, end);
    if (lo < 0 || hi >= size) *extra = 1;
    return lo >= -1 && hi < size + 1;
}

bool setup_takes(const BoundContext& c, const Vertex* vertices, int count) {
    if (c.prepared) return c.prepared->status == SetupStatus::Ok;
    PolygonSetup s;
    return setup_polygon(vertices, count, &s, PLANES_NONE) == SetupStatus::Ok;
}

ErrorBound unbounded(const BoundContext& c, const Vertex* vertices, int count) {
    ErrorBound b;
    (void)vertices, (void)count;  // its own conversion decides (a sliver our setup finds degenerate may round to a triangle)
    b.draws = mapper_accepts(c.mapper, c.tex);
    b.exact_coverage = c.mapper.guarantee.exact_coverage;
    b.footprint = NO_BOUND;
    return b;
}

}  // namespace raster
