// Under test: kernel/mappers/auto/choice.h, prepared.h.
// auto: the cost model has a row for every mapper; auto picks the cheapest mapper whose bound meets
// the budget, never a dearer one when the budget loosens; and on every demo scene at the bench's
// frames, at budgets from 0 to any, through rows and columns, priced for each target in turn, its
// measured footprint error stays inside the budget and its coverage is exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "kernel/core/bound.h"
#include "kernel/mappers/auto/choice.h"
#include "kernel/core/footprint.h"
#include "kernel/core/measured.h"
#include "kernel/core/policy.h"
#include "kernel/core/prepared.h"
#include "kernel/core/spread.h"
#include "kernel/mappers/fastsubdiv.h"
#include "qemu/tools/demo_scenes.h"
#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

const Mapper& auto_mapper() { return *find_mapper("auto"); }

const Budget BUDGETS[] = {{true, 0, true}, {true, 0.5, true}, {true, 1, true}, {true, 2, true}, {true, 4, true}, {true, ANY_ERROR, false}};

// A table a target, each with a row per registry row in its order.
TEST(CostModel, HasOneRowPerRegistryRowInItsOrder) {
    ASSERT_EQ(MAPPER_COST_COUNT, MAPPER_COUNT) << "kernel/mappers/auto/costs.cpp is out of date: run make bench";
    EXPECT_EQ(cost_model(CostTarget::Icount).rows, MAPPER_COSTS);
    for (int t = 0; t < int(CostTarget::Count); ++t) {
        const CostModel& model = cost_model(CostTarget(t));
        EXPECT_STREQ(model.target, cost_target_name(CostTarget(t)));
        EXPECT_GT(model.proof_scale, 0) << model.target;
        for (int i = 0; i < MAPPER_COUNT; ++i) {
            EXPECT_STREQ(model.rows[i].mapper, MAPPERS[i].name) << "kernel/mappers/auto/costs.cpp is out of date: run make bench";
            if (choosable(MAPPERS[i])) {
                EXPECT_GT(model.rows[i].pixel, 0) << MAPPERS[i].name << " is not measured on " << model.target;
            }
        }
    }
}

// The errors the on-screen bench shows: one for every demo scene and registry row (a new mapper or
// scene needs a make bench), as make bench measured them: exact's 0, and a mapper's that
// drew nothing -1.
// Each role auto gives a registry row is one row's, and that row is fit for it: the fallback equals
// the reference, the oriented one picks its walker, the others are candidates auto may choose.
TEST(Auto, EachRoleIsOneRowOfTheRegistryFitForIt) {
    for (const AutoRole role : {AutoRole::Adaptive1, AutoRole::Adaptive2, AutoRole::Oriented, AutoRole::ConstantDepth, AutoRole::Fallback}) {
        int rows = 0;
        for (int i = 0; i < MAPPER_COUNT; ++i) rows += MAPPERS[i].auto_role == role;
        EXPECT_EQ(rows, 1) << int(role);
    }
    const Mapper& fallback = auto_fallback();
    EXPECT_EQ(fallback.auto_role, AutoRole::Fallback);
    EXPECT_EQ(fallback.guarantee.max_error, 0.0);
    EXPECT_TRUE(fallback.guarantee.exact_coverage);
    EXPECT_EQ(fallback.needs, uint32_t(NEED_NOTHING)) << "it takes every texture";
    for (int i = 0; i < MAPPER_COUNT; ++i) {
        const Mapper& m = MAPPERS[i];
        const bool candidate = m.auto_role == AutoRole::Adaptive1 || m.auto_role == AutoRole::Adaptive2 || m.auto_role == AutoRole::ConstantDepth;
        if (m.auto_role == AutoRole::Oriented) {
            EXPECT_TRUE(m.own_walker && drawn_by_auto(m) && !choosable(m)) << m.name;
        }
        if (candidate) {
            EXPECT_TRUE(choosable(m)) << m.name;
        }
    }
}

TEST(MeasuredErrors, EveryDemoSceneAndMapperHasItsRow) {
    for (const harness::DemoScene& d : harness::demo_scenes())
        for (int i = 0; i < MAPPER_COUNT; ++i) {
            double e = -2;
            EXPECT_TRUE(measured_error((std::string(d.name) + ".scene").c_str(), MAPPERS[i].name, &e))
                << d.name << " " << MAPPERS[i].name << ": kernel/mappers/errors.cpp is out of date: run make bench";
            EXPECT_GE(e, -1) << d.name << " " << MAPPERS[i].name;
            if (MAPPERS[i].guarantee.max_error == 0 && MAPPERS[i].guarantee.exact_coverage && !MAPPERS[i].is_auto) {
                EXPECT_EQ(e, 0) << d.name << " " << MAPPERS[i].name << " promises the reference";
            }
        }
    double e;
    EXPECT_FALSE(measured_error("no-such.scene", "exact", &e));
    EXPECT_FALSE(measured_error("ball.scene", "no-such-mapper", &e));
    EXPECT_FALSE(measured_error("ball-256.scene", "nothing", &e));
    EXPECT_TRUE(measured_error("ball", "exact", &e)) << "a scene's name with or without .scene";
}

// The spans auto's bounds walk (and the mappers that take spans draw from) are the walker's: the
// pixels the exact mapper draws.
TEST(Auto, PreparesThePolygonAsTheWalkerDrawsIt) {
    TriangleGen gen(77u);
    const Mapper& exact = *find_mapper("exact");
    std::vector<uint8_t> texels(64 * 64, 1), pixels(SCREEN_PIXELS * 4);
    Texture tex{texels.data(), 64, 64, Wrap::Repeat};
    for (int n = 0; n < 300; ++n) {
        std::vector<Vertex> p = gen.triangle();
        for (Axis axis : {Axis::Rows, Axis::Columns}) {
            Target t = ram_target(pixels.data(), axis == Axis::Columns);
            PreparedPolygon prepared;
            prepare_polygon(p.data(), 3, axis, t.clip, &prepared);
            RenderStats stats;
            SetupStatus status = draw_polygon(p.data(), 3, tex, exact, axis, t, &stats);
            EXPECT_EQ(prepared.status, status);
            if (status != SetupStatus::Ok) continue;
            EXPECT_EQ(uint32_t(prepared.walked[int(axis)].count), stats.spans);
            EXPECT_EQ(uint32_t(prepared.walked[int(axis)].pixels), stats.pixels);
        }
    }
}

// The choice against every candidate (mapper and walker), worked out here from the bounds and the
// cost model: a candidate proven by the whole polygon at once costs its estimate and that proof,
// one proven span by span (its tight bound, asked without a budget, where proven_by_spans)
// BOUND_SPAN_COST a span more (proven_cost; a mapper whose bound walks is proven only so, at its own
// price); auto takes the least, and a looser budget never costs more. Priced for each target in turn
// (its cost model's rows, auto's own costs times its proof_scale).
TEST(Auto, ChoosesTheCheapestMapperWhoseBoundMeetsTheBudget) {
    TriangleGen gen(1123u);
    std::vector<uint8_t> texels(256 * 256);
    generate_texture(TextureKind::Xor, 256, 256, texels.data());
    Texture tex{texels.data(), 256, 256, Wrap::Repeat};
    TextureCopies copies(&tex);
    const Mapper& oriented = *find_mapper("fast-oriented-1");
    const Mapper& adaptive1 = *find_mapper("fast-adaptive-1");
    const Mapper& adaptive2 = *find_mapper("fast-adaptive-2");
    const Mapper& constant_depth = *find_mapper("fast-constant-depth");
    int chose[MAPPER_LIMIT][2] = {}, by_spans = 0, choices = 0, unsearched = 0, outside = 0, undercut = 0, ruled_out = 0, by_chords = 0, chords_certified = 0, chords_outside = 0;
    for (int n = 0; n < 400; ++n) {
        gen.depth_ratio = n % 4 == 0 ? 1.0001 : n % 4 == 1 ? 3 : 50;
        std::vector<Vertex> p = gen.triangle();
        // priced for each target in turn: its rows, its proofs' costs scaled
        const CostTarget priced_for = CostTarget(n % int(CostTarget::Count));
        const CostModel& model = cost_model(priced_for);
        const double scale = model.proof_scale;
        for (Surface surface : {Surface::Linear, Surface::Planar}) {
            Target target = surface_kind(surface);
            target.clip = ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
            double last_total = 1e300;
            for (Budget b : BUDGETS) {
                b.target = priced_for;
                PreparedPolygon prepared;
                Choice c = choose_mapper(b, p.data(), 3, tex, target, &prepared);
                if (!c.mapper) {  // only where exact cannot draw it either
                    EXPECT_FALSE(find_mapper("exact")->bound(BoundContext{*find_mapper("exact"), tex, Axis::Rows, target.clip}, p.data(), 3).draws);
                    break;
                }
                const int row = int(c.mapper - MAPPERS);
                ++chose[row][int(c.axis)], ++choices, by_spans += c.by_spans;
                EXPECT_TRUE(budget_allows(b, c.bound)) << c.mapper->name;
                EXPECT_TRUE(mapper_targets(*c.mapper, target, c.axis) && mapper_walks(*c.mapper, c.axis)) << c.mapper->name;
                PolygonSetup setup;
                ASSERT_EQ(setup_polygon(p.data(), 3, &setup), SetupStatus::Ok);
                PolygonSize sizes[2];
                polygon_sizes(setup, target.clip, sizes);
                // what a candidate costs with its proof, or nothing where it has none within the budget
                auto total = [&](const Mapper& m, Axis axis) {
                    const double cost = estimate_cost(proven_cost(m, cost_row(model.rows[&m - MAPPERS]), scale), sizes[int(axis)]);
                    BoundContext whole{m, tex, axis, target.clip, b.max_error < 0 ? NO_BOUND : b.max_error, nullptr, true};
                    if (!bound_walks(m) && budget_allows(b, m.bound(whole, p.data(), 3))) return cost;
                    if (proven_by_spans(m) && budget_allows(b, m.bound(BoundContext{m, tex, axis, target.clip}, p.data(), 3)))
                        return cost + (bound_walks(m) ? 0 : BOUND_SPAN_COST * scale * sizes[int(axis)].spans);
                    return 1e300;
                };
                // the oriented candidate (ORIENTED_GATE): from a budget of 1, fast-adaptive-B
                // (B = 1 below 2, else 2) along fast-oriented-B's walker, where fast_oriented_guard holds,
                // else its certificate (inside the clip) or its whole bound within B, priced by
                // fast-oriented-1's row (B = 1) or fast-adaptive-2's; or fast-constant-depth where the
                // same proof bounds its chords within the budget (the spread's only where unsearched):
                // drawn so where no candidate with its proof undercuts it by more than the gate, or where
                // the affine deviation is above the budget (then only a mapper that does not step
                // affinely may undercut it, by any amount); else only a cheaper proven one is chosen
                const bool one = b.max_error >= 1 && b.max_error < 2, two = b.max_error >= 2;
                const double within = two ? 2 : 1;
                const Mapper& adaptive = two ? adaptive2 : adaptive1;
                const Mapper& drawn_by = two ? adaptive2 : oriented;
                const Axis walker =
                    surface == Surface::Planar ? Axis::Columns : oriented_axis(setup, target.clip, fast_adaptive_room(within));
                const ClipRect& clip = target.clip;
                const bool inside = box_in_clip(setup, clip);
                const ErrorBound adaptive_whole = (one || two) && !inside
                                                      ? adaptive.bound(BoundContext{adaptive, tex, walker, clip, within, nullptr, true}, p.data(), 3)
                                                      : ErrorBound{};
                const FastCertificate certificate = inside ? fast_certificate(setup, clip, tex) : FastCertificate{};
                const bool certain_inside = two ? fast_adaptive_certain<8>(certificate, setup, walker) : fast_adaptive_certain<4>(certificate, setup, walker);
                EXPECT_EQ(certain_inside, two ? fast_adaptive_certain<8>(setup, clip, tex, walker) : fast_adaptive_certain<4>(setup, clip, tex, walker));
                const bool affine_ruled_out = affine_deviation(setup, clip) > b.max_error;
                const double uv_most = texel_most(p), guard = fast_oriented_guard_takes(uv_most, clip) ? fast_oriented_guard(setup, clip, walker, uv_most) : 0;
                const Mapper* unsearched_by = nullptr;
                double estimate = 1e300, unsearched_bound = within;
                if ((one || two) && (guard > 0 || (inside ? certain_inside : adaptive_whole.draws && adaptive_whole.footprint <= within)))
                    unsearched_by = &drawn_by, estimate = estimate_cost(model.rows[&drawn_by - MAPPERS], sizes[int(walker)]);
                const bool constant_depth_here = mapper_walks(constant_depth, walker) && mapper_targets(constant_depth, target, walker);
                if ((one || two) && guard > 0 && constant_depth_here) {
                    const double cost = estimate_cost(model.rows[&constant_depth - MAPPERS], sizes[int(walker)]);
                    if (cost < estimate && fast_constant_within(setup, clip, walker, guard, fast_adaptive_room(b.max_error))) {
                        const BoundContext whole{constant_depth, tex, walker, clip, b.max_error, nullptr, true};
                        EXPECT_LE(constant_depth.bound(whole, p.data(), 3).footprint, b.max_error);
                        ++chords_certified;
                        unsearched_by = &constant_depth, estimate = cost, unsearched_bound = b.max_error;
                    }
                } else if ((one || two) && (inside || unsearched_by) && constant_depth_here) {
                    PolygonSpread spread;
                    if (!inside) polygon_spread(setup, clip, &spread);
                    const FastCertificate chords = inside ? certificate : fast_certificate(spread);
                    const double cost = estimate_cost(model.rows[&constant_depth - MAPPERS], sizes[int(walker)]);
                    const double bound = fast_chords_bound(chords, setup, walker, FAST_SPAN_LONG);
                    // (where within the budget, at least the whole bound it stands for)
                    if (bound <= b.max_error) {
                        EXPECT_LE(constant_depth.bound(BoundContext{constant_depth, tex, walker, clip, b.max_error, nullptr, true}, p.data(), 3).footprint, bound);
                        ++chords_certified;
                    }
                    // (what any candidate could cost at least with its proof: the least polygon, span
                    // and pixel costs of all of them, the spans most where one costs less than 0 a span)
                    double least[3] = {1e300, 1e300, 1e300};
                    for (int i = 0; i < MAPPER_COUNT; ++i)
                        for (Axis axis : {Axis::Rows, Axis::Columns}) {
                            const Mapper& m = MAPPERS[i];
                            if (!choosable(m) || !mapper_walks(m, axis) || !mapper_accepts(m, tex) || !mapper_targets(m, target, axis)) continue;
                            if ((b.exact_coverage && !m.guarantee.exact_coverage) || (b.max_error == 0 && m.guarantee.max_error != 0)) continue;
                            const CostRow r = proven_cost(m, cost_row(model.rows[i]), scale);
                            least[0] = std::min(least[0], double(r.polygon)), least[1] = std::min(least[1], double(r.span)), least[2] = std::min(least[2], double(r.pixel));
                        }
                    const double fewest = std::min(sizes[0].spans, sizes[1].spans), most = std::max(sizes[0].spans, sizes[1].spans);
                    const double least_cost = least[0] + least[1] * (least[1] < 0 ? most : fewest) + least[2] * sizes[0].pixels;
                    const bool unsearched_only = !inside && !(cost <= least_cost + ORIENTED_GATE * scale) && !affine_ruled_out;
                    if (cost < estimate && bound <= b.max_error && !unsearched_only) unsearched_by = &constant_depth, estimate = cost, unsearched_bound = bound;
                }
                const bool certified = unsearched_by != nullptr;
                double chosen, slack = 0;
                if (certified && c.mapper == unsearched_by && c.axis == walker && c.bound.footprint == unsearched_bound) {
                    ++unsearched, outside += !inside, ruled_out += affine_ruled_out, by_chords += unsearched_by != &drawn_by;
                    chords_outside += unsearched_by != &drawn_by && !inside;
                    chosen = estimate, slack = affine_ruled_out ? 1e300 : ORIENTED_GATE * scale;
                } else {
                    EXPECT_NE(c.mapper, &oriented) << "fast-oriented-1 where its candidate is not proven";
                    chosen = total(*c.mapper, c.axis);
                    EXPECT_LT(chosen, 1e300) << c.mapper->name << " has no bound within the budget";
                    EXPECT_LE(chosen, estimate + 1) << c.mapper->name << " is dearer than the unsearched candidate";
                    undercut += certified;
                }
                const bool affine_stepping_only = slack == 1e300;
                for (int i = 0; i < MAPPER_COUNT; ++i) {
                    const Mapper& m = MAPPERS[i];
                    for (Axis axis : {Axis::Rows, Axis::Columns}) {
                        if (!choosable(m) || !mapper_walks(m, axis) || !mapper_targets(m, target, axis) || !mapper_accepts(m, tex)) continue;
                        // (the search prices in whole instructions, each estimate rounded to the
                        // nearest: two within one of each other may tie, and the tie goes to the
                        // one priced first)
                        // (where the affine deviation ruled the search out: the affine-stepping ones)
                        const bool stepping = m.enveloped || m.span_planes == PLANES_AFFINE || std::string(m.name).rfind("fast-table", 0) == 0;
                        if (affine_stepping_only && !stepping) continue;
                        EXPECT_GE(total(m, axis), affine_stepping_only ? chosen : chosen - 1 - slack)
                            << m.name << " is cheaper than " << c.mapper->name << " within the budget " << b.max_error;
                    }
                }
                if (!affine_stepping_only) {
                    EXPECT_LE(chosen, last_total + 1 + slack) << "a looser budget chose a dearer mapper";
                }
                // (after the unsearched candidate, what a looser budget may cost at most: it with its
                // proof, fast-adaptive-B along that walker for the oriented one)
                last_total = slack == 0 ? chosen : unsearched_by == &drawn_by ? total(adaptive, walker) : total(*unsearched_by, walker);
            }
        }
        if (HasFailure()) return;
    }
    int kinds = 0, columns = 0;
    for (int i = 0; i < MAPPER_COUNT; ++i) kinds += chose[i][0] + chose[i][1] > 0, columns += chose[i][1];
    EXPECT_GE(kinds, 3) << "the random polygons exercise more than one or two choices";
    EXPECT_GT(columns, 0) << "and both walkers";
    EXPECT_GT(by_spans, 0) << "and proofs span by span";
    EXPECT_LT(by_spans, choices) << "and of the whole polygon";
    EXPECT_GT(unsearched, 0) << "the oriented candidate taken unsearched";
    EXPECT_GT(outside, 0) << "the oriented candidate taken on polygons reaching outside the clip";
    EXPECT_GT(undercut, 0) << "and undercut by a cheaper proven one";
    EXPECT_GT(ruled_out, 0) << "and taken where the affine deviation rules the search out";
    EXPECT_GT(by_chords, 0) << "fast-constant-depth taken unsearched, proven by the oriented candidate's certificate or spread";
    EXPECT_GT(chords_outside, 0) << "also on polygons reaching outside the clip, by the spread";
    EXPECT_GT(chords_certified, by_chords) << "and proven where not taken";
}

// A planar quad in perspective: a square of side 2 (texels 0..side) about a random point in front of
// the eye, tilted at random, projected (focal length 160 pixels, the screen's centre).
std::vector<Vertex> planar_quad(TriangleGen& gen, double depth, double side) {
    const double cz = gen.uniform(1, depth), cx = gen.uniform(-1, 1) * cz, cy = gen.uniform(-0.75, 0.75) * cz;
    double a[3] = {gen.uniform(-1, 1), gen.uniform(-1, 1), gen.uniform(-1, 1)}, b[3] = {gen.uniform(-1, 1), gen.uniform(-1, 1), gen.uniform(-1, 1)};
    const double scale = gen.uniform(0.05, 1) * cz * 0.5;
    std::vector<Vertex> quad;
    for (int k = 0; k < 4; ++k) {
        const double sa = k == 0 || k == 3 ? -1 : 1, sb = k < 2 ? -1 : 1;
        const double x = cx + scale * (sa * a[0] + sb * b[0]), y = cy + scale * (sa * a[1] + sb * b[1]), z = cz + scale * (sa * a[2] + sb * b[2]);
        if (!(z > 0.05)) return {};
        quad.push_back(vertex_raw(int32_t((160 + 160 * x / z) * 256), int32_t((120 + 160 * y / z) * 256), z, (sa + 1) / 2 * side, (sb + 1) / 2 * side));
    }
    return quad;
}

// affine_deviation is a floor of every bound of a mapper that steps the polygon affinely (the
// affine planes, or fast-table's offsets from them): where it is above the budget, none of them is
// within it, which the oriented candidate's gate relies on to skip the search. Their tightest
// bounds on random triangles and planar quads, perspective from none to steep, both walkers.
TEST(Auto, NoAffineSteppingMapperIsBoundedBelowTheAffineDeviation) {
    TriangleGen gen(1126u);
    Texture256 blank;
    Texture& tex = blank.tex;
    const ClipRect clip{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
    int asked = 0, above_one = 0, inside = 0;
    double worst = 1e300;
    for (int n = 0; n < 24000; ++n) {
        gen.depth_ratio = n % 4 == 0 ? 1.0001 : n % 4 == 1 ? 1.2 : n % 4 == 2 ? 3 : 50;
        const std::vector<Vertex> p = n % 2 ? gen.triangle() : planar_quad(gen, n % 4 < 2 ? 4 : 40, n % 8 < 4 ? 16 : 512);
        PolygonSetup setup;
        if (p.empty() || setup_polygon(p.data(), int(p.size()), &setup) != SetupStatus::Ok) continue;
        const double d = affine_deviation(setup, clip);
        inside += d > 0;
        above_one += d > 1;
        for (const char* name : {"affine", "fast-affine", "fast-columns", "fast-table", "fast-table-columns"}) {
            const Mapper& m = *find_mapper(name);
            for (Axis axis : {Axis::Rows, Axis::Columns}) {
                if (!mapper_walks(m, axis)) continue;
                const ErrorBound b = m.bound(BoundContext{m, tex, axis, clip}, p.data(), int(p.size()));
                if (!b.draws) continue;
                ++asked;
                if (d > 0 && b.footprint < d) std::printf("LOW %s %d %zu %.4f %.4f %.4f\n", name, n, p.size(), d, b.footprint, b.footprint / d);
                if (d > 0) worst = std::min(worst, b.footprint / d);
            }
        }
        if (HasFailure()) return;
    }
    EXPECT_GT(inside, 500) << "polygons whose deviation is known";
    EXPECT_GT(above_one, 250) << "polygons where the gate would skip the search at a budget of 1";
    std::printf("  %d bounds asked; the deviation above 1 on %d polygons; the least bound over it %.3f\n", asked, above_one, worst);
}

// The small box (AutoPlan::small_box) gives exact unchosen before any area or estimate only where
// the whole rule would (exact's estimate on its walker at most the others' least plus CHOICE_COST),
// and does on most polygons of a pixel or two. A plan whose others cost nothing leaves the box the
// only way to exact; random triangles of half a pixel to 120, every budget, either target.
TEST(Auto, TheSmallBoxGivesExactOnlyWhereTheWholeRuleWould) {
    TriangleGen gen(1129u);
    Texture256 blank;
    Texture& tex = blank.tex;
    int by_box = 0, tiny = 0, tiny_by_box = 0;
    for (Surface surface : {Surface::Linear, Surface::Planar}) {
        Target target = surface_kind(surface);
        target.clip = ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
        for (const Budget& b : BUDGETS) {
            const AutoPlan plan = plan_auto(b, tex, target, NO_BOUND);
            if (plan.sole) continue;
            AutoPlan only_box = plan;
            only_box.others = CostRow{-1e30, 0, 0}, only_box.exact_below = 0, only_box.choosing_pays_above2 = INT64_MAX;
            for (int n = 0; n < 2000; ++n) {
                std::vector<Vertex> p = gen.triangle();
                PreparedPolygon prepared;
                prepare_setup(p.data(), 3, &prepared);
                if (prepared.status != SetupStatus::Ok) continue;
                PolygonSize size[2];
                polygon_sizes(prepared.setup, target.clip, size);
                Axis axis, box_axis;
                const Mapper* whole = unchosen_mapper(plan, p.data(), 3, target.clip, &axis);
                const bool boxed = unchosen_mapper(only_box, p.data(), 3, target.clip, &box_axis) == plan.certain;
                const bool small = size[0].spans <= 2 && size[1].spans <= 2;
                tiny += small, tiny_by_box += small && boxed;
                if (!boxed) continue;
                ++by_box;
                const double best = estimate_cost(plan.certain_row, size[int(box_axis)]);
                const double least = std::min(estimate_cost(plan.others, size[0]), estimate_cost(plan.others, size[1]));
                EXPECT_LE(best, least + plan.choice_cost) << "polygon " << n << " at budget " << b.max_error;
                EXPECT_EQ(whole, plan.certain) << "polygon " << n << ": the whole rule gives exact too";
                EXPECT_EQ(int(axis), int(box_axis)) << "polygon " << n << ": on the same walker";
                if (HasFailure()) return;
            }
        }
    }
    std::printf("  exact unchosen by the box alone on %d polygons; on %d of the %d within 2 x 2 pixels\n", by_box, tiny_by_box, tiny);
    EXPECT_GT(tiny_by_box * 2, tiny) << "most polygons of a pixel or two";
}

// Where choosing cannot pay (unchosen_mapper), auto draws exact unchosen: only where, by the cost
// model, exact on that walker costs no more than CHOICE_COST plus what the choice would draw with
// its proof; at a budget of 0, always, on the walker the choice takes. On random polygons at
// every budget, on either kind of target.
TEST(Auto, DrawsUnchosenOnlyWhereChoosingCannotPay) {
    TriangleGen gen(1124u);
    Texture256 blank;
    Texture& tex = blank.tex;
    int unchosen = 0, chosen = 0, walkers[2] = {}, by_footprint = 0, missed = 0, at_once = 0;
    for (Surface surface : {Surface::Linear, Surface::Planar}) {
        Target target = surface_kind(surface);
        target.clip = ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
        for (const Budget& b : BUDGETS) {
            const AutoPlan plan = plan_auto(b, tex, target, NO_BOUND);
            ASSERT_EQ(plan.certain, find_mapper("exact"));
            EXPECT_EQ(plan.sole, b.max_error == 0) << "budget " << b.max_error;
            for (int n = 0; n < 300; ++n) {
                gen.depth_ratio = n % 2 ? 1.0001 : 20;
                std::vector<Vertex> p = n % 3 ? gen.triangle() : std::vector<Vertex>{gen.random_vertex(), gen.random_vertex(), gen.random_vertex()};
                PreparedPolygon prepared;
                Choice c = choose_mapper(b, p.data(), 3, tex, target, &prepared);
                Axis axis;
                const Mapper* m = unchosen_mapper(plan, p.data(), 3, target.clip, &axis);
                if (!m && c.mapper && b.max_error >= 1) {
                    // and where it gives none (from a budget of 1, also at once: choosing_pays_above2),
                    // exact on either of its walkers costs more than CHOICE_COST above the least the
                    // others could cost on the walker where they cost least
                    PolygonSize size[2];
                    polygon_sizes(prepared.setup, target.clip, size);
                    double best = 1e300, least = 1e300;
                    for (int w = 0; w < plan.certain_walkers; ++w) best = std::min(best, estimate_cost(plan.certain_row, size[int(plan.certain_axes[w])]));
                    for (const PolygonSize& on : size) least = std::min(least, estimate_cost(plan.others, on));
                    EXPECT_GT(best, least + CHOICE_COST) << "polygon " << n << ": exact unchosen would have cost less";
                    at_once += magnitude(double(prepared.setup.area2)) > double(plan.choosing_pays_above2);
                }
                if (!m || !c.mapper) {
                    chosen += !m;
                    continue;
                }
                ++unchosen, ++walkers[int(axis)];
                EXPECT_EQ(m, plan.certain);
                PolygonSize size[2];
                polygon_sizes(prepared.setup, target.clip, size);
                const double drawn = estimate_cost(plan.certain_row, size[int(axis)]);
                const double choice = estimate_cost(proven_cost(*c.mapper, cost_row(MAPPER_COSTS[c.mapper - MAPPERS]), 1), size[int(c.axis)]);
                // where choosing would pay, only below a budget of 1, for a polygon inside the clip
                // whose first corner's footprint is below 1 / budget
                if (drawn > choice + CHOICE_COST + 1e-6) {
                    bool inside = true;
                    for (const Vertex& v : p)
                        inside = inside && v.x.raw >= target.clip.x0 * SUBPIXEL_ONE && v.x.raw <= target.clip.x1 * SUBPIXEL_ONE &&
                                 v.y.raw >= target.clip.y0 * SUBPIXEL_ONE && v.y.raw <= target.clip.y1 * SUBPIXEL_ONE;
                    EXPECT_TRUE(inside && b.max_error > 0 && b.max_error < 1 && corner_footprint(p.data()) < 1 / b.max_error)
                        << "polygon " << n << ": choosing " << c.mapper->name << " would pay";
                    ++by_footprint;
                    missed += c.mapper != m;
                }
                if (c.mapper == m) {
                    EXPECT_EQ(int(c.axis), int(axis)) << "polygon " << n << ": exact on the walker the choice takes";
                }
                if (HasFailure()) return;
            }
        }
    }
    std::printf("  unchosen %d (by rows %d, by columns %d; %d by the footprint below 1 / budget, of which choosing would have found a "
                "cheaper mapper on %d), chosen %d (%d at once, by their size)\n",
                unchosen, walkers[0], walkers[1], by_footprint, missed, chosen, at_once);
    EXPECT_GT(at_once, 0) << "polygons given to the choice at once";
    EXPECT_LE(missed * 20, by_footprint) << "the corner's footprint misjudges one polygon in 20 or more";
    EXPECT_GT(walkers[0], 0);
    EXPECT_GT(walkers[1], 0);
    EXPECT_GT(chosen, 0);
}

TEST(Auto, StaysWithinTheBudgetOnEveryDemoScene) {
    const Mapper& a = auto_mapper();
    for (const DemoScene& d : demo_scenes()) {
        LoadedWorld w = load_world_file(std::string("scenes/") + d.name + ".scene");
        std::vector<std::unique_ptr<HostFrame>> frames;  // the bench's
        for (int f = 0; f < 8; f += SANITIZED_SHARE) frames.push_back(world_frame(w, int32_t(int64_t(f) * w.world->frames / 8)));
        for (const Budget& b : BUDGETS) {
            for (Axis axis : {Axis::Rows, Axis::Columns}) {
                uint32_t by_mapper[MAPPER_LIMIT] = {};
                for (size_t fi = 0; fi < frames.size(); ++fi) {
                    const int f = int(fi) * SANITIZED_SHARE;
                    Frame* frame = frames[fi].get();
                    frame->budget = b;
                    frame->budget.target = CostTarget(fi % int(CostTarget::Count));  // priced for each target in turn
                    AccuracyMetrics m = measure_world_frame(w, *frame, a, axis);
                    std::string what = std::string(d.name) + " frame " + std::to_string(f) + " budget " + std::to_string(b.max_error) +
                                       (axis == Axis::Rows ? " rows" : " columns") + " priced for " + cost_target_name(frame->budget.target);
                    if (b.max_error >= 0) {
                        EXPECT_LE(m.max_footprint_error, b.max_error + 1e-6) << what;
                    }
                    if (b.exact_coverage) {  // else a classic's own fill convention may draw
                        EXPECT_EQ(m.gaps, 0u) << what;
                        EXPECT_EQ(m.overdraw, 0u) << what;
                    }
                    RenderStats stats;
                    render_world_frame(w, *frame, a, axis, &stats);
                    uint32_t polygons = 0, pixels = 0;
                    for (int i = 0; i < MAPPER_COUNT; ++i) polygons += stats.mapper_polygons[i], pixels += stats.mapper_pixels[i], by_mapper[i] += stats.mapper_polygons[i];
                    EXPECT_EQ(polygons, stats.polygons) << what;
                    EXPECT_EQ(pixels, stats.pixels) << what;
                    EXPECT_EQ(stats.mapper_polygons[&a - MAPPERS], 0u) << what << ": auto draws with other mappers";
                    if (b.max_error == 0) {
                        EXPECT_EQ(m.max_texel_error, 0u) << what;
                    }
                    if (HasFailure()) return;
                }
                std::string line;
                for (int i = 0; i < MAPPER_COUNT; ++i)
                    if (by_mapper[i]) line += std::string(" ") + MAPPERS[i].name + " " + std::to_string(by_mapper[i]);
                std::printf("  %-9s budget %-5g %-7s:%s\n", d.name, b.max_error, axis == Axis::Rows ? "rows" : "columns", line.c_str());
            }
        }
    }
}

}  // namespace

// The footprint at the first corner before any setup is the setup's own there (texel_footprint),
// on random triangles either way round.
TEST(Auto, CornerFootprintIsTheSetupsAtThatCorner) {
    TriangleGen gen(1125u);
    int compared = 0;
    for (int n = 0; n < 500; ++n) {
        gen.depth_ratio = n % 3 == 0 ? 1.0001 : n % 3 == 1 ? 4 : 50;
        const std::vector<Vertex> p = gen.triangle();
        PolygonSetup s;
        if (setup_polygon(p.data(), 3, &s) != SetupStatus::Ok) continue;
        const double at = texel_footprint(s, double(p[0].x.raw - s.ref_x), double(p[0].y.raw - s.ref_y));
        EXPECT_NEAR(corner_footprint(p.data()), at, at * 1e-6 + 1e-9) << "triangle " << n;
        ++compared;
    }
    EXPECT_GT(compared, 400);
}

// Below a budget of 1, a polygon inside the clip whose first corner's footprint is below 1 / budget
// is drawn with exact unchosen, however large (no other bound can come within the budget there:
// the choice itself takes exact); minified enough, or reaching outside the clip, it is chosen for.
TEST(Auto, DrawsExactUnchosenWhereTheFootprintIsTooSmallForTheBudget) {
    Texture256 blank;
    Texture& tex = blank.tex;
    Target target = screen_target(Surface::Linear);
    const Budget half{true, 0.5, true};
    const AutoPlan plan = plan_auto(half, tex, target, NO_BOUND);
    // a receding triangle of some 9000 pixels: a texel spans about two pixels (magnified), or,
    // its texel coordinates times eight, four texels a pixel
    auto triangle = [](double scale, double dx) {
        return std::vector<Vertex>{vertex(40 + dx, 30, 1, 0, 0), vertex(250 + dx, 60, 1.5, 100 * scale, 0),
                                   vertex(60 + dx, 200, 1.2, 0, 80 * scale)};
    };
    Axis axis;
    const std::vector<Vertex> magnified = triangle(1, 0), minified = triangle(8, 0), outside = triangle(1, -60);
    EXPECT_LT(corner_footprint(magnified.data()), 1.0);
    EXPECT_GT(corner_footprint(minified.data()), 2.0);
    EXPECT_EQ(unchosen_mapper(plan, magnified.data(), 3, target.clip, &axis), find_mapper("exact"));
    PreparedPolygon prepared;
    EXPECT_EQ(choose_mapper(half, magnified.data(), 3, tex, target, &prepared).mapper, find_mapper("exact")) << "nothing cheaper within 0.5";
    EXPECT_EQ(unchosen_mapper(plan, minified.data(), 3, target.clip, &axis), nullptr);
    EXPECT_EQ(unchosen_mapper(plan, outside.data(), 3, target.clip, &axis), nullptr) << "its first corner is off the screen";
    const AutoPlan one = plan_auto(Budget{true, 1, true}, tex, target, NO_BOUND);
    EXPECT_EQ(unchosen_mapper(one, magnified.data(), 3, target.clip, &axis), nullptr) << "a budget of 1 is met at any footprint";
}
