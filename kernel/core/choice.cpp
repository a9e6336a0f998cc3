// The cheapest mapper within the budget, polygon by polygon.
#include "kernel/core/choice.h"

#include "kernel/core/policy.h"

namespace raster {

bool choosable(const Mapper& m) { return !m.chooses && m.bound && m.bound != unbounded; }

PolygonSize polygon_size(const PreparedPolygon& walked, Axis axis, const ClipRect& clip) {
    const PolygonSetup& s = walked.setup;
    const bool rows = axis == Axis::Rows;
    double lo = double(rows ? s.min_y : s.min_x) / SUBPIXEL_ONE, hi = double(rows ? s.max_y : s.max_x) / SUBPIXEL_ONE;
    double first = rows ? clip.y0 : clip.x0, end = rows ? clip.y1 : clip.x1;
    lo = lo < first ? first : lo, hi = hi > end ? end : hi;
    return PolygonSize{hi > lo ? hi - lo : 0, double(walked.pixels)};
}

Choice choose_mapper(const Budget& budget, const Vertex* vertices, int count, const Texture& tex, const Target& target,
                     PreparedPolygon* prepared) {
    Choice choice;
    // the candidates, (mapper, walker) pairs, cheapest first (insertion sort: a registry's worth,
    // twice); the polygon set up and walked for the first walker a candidate takes, the other
    // walked only when a candidate of it is asked for its bound
    struct Candidate {
        const Mapper* mapper;
        Axis axis;
        double cost;
    } order[2 * MAPPER_LIMIT];
    int n = 0;
    PreparedPolygon* walked = nullptr;
    for (int a = 0; a < 2; ++a) {
        const Axis axis = Axis(a);
        prepared[a].count = -1, prepared[a].status = SetupStatus::Unsupported;  // not walked
        PolygonSize size{0, 0};
        for (int i = 0; i < MAPPER_COUNT && i < MAPPER_COST_COUNT; ++i) {
            const Mapper& m = MAPPERS[i];
            if (!choosable(m) || !mapper_walks(m, axis) || !mapper_accepts(m, tex) || !mapper_targets(m, target, axis)) continue;
            if (!walked) {
                walked = &prepared[a];
                prepare_polygon(vertices, count, axis, target.clip, walked);
                if (walked->status != SetupStatus::Ok) return choice;
            }
            if (size.pixels == 0 && size.spans == 0) size = polygon_size(*walked, axis, target.clip);
            double c = estimate_cost(MAPPER_COSTS[i], size);
            int k = n++;
            for (; k > 0 && order[k - 1].cost > c; --k) order[k] = order[k - 1];
            order[k] = Candidate{&m, axis, c};
        }
    }
    for (int k = 0; k < n; ++k) {
        const Candidate& o = order[k];
        PreparedPolygon& p = prepared[int(o.axis)];
        if (p.status == SetupStatus::Unsupported) prepare_polygon(vertices, count, o.axis, target.clip, &p, walked);
        // asked with the budget: a coarse bound within it will do, and above it the search moves on
        BoundContext c{*o.mapper, tex, o.axis, target.clip, budget.max_error < 0 ? NO_BOUND : budget.max_error, &p};
        ErrorBound b = o.mapper->bound(c, vertices, count);
        if (budget_allows(budget, b)) {
            choice.mapper = o.mapper, choice.axis = o.axis, choice.bound = b;
            break;
        }
    }
    return choice;
}

ErrorBound auto_bound(const BoundContext& c, const Vertex* vertices, int count) {
    Target kind = surface_kind(c.axis == Axis::Rows ? Surface::Linear : Surface::Planar);
    kind.clip = c.clip;
    PreparedPolygon prepared[2];
    return choose_mapper(DEFAULT_BUDGET, vertices, count, c.tex, kind, prepared).bound;
}

}  // namespace raster
