// The cheapest mapper within the budget, polygon by polygon.
#include "kernel/mappers/auto/choice.h"

#include "kernel/core/envelope.h"
#include "kernel/core/footprint.h"
#include "kernel/core/policy.h"
#include "kernel/mappers/fastsubdiv.h"

namespace raster {

bool choosable(const Mapper& m) { return !m.is_auto && !m.own_walker && m.bound && m.bound != unbounded; }
bool drawn_by_auto(const Mapper& m) { return choosable(m) || m.auto_role == AutoRole::Oriented; }

const Mapper& auto_fallback() {
    int row = 0;
    while (row < MAPPER_COUNT - 1 && MAPPERS[row].auto_role != AutoRole::Fallback) ++row;
    return MAPPERS[row];
}

namespace {

// fast_oriented_guard on a polygon, the object's check asked of its own corners' |u| and |v|.
double polygon_guard(const PolygonSetup& s, const Vertex* vertices, int count, const Texture& tex, const ClipRect& clip, Axis axis) {
    double most = 0;
    for (int i = 0; i < count; ++i) most = larger(most, larger(magnitude(vertices[i].u), magnitude(vertices[i].v)));
    return tex.wrap == Wrap::Repeat && fast_oriented_guard_takes(most, clip) ? fast_oriented_guard(s, clip, axis, most) : 0;
}

// Twice the area the setup would find, from the corners (the shoelace, exact in a double for
// coordinates within setup's range: repeated corners add nothing): unchosen_mapper's and the
// oriented path's gate.
double corner_area2(const Vertex* vertices, int count) {
    double area2 = 0;
    if (count == 3) {
        const Vertex &a = vertices[0], &b = vertices[1], &c = vertices[2];
        area2 = double(b.x.raw - a.x.raw) * double(c.y.raw - a.y.raw) - double(c.x.raw - a.x.raw) * double(b.y.raw - a.y.raw);
    } else {
        for (int i = 0; i < count; ++i) {
            const Vertex &a = vertices[i], &b = vertices[i + 1 < count ? i + 1 : 0];
            area2 += double(a.x.raw) * double(b.y.raw) - double(b.x.raw) * double(a.y.raw);
        }
    }
    return magnitude(area2);
}

}  // namespace

double affine_deviation(const PolygonSetup& s, const ClipRect& clip) {
    if (s.area2 < 2 * AFFINE_DEVIATION_PIXELS * SUBPIXEL_ONE * SUBPIXEL_ONE) return 0;
    // at the corners' mean (relative to the reference vertex), or, reaching outside the clip, at the
    // centre of the pixel in the middle of its box inside the clip where the polygon covers it
    double x = 0, y = 0;
    if (box_in_clip(s, clip)) {
        for (int i = 0; i < s.edge_count; ++i) x += double(s.edges[i].px - s.ref_x), y += double(s.edges[i].py - s.ref_y);
        x /= s.edge_count, y /= s.edge_count;
    } else {
        auto middle = [](int64_t lo, int64_t hi, int32_t first, int32_t end) {  // a pixel, or first - 1 where none
            const int64_t l = int64_t(first) * SUBPIXEL_ONE, h = int64_t(end) * SUBPIXEL_ONE;
            lo = lo < l ? l : lo, hi = hi > h ? h : hi;
            return hi > lo ? int32_t(((lo + hi) / 2) >> SUBPIXEL_BITS) : first - 1;
        };
        const int32_t px = middle(s.min_x, s.max_x, clip.x0, clip.x1), py = middle(s.min_y, s.max_y, clip.y0, clip.y1);
        if (px < clip.x0 || py < clip.y0 || px >= clip.x1 || py >= clip.y1 || !covers(s, px, py)) return 0;
        x = double(int64_t(px) * SUBPIXEL_ONE + SUBPIXEL_HALF - s.ref_x), y = double(int64_t(py) * SUBPIXEL_ONE + SUBPIXEL_HALF - s.ref_y);
    }
    const double q = s.q.at(x, y);
    if (!(q > 0)) return 0;
    const double du = magnitude(s.u.at(x, y) - s.pu.at(x, y) / q), dv = magnitude(s.v.at(x, y) - s.pv.at(x, y) / q);
    return larger(du, dv) / larger(1.0, texel_footprint(s, x, y));
}

void polygon_sizes(const PolygonSetup& s, const ClipRect& clip, PolygonSize size[2]) {
    const double one = double(SUBPIXEL_ONE);
    // (the box's corners are vertices': 32 bits)
    const double w = double(box_inside(int32_t(s.min_x), int32_t(s.max_x), clip.x0, clip.x1)) / one;
    const double h = double(box_inside(int32_t(s.min_y), int32_t(s.max_y), clip.y0, clip.y1)) / one;
    const double area = double(s.area2) / (2 * one * one), pixels = area < w * h ? area : w * h;
    size[int(Axis::Rows)] = PolygonSize{h, pixels};
    size[int(Axis::Columns)] = PolygonSize{w, pixels};
}

namespace {

// The budget's lists where prepared (the one for the texture and the target, built where it is not
// yet), else one built into `room`.
const CandidateList& candidates(const Texture& tex, const Target& target, const Budget& budget, ListRoom* room) {
    // (mapper_accepts' needs: the copies, and the wrap for NEED_POW2_REPEAT)
    const bool whole256 = texture_aligned256(tex), any_wrap = texture_tiled256_any_wrap(tex), repeat = tex.wrap == Wrap::Repeat;
    const bool doubled = tex.doubled != nullptr;
    const bool exact_coverage = budget.exact_coverage, no_error = budget.max_error == 0;
    const int kind = (tex.bordered ? 1 : 0) | (whole256 ? 2 : 0) | (target.planar ? 4 : 0) | (exact_coverage ? 8 : 0) | (no_error ? 16 : 0) |
                    (doubled ? 32 : 0) | (any_wrap ? 64 : 0) | (repeat ? 128 : 0);
    CandidateList& c = budget.lists ? budget.lists->lists[kind] : room->list;
    const CostModel& model = cost_model(budget.target);
    if (budget.lists && c.built && c.priced_for == budget.target) return c;
    c = CandidateList{};
    c.priced_for = budget.target;
    for (int a = 0; a < 2; ++a)
        for (int i = 0; i < MAPPER_COUNT && i < MAPPER_COST_COUNT; ++i) {
            const Mapper& m = MAPPERS[i];
            if (!choosable(m) || !mapper_walks(m, Axis(a)) || !mapper_accepts(m, tex) || !mapper_targets(m, target, Axis(a))) continue;
            if ((exact_coverage && !m.guarantee.exact_coverage) || (no_error && m.guarantee.max_error != 0)) continue;
            // insertion by the cost per pixel, rows not measured last (stable: ties keep rows first,
            // registry order)
            const CostRow cost = proven_cost(m, cost_row(model.rows[i]), model.proof_scale);
            auto key = [](const CostRow& r) { return r.polygon < 1e29 ? r.pixel : 1e300; };
            int k = c.count++;
            for (; k > 0 && key(c.cost[k - 1]) > key(cost); --k)
                c.row[k] = c.row[k - 1], c.axis[k] = c.axis[k - 1], c.cost[k] = c.cost[k - 1], c.walks[k] = c.walks[k - 1], c.spans[k] = c.spans[k - 1];
            c.row[k] = int16_t(i), c.axis[k] = Axis(a), c.cost[k] = cost, c.walks[k] = bound_walks(m), c.spans[k] = proven_by_spans(m);
        }
    for (int k = 0; k < c.count; ++k)
        for (int two = 0; two < 2; ++two)
            if (MAPPERS[c.row[k]].auto_role == (two ? AutoRole::Adaptive2 : AutoRole::Adaptive1)) c.adaptive[two][int(c.axis[k])] = k;
    for (int i = 0; i < MAPPER_COUNT && i < MAPPER_COST_COUNT; ++i)
        if (MAPPERS[i].auto_role == AutoRole::Oriented && mapper_accepts(MAPPERS[i], tex) && model.rows[i].polygon >= 0) c.oriented_row = i;
    for (int k = 0; k < c.count; ++k)
        if (MAPPERS[c.row[k]].auto_role == AutoRole::ConstantDepth && c.cost[k].polygon < 1e29) c.constant_depth[int(c.axis[k])] = k;
    for (int k = c.count - 1; k >= 0; --k) {
        const bool last = k == c.count - 1;
        c.least_polygon[k] = last || c.cost[k].polygon < c.least_polygon[k + 1] ? c.cost[k].polygon : c.least_polygon[k + 1];
        c.least_span[k] = last || c.cost[k].span < c.least_span[k + 1] ? c.cost[k].span : c.least_span[k + 1];
        c.least_pixel[k] = last || c.cost[k].pixel < c.least_pixel[k + 1] ? c.cost[k].pixel : c.least_pixel[k + 1];
    }
    for (int k = 0; k < c.count && c.certain < 0; ++k) {
        const Mapper& m = MAPPERS[c.row[k]];
        if (m.guarantee.max_error == 0 && m.guarantee.exact_coverage && whole_proof_cost(m) == 0 && !c.walks[k]) c.certain = k;
    }
    // (the certain one's setup may be the cheaper: only its span and pixel costs are weighed, see
    // ENVELOPE_SETUP_ALLOWANCE; one cheaper a pixel: up to the size where it undercuts)
    for (int j = 0; j < c.count; ++j) {
        if (!MAPPERS[c.row[j]].enveloped) continue;
        if (c.enveloped_count++ == 0)
            c.enveloped_first = j, c.envelope_cheapest = true, c.envelope_pixels = 1e300, c.envelope_lines = double(ENVELOPE_REACH + 1);
        const CostRow own = cost_row(model.rows[c.row[j]]);  // proven for nothing
        for (int k = 0; k < c.count; ++k) {
            if (MAPPERS[c.row[k]].enveloped) continue;
            const CostRow& other = c.cost[k];
            const bool certain = c.certain >= 0 && c.row[k] == c.row[c.certain];
            // what the other costs more on a triangle of one line to the most lines the envelope
            // takes (the guards' ENVELOPE_REACH + 1, or fewer), less the pixels: at least 0; where it
            // costs less a line, the lines limited where needed so that they take at most half of
            // what its setup costs more; and where it costs less a pixel, the most pixels up to
            // which what it costs more for the rest is not made up
            const double polygon = other.polygon + (certain ? ENVELOPE_SETUP_ALLOWANCE * model.proof_scale : 0) - own.polygon;
            const double span = other.span - own.span;
            if (span < 0 && polygon + span * c.envelope_lines < 0 && polygon > 0) c.envelope_lines = polygon / (2 * -span);
            const double fixed = polygon + (span < 0 ? span * c.envelope_lines : span);
            if (fixed < 0 || c.envelope_lines < 1) c.envelope_cheapest = false;
            else if (other.pixel < own.pixel) {
                const double pixels = fixed / (own.pixel - other.pixel);
                c.envelope_pixels = pixels < c.envelope_pixels ? pixels : c.envelope_pixels;
            }
        }
    }
    if (c.certain >= 0) {  // the plan's part that depends on the candidates alone (plan_auto)
        AutoPlan& plan = c.plan;
        const int row = c.row[c.certain];
        plan.certain = &MAPPERS[row];
        plan.certain_row = c.cost[c.certain];
        bool others = false;
        for (int k = 0; k < c.count; ++k) {
            const CostRow& cost = c.cost[k];
            if (c.row[k] == row) {
                plan.certain_axes[plan.certain_walkers++] = c.axis[k];
            } else if (!others) {
                plan.others = cost, others = true;
            } else {
                plan.others.polygon = cost.polygon < plan.others.polygon ? cost.polygon : plan.others.polygon;
                plan.others.span = cost.span < plan.others.span ? cost.span : plan.others.span;
                plan.others.pixel = cost.pixel < plan.others.pixel ? cost.pixel : plan.others.pixel;
            }
        }
        plan.sole = !others;
    }
    c.built = true;
    return c;
}

}  // namespace

void prepare_choice(const Budget& budget, const Texture& tex) {
    if (!budget.lists) return;
    ListRoom room;
    candidates(tex, surface_kind(Surface::Linear), budget, &room);
    candidates(tex, surface_kind(Surface::Planar), budget, &room);
}

Choice choose_mapper(const Budget& budget, const Vertex* vertices, int count, const Texture& tex, const Target& target,
                     PreparedPolygon* prepared, Input input, Probe* probe, bool set_up) {
    Choice choice;
    for (PreparedSpans& w : prepared->walked) w.count = PreparedSpans::NOT_WALKED;
    if (!set_up) prepared->status = SetupStatus::Unsupported;
    ListRoom room;
    const CandidateList& list = candidates(tex, target, budget, &room);
    if (list.count == 0) return choice;
    const CostModel& model = cost_model(budget.target);
    // set up once, for both walkers (the spread and the spans come when a bound asks for them)
    if (set_up) prepared->spread_known = false;
    else prepare_setup(vertices, count, prepared, input);
    probe_lap(probe, Phase::Setup);
    if (prepared->status != SetupStatus::Ok) return choice;
    PolygonSize size[2];
    polygon_sizes(prepared->setup, target.clip, size);
    // the estimates with the first proofs (a mapper whose bound walks: span by span already), as
    // whole instructions for the search below (integer compares: it scans the candidates once for
    // each one it asks); NOT_LIVE: asked already, or not priced
    constexpr int32_t NOT_LIVE = 0x7FFFFFFF;
    // (to the nearest whole number by adding 1.5 * 2^52, which leaves it in the sum's low bits:
    // int32_t() on the x87 would switch the rounding mode twice a candidate)
    auto price_of = [](double c) {
        if (!(c < 2e9)) return NOT_LIVE;
        if (!(c > -2e9)) return -NOT_LIVE;
        const double shifted = c + 6755399441055744.0;
        uint64_t bits;
        __builtin_memcpy(&bits, &shifted, sizeof bits);
        return int32_t(uint32_t(bits));
    };
    // (written as each is priced, the certain one first: nothing reads a candidate not yet priced,
    // so the list is never filled whole)
    double cost[2 * MAPPER_LIMIT];
    int32_t price[2 * MAPPER_LIMIT];
    const bool rows_fewer = size[0].spans < size[1].spans;
    const double fewest_spans = size[rows_fewer ? 0 : 1].spans, most_spans = size[rows_fewer ? 1 : 0].spans, pixels = size[0].pixels;
    auto least_cost = [&](int k) {  // what candidates k on cost at least (a fitted cost below 0 a span: least where the spans are most)
        const double a_span = list.least_span[k];
        return list.least_polygon[k] + a_span * (a_span < 0 ? most_spans : fewest_spans) + list.least_pixel[k] * pixels;
    };
    // the certain one at once (it always holds: no candidate dearer than it is ever asked), the
    // others in the list's order as the search needs them: candidates 0..priced-1, and the least
    // any of the rest could cost (next_least)
    int priced = 0;
    const int certain = list.certain;
    if (certain >= 0) {
        cost[certain] = estimate_cost(list.cost[certain], size[int(list.axis[certain])]);
        price[certain] = price_of(cost[certain]);
    }
    double next_least = least_cost(0);
    const bool* walks = list.walks;
    // the cheapest candidate priced and not yet asked whose price is below `ceiling` (ties: the
    // earlier), or -1
    auto cheapest = [&](int32_t ceiling) {
        int best = -1;
        for (int k = 0; k < priced; ++k)
            if (price[k] < ceiling) best = k, ceiling = price[k];
        if (certain >= priced && price[certain] < ceiling) best = certain;
        return best;
    };
    // the cheapest not yet asked of all: priced further while one not yet priced could cost less
    auto next = [&]() {
        int k = cheapest(NOT_LIVE);
        double best = k >= 0 ? double(price[k]) + 1 : 1e300;
        while (priced < list.count && next_least < best) {
            if (priced != certain) {
                cost[priced] = estimate_cost(list.cost[priced], size[int(list.axis[priced])]);
                price[priced] = price_of(cost[priced]);
                if (price[priced] < (k >= 0 ? price[k] : NOT_LIVE)) k = priced, best = double(price[k]) + 1;
            }
            ++priced;
            next_least = priced < list.count ? least_cost(priced) : 1e300;
        }
        return k;
    };
    auto ask = [&](int k, bool whole_only) {
        price[k] = NOT_LIVE;
        const Mapper& m = MAPPERS[list.row[k]];
        BoundContext c{m, tex, list.axis[k], target.clip, budget.max_error < 0 ? NO_BOUND : budget.max_error, prepared, whole_only};
        ErrorBound b = m.bound(c, vertices, count);
        if (!budget_allows(budget, b)) return false;
        choice.mapper = &m, choice.axis = list.axis[k], choice.bound = b, choice.by_spans = !whole_only;
        return true;
    };
    // The oriented candidate (ORIENTED_GATE; docs/auto.md, "The rule", 4): from a budget of 1,
    // fast-adaptive-B (B = 1 below two, else 2) along fast-oriented-B's walker, proven within B by
    // fast_oriented_guard, else its certificate or its whole bound from the spread; priced by
    // fast-oriented-1's row (B = 1: drawn by it) or fast-adaptive-2's. Or fast-constant-depth along
    // that walker, cheaper by its row, where the same proof bounds its chords (the spread's: unsearched).
    // Taken where its price is within the gate of the least any candidate could cost, or
    // affine_deviation is above the budget; else the price the search must undercut.
    const Mapper* oriented = nullptr;
    Axis oriented_walker = Axis::Rows;
    int32_t oriented_price = NOT_LIVE;
    ErrorBound oriented_bound{true, true, 1};
    bool deferred = false;  // its proof put off until the search reaches its least price
    double estimate = 1e300;  // the proven pick's
    int ruled_out = -1;       // (affine_deviation above the budget: asked once, where needed)
    const double gate = ORIENTED_GATE * model.proof_scale;
    const PolygonSetup& s = prepared->setup;
    // (a polygon at one depth, Q the same everywhere: the affine planes are its mapping, no affine
    // stepping ruled out, and the oriented candidate, past the gate, not asked)
    const bool one_depth = s.q.gx == 0 && s.q.gy == 0;
    auto affine_ruled_out = [&] {
        return ruled_out < 0 ? (ruled_out = !one_depth && affine_deviation(s, target.clip) > budget.max_error) : ruled_out;
    };
    const int two = budget.max_error >= 2;
    const double within = two ? 2 : 1;
    const bool asked = budget.max_error >= 1 && list.oriented_row >= 0;
    if (asked) oriented_walker = target.planar ? Axis::Columns : oriented_axis(s, size, fast_adaptive_room(within));
    const int a = asked ? list.adaptive[two][int(oriented_walker)] : -1, d = asked ? list.constant_depth[int(oriented_walker)] : -1;
    const bool inside = asked && box_in_clip(s, target.clip);
    // fast_oriented_guard first, then the certificate inside the clip, else the whole bound from the
    // spread inside (the certificate computed where the guard fails); fast-constant-depth's chords
    // from the same proof
    auto prove = [&] {
        const Mapper& m = MAPPERS[a >= 0 ? list.row[a] : 0];
        const double guard = a >= 0 ? polygon_guard(s, vertices, count, tex, target.clip, oriented_walker) : 0;
        FastCertificate certificate;
        if (guard <= 0 && inside) certificate = fast_certificate(s, target.clip, tex);
        auto proven = [&] {
            if (guard > 0) return true;
            if (inside) return two ? fast_adaptive_certain<8>(certificate, s, oriented_walker) : fast_adaptive_certain<4>(certificate, s, oriented_walker);
            const ErrorBound b = m.bound(BoundContext{m, tex, oriented_walker, target.clip, within, prepared, true}, vertices, count);
            return b.draws && b.footprint <= within;
        };
        if (a >= 0 && proven()) {
            oriented = two ? &m : &MAPPERS[list.oriented_row];
            oriented_bound.footprint = within;
            estimate = estimate_cost(model.rows[oriented - MAPPERS], size[int(oriented_walker)]);
        }
        if (d >= 0 && guard > 0) {
            const double priced_at = estimate_cost(model.rows[list.row[d]], size[int(oriented_walker)]);
            if (priced_at < estimate && fast_constant_within(s, target.clip, oriented_walker, guard, fast_adaptive_room(budget.max_error)))
                oriented = &MAPPERS[list.row[d]], oriented_bound.footprint = budget.max_error, estimate = priced_at;
        } else if (d >= 0) {
            const bool by_spread = !inside && oriented;
            const FastCertificate chords = by_spread ? fast_certificate(prepared_spread(prepared, target.clip)) : certificate;
            if (chords.holds) {
                const Mapper& c = MAPPERS[list.row[d]];
                const double priced_at = estimate_cost(model.rows[list.row[d]], size[int(oriented_walker)]);
                const double bound = priced_at < estimate && (!by_spread || priced_at <= least_cost(0) + gate || affine_ruled_out())
                                         ? fast_chords_bound(chords, s, oriented_walker, FAST_SPAN_LONG)
                                         : NO_BOUND;
                if (bound <= budget.max_error) oriented = &c, oriented_bound.footprint = bound, estimate = priced_at;
            }
        }
        oriented_price = oriented ? price_of(estimate) : NOT_LIVE;
    };
    if (a >= 0 || d >= 0) {
        // the least either pick could cost, before any proof: past the gate (no affine stepping ruled
        // out), the price the search must undercut, the pick proven where the search reaches it
        const PolygonSize& along = size[int(oriented_walker)];
        const double pick = a >= 0 ? estimate_cost(model.rows[two ? list.row[a] : list.oriented_row], along) : 1e300;
        const double pick_constant = d >= 0 ? estimate_cost(model.rows[list.row[d]], along) : 1e300;
        const double least_pick = pick < pick_constant ? pick : pick_constant;
        if (least_pick <= least_cost(0) + gate || affine_ruled_out()) {
            prove();
            if (oriented && (estimate <= least_cost(0) + gate || affine_ruled_out())) return Choice{oriented, oriented_walker, oriented_bound, false};
        } else if (!one_depth) {
            deferred = true, oriented_price = price_of(least_pick);
        }
    }
    // the cheapest proven by the whole polygon at once (from its vertices: cheap; exact always is),
    // below the oriented candidate's price; then the cheaper ones proven span by span, by their cost
    // with the proof's, as long as that is below the first's (or the oriented one's)
    int before[2 * MAPPER_LIMIT], n = 0;
    int32_t ceiling = oriented_price;
    for (int k = next(); k >= 0; k = next()) {
        if (price[k] >= oriented_price && deferred) deferred = false, prove(), ceiling = oriented_price;
        if (price[k] >= oriented_price) break;
        if (walks[k]) {
            price[k] = NOT_LIVE;
        } else if (ask(k, true)) {
            ceiling = price_of(cost[k]);
            break;
        }
        if (list.spans[k]) before[n++] = k;
    }
    for (int i = 0; i < n; ++i) {
        const int k = before[i];
        price[k] = price_of(walks[k] ? cost[k] : cost[k] + BOUND_SPAN_COST * model.proof_scale * size[int(list.axis[k])].spans);
    }
    if (deferred && !choice.mapper) deferred = false, prove(), ceiling = oriented_price;
    for (int k; n > 0 && (k = cheapest(ceiling)) >= 0;)
        if (ask(k, false)) break;
    return choice.mapper || !oriented ? choice : Choice{oriented, oriented_walker, oriented_bound, false};
}

double corner_footprint(const Vertex* v) {
    const double xb = double(v[1].x.raw - v[0].x.raw), yb = double(v[1].y.raw - v[0].y.raw);
    const double xc = double(v[2].x.raw - v[0].x.raw), yc = double(v[2].y.raw - v[0].y.raw);
    const double d = xb * yc - xc * yb;
    if (d == 0) return 1e300;
    // the planes as setup_polygon puts them through these three corners
    auto plane = [&](double a, double b, double c) { return plane_through(a, b, c, xb, yb, xc, yc, d); };
    const Plane q = plane(1 / v[0].w, 1 / v[1].w, 1 / v[2].w);
    const Plane pu = plane(v[0].u / v[0].w, v[1].u / v[1].w, v[2].u / v[2].w);
    const Plane pv = plane(v[0].v / v[0].w, v[1].v / v[1].w, v[2].v / v[2].w);
    return texel_footprint(q, pu, pv, 0, 0);
}

void plan_auto(const Budget& budget, const Texture& tex, const Target& target, double envelope_footprint, AutoPlan* plan) {
    ListRoom room;
    const CandidateList& list = candidates(tex, target, budget, &room);
    AutoPlan& p = *plan;
    p = list.plan;
    p.choice_cost = CHOICE_COST * cost_model(budget.target).proof_scale;
    // below a budget of 1, every bound but the certain one's is at least 1 / max(1, F) (a rounding
    // of some texel, over the footprint F where it is least): within it only where F >= 1 / budget
    p.exact_below = budget.max_error > 0 && budget.max_error < 1 ? 1 / budget.max_error : 0;
    // (the estimates' difference less CHOICE_COST is at least (polygon - CHOICE_COST) + (span at
    // most lines, where the certain one's is the less) + pixel P: above 0 where P > P0 below, the
    // pixels one more for the roundings)
    p.choosing_pays_above2 = INT64_MAX;
    // (each term of the estimates' difference less CHOICE_COST taken at its largest over a box of
    // W x H pixels: the certain one's lines along its walker, the others' at most the box's longer
    // side where a fitted cost a line is below 0, the pixels at most W H)
    p.small_box = SmallBox{-1, 0, 0, 0, 0};
    if (p.certain && !p.sole) {
        SmallBox& b = p.small_box;
        b = SmallBox{0, p.certain_row.polygon - p.others.polygon - p.choice_cost, larger(p.certain_row.span, 0.0),
                     larger(-p.others.span, 0.0), larger(p.certain_row.pixel - p.others.pixel, 0.0)};
        // (the largest box, W H subpixels squared, where the test can pass: its other terms 0)
        const double one = double(SUBPIXEL_ONE), most = b.pixel > 0 ? (-1 - b.fixed) / b.pixel * one * one : 1e300;
        b.most_box = b.fixed > -1 ? -1 : most < 4e18 ? int64_t(most) : INT64_MAX;
    }
    const CostRow &mine = p.certain_row, &least = p.others;
    if (p.certain && !p.sole && p.exact_below == 0 && mine.pixel > least.pixel) {
        const double most_lines = double(larger(target.clip.x1 - target.clip.x0, target.clip.y1 - target.clip.y0));
        const double span = mine.span < least.span ? (mine.span - least.span) * most_lines : 0;
        const double p0 = (p.choice_cost - (mine.polygon - least.polygon) - span) / (mine.pixel - least.pixel) + 1;
        const double one = double(SUBPIXEL_ONE), above2 = 2 * (p0 > 0 ? p0 : 0) * one * one;
        if (above2 < 1e18) p.choosing_pays_above2 = int64_t(above2);
    }
    if (list.enveloped_count == 1 && list.envelope_cheapest && budget_allows(budget, ErrorBound{true, true, envelope_footprint})) {
        p.enveloped = &MAPPERS[list.row[list.enveloped_first]];
        p.enveloped_axis = list.axis[list.enveloped_first];
        const double one = double(SUBPIXEL_ONE);
        p.enveloped_area2 = list.envelope_pixels < 1e9 ? int64_t(2 * list.envelope_pixels * one * one) : INT64_MAX;
        p.enveloped_extent = int32_t(list.envelope_lines * one);  // (at most ENVELOPE_REACH + 1 pixels)
    }
}

OrientedPlan plan_oriented(const Budget& budget, const Texture& tex, const Target& target, double texel_most) {
    ListRoom room;
    const CandidateList& list = candidates(tex, target, budget, &room);
    OrientedPlan plan{};
    // where choose_mapper would ask the oriented candidate first, with fast-adaptive-B a candidate
    // along each walker fast-oriented-B may pick
    const int two = budget.max_error >= 2, a = list.adaptive[two][int(Axis::Columns)];
    const bool walkers = a >= 0 && (target.planar || list.adaptive[two][int(Axis::Rows)] >= 0);
    if (!oriented_plan_wanted(budget) || list.oriented_row < 0 || !walkers || tex.wrap != Wrap::Repeat || !fast_oriented_guard_takes(texel_most, target.clip))
        return plan;
    const CostModel& model = cost_model(budget.target);
    plan.oriented = &MAPPERS[two ? list.row[a] : list.oriented_row];
    plan.oriented_row = plan.constant_row = cost_row(model.rows[plan.oriented - MAPPERS]);
    plan.walker_room = fast_adaptive_room(two ? 2 : 1);
    const int d = list.constant_depth[int(Axis::Columns)];
    if (d >= 0 && (target.planar || list.constant_depth[int(Axis::Rows)] >= 0)) {
        plan.constant = &MAPPERS[list.row[d]];
        plan.constant_row = cost_row(model.rows[list.row[d]]);
    }
    plan.room = fast_adaptive_room(budget.max_error);
    plan.least = CostRow{list.least_polygon[0], list.least_span[0], list.least_pixel[0]};
    plan.gate = ORIENTED_GATE * model.proof_scale;
    plan.budget = budget.max_error;
    plan.texel_most = texel_most;
    return plan;
}

const Mapper* unchosen_mapper(const AutoPlan& plan, const Vertex* vertices, int count, const ClipRect& clip, Axis* axis, const CornerBox* given) {
    if (!plan.certain) return nullptr;
    *axis = plan.certain_axes[0];
    if (plan.sole && plan.certain_walkers == 1) return plan.certain;
    // the box the setup would find, and its sides inside the clip (subpixels)
    const CornerBox corners = given ? *given : corner_box(vertices, count);
    const int32_t x_lo = corners.x_lo, x_hi = corners.x_hi, y_lo = corners.y_lo, y_hi = corners.y_hi;
    const int32_t width = box_inside(x_lo, x_hi, clip.x0, clip.x1), height = box_inside(y_lo, y_hi, clip.y0, clip.y1);
    const double one = double(SUBPIXEL_ONE), span = plan.certain_row.span;
    double lines[2];
    // its lines along each walker, and its walker: the estimates on its walkers differ only in their lines
    auto walker = [&] [[gnu::always_inline]] {
        lines[int(Axis::Rows)] = double(height) / one;
        lines[int(Axis::Columns)] = double(width) / one;
        if (plan.certain_walkers == 2 && span * lines[int(plan.certain_axes[1])] < span * lines[int(*axis)]) *axis = plan.certain_axes[1];
    };
    // a box so small that no polygon in it could pay for choosing (AutoPlan::small_box)
    const SmallBox& small = plan.small_box;
    if (!plan.sole && int64_t(width) * height <= small.most_box) {
        walker();
        const double most = larger(lines[0], lines[1]);
        if (small.fixed + small.line * lines[int(*axis)] + small.other_line * most + small.pixel * lines[0] * lines[1] <= -1) return plan.certain;
    }
    const double area2 = plan.sole ? 0 : corner_area2(vertices, count);
    if (area2 > double(plan.choosing_pays_above2) && 2 * int64_t(width) * height > plan.choosing_pays_above2) return nullptr;
    walker();
    if (plan.sole) return plan.certain;
    const double area = area2 / (2 * one * one), box = lines[0] * lines[1], pixels = area < box ? area : box;
    const double best = plan.certain_row.polygon + span * lines[int(*axis)] + plan.certain_row.pixel * pixels;
    const bool rows_fewer = lines[0] < lines[1];
    const double others_lines = lines[(plan.others.span < 0) == rows_fewer ? 1 : 0];  // (a fitted cost below 0: where they are most)
    const double least = plan.others.polygon + plan.others.span * others_lines + plan.others.pixel * pixels;
    if (best <= least + plan.choice_cost) return plan.certain;
    // (only where the polygon lies inside the clip: its first corner is then among the pixels
    // drawn, not off the screen where a wall comes nearest)
    const int32_t one_px = SUBPIXEL_ONE;
    const bool in_clip = x_lo >= clip.x0 * one_px && x_hi <= clip.x1 * one_px && y_lo >= clip.y0 * one_px && y_hi <= clip.y1 * one_px;
    return in_clip && plan.exact_below > 0 && corner_footprint(vertices) < plan.exact_below ? plan.certain : nullptr;
}

AutoObjectKey auto_object_key(const Budget& budget, const Texture& tex, const Target& target, Variant variant, double texel_most) {
    return AutoObjectKey{&tex, tex, budget.max_error, texel_most, target.clip, budget.exact_coverage, target.planar, target.vga, budget.target, variant};
}

bool same_key(const AutoObjectKey& a, const AutoObjectKey& b) {
    const Texture &s = a.texture, &t = b.texture;
    return a.tex == b.tex && s.texels == t.texels && s.width == t.width && s.height == t.height && s.wrap == t.wrap && s.bordered == t.bordered &&
           s.aligned256 == t.aligned256 && s.doubled == t.doubled && a.max_error == b.max_error && a.texel_most == b.texel_most &&
           a.clip.x0 == b.clip.x0 && a.clip.y0 == b.clip.y0 && a.clip.x1 == b.clip.x1 && a.clip.y1 == b.clip.y1 && a.exact_coverage == b.exact_coverage &&
           a.planar == b.planar && a.vga == b.vga && a.priced_for == b.priced_for && a.variant == b.variant;
}

bool oriented_gate_may_hold(const OrientedPlan& plan, const CornerBox& b, const ClipRect& clip, const Vertex* vertices, int count) {
    const double area2 = corner_area2(vertices, count);
    // the gate at its least over both picks and walkers: lines at least the shorter side of the
    // box inside the clip (or, for a fitted cost below 0 a line, at most its longer), the pixels
    // the setup's (polygon_sizes)
    const double one = double(SUBPIXEL_ONE);
    const double w = double(box_inside(b.x_lo, b.x_hi, clip.x0, clip.x1)) / one, h = double(box_inside(b.y_lo, b.y_hi, clip.y0, clip.y1)) / one;
    const double box = w * h, area = area2 / (2 * one * one);
    const double fewer = w < h ? w : h, more = w < h ? h : w, pixels = area < box ? area : box;
    const CostRow &o = plan.oriented_row, &c = plan.constant_row, &l = plan.least;
    auto part = [](double x, double y) { return x < y ? x : y; };
    const double span = part(o.span, c.span);
    const double pick = part(o.polygon, c.polygon) + span * (span < 0 ? more : fewer) + part(o.pixel, c.pixel) * pixels;
    return pick <= l.polygon + l.span * (l.span < 0 ? more : fewer) + l.pixel * pixels + plan.gate;
}

ErrorBound auto_bound(const BoundContext& c, const Vertex* vertices, int count) {
    Target kind = surface_kind(c.axis == Axis::Rows ? Surface::Linear : Surface::Planar);
    kind.clip = c.clip;
    PreparedPolygon prepared;
    return choose_mapper(DEFAULT_BUDGET, vertices, count, c.tex, kind, &prepared).bound;
}

}  // namespace raster
