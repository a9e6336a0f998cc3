// Error bounds before drawing (docs/bounds.md): how far, in footprints, a mapper's texel can be
// from the reference's on a polygon, from what setup knows. What the mappers' own bound functions
// are asked with and built from: the context, the span pieces, and the helpers that take the
// polygon span by span or whole (the maths along a span: spanline.h; over the polygon: spread.h).
#pragma once

#include <stdint.h>

#include "kernel/core/footprint.h"
#include "kernel/core/mapper.h"
#include "kernel/core/prepared.h"
#include "kernel/core/setup.h"
#include "kernel/core/spread.h"
#include "kernel/core/walk.h"

namespace raster {

// The pieces a span's bound is taken over: a deviation and the footprint it is divided by belong
// to the same few pixels, not the whole span.
constexpr double BOUND_PIECE = 16;

// What a mapper promises for one polygon before drawing it.
struct ErrorBound {
    bool draws = false;           // whether the mapper draws the polygon (false: it refuses it, or it
                                  // is degenerate); for `unbounded` mappers: whether it may
    bool exact_coverage = false;  // it draws exactly the pixels the reference covers
    double footprint = 0;         // max footprint error on every pixel it draws (NO_BOUND: none)
};

struct BoundContext {
    const Mapper& mapper;
    const Texture& tex;  // with the copies prepare_texture builds
    Axis axis;           // the walker the mapper uses
    ClipRect clip;
    // What the caller asks (auto: its budget). Below 0: the tightest bound, every span piece by
    // piece. At or above 0: only whether the bound is within it, cheaply: a span whose coarse
    // bound (the whole span as one piece) is within it is not taken piece by piece, and once the
    // bound is above it the evaluation stops (the footprint returned is then only known to be
    // above the budget, not the polygon's bound).
    double budget = -1;
    PreparedPolygon* prepared = nullptr;  // the polygon set up and walked already, or nullptr
    // With a budget: the whole polygon at once only (from its vertices, never walked); where that
    // is not within the budget, NO_BOUND.
    bool whole_only = false;
    bool settled(double worst) const { return budget >= 0 && worst > budget; }
};

// The bound over pixels k0..k1 of a span (k0 a multiple of `length`) from the bounds of its
// pieces: piece(a, b) bounds pixels a..b, pieces of `length` pixels from k0. With a budget
// (BoundContext::budget), first the whole range as one piece (`coarse(k0, k1)`, valid over any
// range of whole pieces), and where that is above the budget its halves, down to the pieces.
template <typename Coarse, typename Piece>
double span_bound(const BoundContext& c, double k0, double k1, double length, Coarse&& coarse, Piece&& piece) {
    double pieces = double(int64_t((k1 - k0) / length)) + 1;
    if (c.budget >= 0 && pieces > 1) {
        double whole = coarse(k0, k1);
        if (whole <= c.budget) return whole;
        double mid = k0 + double(int64_t(pieces / 2)) * length;
        double left = span_bound(c, k0, mid - 1, length, coarse, piece);
        if (c.settled(left)) return left;
        return larger(left, span_bound(c, mid, k1, length, coarse, piece));
    }
    double worst = 0;
    for (double a = k0; a <= k1 && !c.settled(worst); a += length) worst = larger(worst, piece(a, a + length - 1 < k1 ? a + length - 1 : k1));
    return worst;
}

// For mappers whose error is not (yet) bounded: whether they may draw the polygon (they take the
// texture), and no bound.
ErrorBound unbounded(const BoundContext& c, const Vertex* vertices, int count);

// Calls f(span, setup) for every span of the polygon inside the clip (the prepared ones, or the
// walker's), f returning the bound so far; stops once that is above the context's budget
// (settled). False when setup does not take the polygon (refused, or degenerate: nothing to draw).
template <typename F>
bool for_each_span(const BoundContext& c, const Vertex* vertices, int count, SetupPlanes planes, F&& f) {
    if (PreparedPolygon* p = c.prepared; p && p->walked[int(c.axis)].count == PreparedSpans::NOT_WALKED) walk_polygon(p, c.axis, c.clip);
    if (PreparedPolygon* p = c.prepared; p && p->walked[int(c.axis)].count >= 0) {
        if (p->status != SetupStatus::Ok) return false;
        PreparedSpans& w = p->walked[int(c.axis)];
        for (int32_t i = 0, k = w.first; i < w.count; ++i, k = k + 1 < w.count ? k + 1 : 0)
            if (c.settled(f(w.spans[k], p->setup))) {
                w.first = k;
                break;
            }
        return true;
    }
    PolygonSetup s;
    if (setup_polygon(vertices, count, &s, planes) != SetupStatus::Ok) return false;
    EdgeWalker walker(s, c.axis, c.clip);
    Span span;
    while (walker.next(&span))
        if (c.settled(f(span, s))) break;
    return true;
}

// Whether setup takes the polygon (the prepared one's status, or a coverage-only setup).
bool setup_takes(const BoundContext& c, const Vertex* vertices, int count);

// Asked with a budget, the polygon's bound at once where that is within it: whole(spread, setup)
// (the spread to complete as needed) gives it (NO_BOUND where it cannot say, 16.16 included). True with *out set when it settles.
template <typename W>
bool whole_within(const BoundContext& c, const Vertex* vertices, int count, W&& whole, ErrorBound* out) {
    if (c.budget < 0) return false;
    PolygonSetup own_setup;
    PolygonSpread own_spread;
    const PolygonSetup* s = &own_setup;
    PolygonSpread* spread = &own_spread;
    if (c.prepared) {
        if (c.prepared->status != SetupStatus::Ok) return false;  // the walk says why
        s = &c.prepared->setup, spread = &prepared_spread(c.prepared, c.clip);
    } else {
        if (setup_polygon(vertices, count, &own_setup, PLANES_ALL) != SetupStatus::Ok) return false;
        polygon_spread(own_setup, c.clip, &own_spread);
    }
    double footprint = whole(*spread, *s);
    if (!(footprint <= c.budget)) return false;
    out->draws = out->exact_coverage = true;
    out->footprint = footprint;
    return true;
}

// The bound of a mapper that draws exactly the reference's pixels and is bounded span by span:
// span_bound_of(span, setup, &fits) gives a span's bound and clears `fits` where 16.16 does not
// hold the mapper's coordinates (no bound then); the polygon's is the largest. Asked with a budget,
// whole(spread, setup) first (whole_within).
template <typename W, typename F>
ErrorBound bound_by_spans(const BoundContext& c, const Vertex* vertices, int count, SetupPlanes planes, W&& whole, F&& span_bound_of) {
    ErrorBound b;
    if (whole_within(c, vertices, count, whole, &b)) return b;
    b.exact_coverage = true;
    if (c.whole_only) {
        b.draws = setup_takes(c, vertices, count);
        b.footprint = NO_BOUND;
        return b;
    }
    bool fits = true;
    double worst = 0;
    b.draws = for_each_span(c, vertices, count, planes, [&](const Span& span, const PolygonSetup& s) {
        double bound = span_bound_of(span, s, &fits);
        worst = bound > worst ? bound : worst;
        return fits ? worst : NO_BOUND;
    });
    b.footprint = fits ? worst : NO_BOUND;
    return b;
}

// For the classics' bounds, which run their own walk again, once the classic's own conversion has
// taken the polygon: *b says it draws, with no bound yet; asked for the whole polygon only, there
// is nothing cheaper than that walk (nullptr); else the polygon's setup for the exact mapping: the
// prepared one, or one set up into `own` (nullptr where setup does not take it).
const PolygonSetup* exact_setup(const BoundContext& c, const Vertex* vertices, int count, PolygonSetup* own, ErrorBound* b);
// The bound over a line the mapper draws (the span's pixels along the axis) reading texel
// floor(a[t] + b[t] k) at pixel k: each line against the exact mapping (lines_bound), BOUND_PIECE
// pixels at a time, with `extra` texels more; NO_BOUND where Q is not positive at either end (a
// pixel far outside the polygon).
double drawn_line_bound(const PolygonSetup& s, Axis axis, const Span& span, const double* a, const double* b, double extra);
// Whether the indices floor(a + b k), k in [0, last], stay in a bordered copy (-1 .. size, the
// border repeating the edge texels); where they reach the border the texel read may be one nearer
// the texture than the index, one texel further from the reference's: *extra becomes 1.
bool within_border(double a, double b, double last, double size, double* extra);

// The affine planes' lines along a span: u and v (t = 0, 1) at its first pixel centre, a[t], and
// their steps a pixel along it, step[t].
void affine_lines(const PolygonSetup& s, Axis axis, const Span& span, double* a, double* step);

}  // namespace raster
