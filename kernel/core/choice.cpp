// The cheapest mapper within the budget, polygon by polygon.
#include "kernel/core/choice.h"

#include "kernel/core/policy.h"

namespace raster {

namespace {

double clamp(double t, double lo, double hi) { return t < lo ? lo : t > hi ? hi : t; }

}  // namespace

PolygonSize estimate_size(const Vertex* vertices, int count, Axis axis, const ClipRect& clip) {
    if (count < 3) return {0, 0};
    double x0 = vertices[0].x.to_double(), x1 = x0, y0 = vertices[0].y.to_double(), y1 = y0, area2 = 0;
    for (int i = 0; i < count; ++i) {
        double x = vertices[i].x.to_double(), y = vertices[i].y.to_double();
        const Vertex& n = vertices[i + 1 < count ? i + 1 : 0];
        area2 += x * n.y.to_double() - n.x.to_double() * y;
        x0 = x < x0 ? x : x0, x1 = x > x1 ? x : x1, y0 = y < y0 ? y : y0, y1 = y > y1 ? y : y1;
    }
    double box = (x1 - x0) * (y1 - y0);
    if (box <= 0) return {0, 0};
    // the clip takes the same share of the area as of the bounding box: an estimate
    double w = clamp(x1, clip.x0, clip.x1) - clamp(x0, clip.x0, clip.x1), h = clamp(y1, clip.y0, clip.y1) - clamp(y0, clip.y0, clip.y1);
    double pixels = (area2 < 0 ? -area2 : area2) / 2 * (w * h / box);
    return {axis == Axis::Rows ? h : w, pixels};
}

bool choosable(const Mapper& m) { return !m.chooses && m.bound && m.bound != unbounded; }

Choice choose_mapper(const Budget& budget, const Vertex* vertices, int count, const Texture& tex, Axis axis, const Target& target) {
    // the candidates, cheapest first (insertion sort: a registry's worth)
    const Mapper* order[MAPPER_LIMIT];
    double cost[MAPPER_LIMIT];
    int n = 0;
    PolygonSize size = estimate_size(vertices, count, axis, target.clip);
    for (int i = 0; i < MAPPER_COUNT && i < MAPPER_COST_COUNT; ++i) {
        const Mapper& m = MAPPERS[i];
        if (!choosable(m) || !mapper_walks(m, axis) || !mapper_accepts(m, tex) || !mapper_targets(m, target, axis)) continue;
        double c = estimate_cost(MAPPER_COSTS[i], size);
        int k = n++;
        for (; k > 0 && cost[k - 1] > c; --k) order[k] = order[k - 1], cost[k] = cost[k - 1];
        order[k] = &m, cost[k] = c;
    }
    Choice choice;
    for (int k = 0; k < n; ++k) {
        // asked with the budget: a coarse bound within it will do, and above it the search moves on
        ErrorBound b = order[k]->bound(BoundContext{*order[k], tex, axis, target.clip, budget.max_error < 0 ? NO_BOUND : budget.max_error},
                                       vertices, count);
        if (!b.draws) continue;
        if (budget_allows(budget, b)) {
            choice.mapper = order[k], choice.bound = b;
            break;
        }
    }
    return choice;
}

ErrorBound auto_bound(const BoundContext& c, const Vertex* vertices, int count) {
    Target kind = surface_kind(c.axis == Axis::Rows ? Surface::Linear : Surface::Planar);
    kind.clip = c.clip;
    return choose_mapper(DEFAULT_BUDGET, vertices, count, c.tex, c.axis, kind).bound;
}

}  // namespace raster
