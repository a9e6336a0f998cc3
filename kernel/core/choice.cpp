// The cheapest mapper within the budget, polygon by polygon.
#include "kernel/core/choice.h"

#include "kernel/core/policy.h"

namespace raster {

bool choosable(const Mapper& m) { return !m.chooses && m.bound && m.bound != unbounded; }

Choice choose_mapper(const Budget& budget, const Vertex* vertices, int count, const Texture& tex, const Target& target,
                     PreparedPolygon* prepared) {
    Choice choice;
    // the candidates, (mapper, walker) pairs, cheapest first (insertion sort: a registry's worth,
    // twice); each walker's spans prepared once, the setup shared
    struct Candidate {
        const Mapper* mapper;
        Axis axis;
        double cost;
    } order[2 * MAPPER_LIMIT];
    int n = 0;
    const PreparedPolygon* done = nullptr;
    for (int a = 0; a < 2; ++a) {
        const Axis axis = Axis(a);
        PreparedPolygon& p = prepared[int(axis)];
        p.count = -1, p.status = SetupStatus::Unsupported;
        for (int i = 0; i < MAPPER_COUNT && i < MAPPER_COST_COUNT; ++i) {
            const Mapper& m = MAPPERS[i];
            if (!choosable(m) || !mapper_walks(m, axis) || !mapper_accepts(m, tex) || !mapper_targets(m, target, axis)) continue;
            if (p.status == SetupStatus::Unsupported) {
                prepare_polygon(vertices, count, axis, target.clip, &p, done);
                if (p.status != SetupStatus::Ok) return choice;
                done = &p;
            }
            double c = estimate_cost(MAPPER_COSTS[i], PolygonSize{double(p.count), double(p.pixels)});
            int k = n++;
            for (; k > 0 && order[k - 1].cost > c; --k) order[k] = order[k - 1];
            order[k] = Candidate{&m, axis, c};
        }
    }
    for (int k = 0; k < n; ++k) {
        // asked with the budget: a coarse bound within it will do, and above it the search moves on
        const Candidate& o = order[k];
        BoundContext c{*o.mapper, tex, o.axis, target.clip, budget.max_error < 0 ? NO_BOUND : budget.max_error, &prepared[int(o.axis)]};
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
