// Edge walkers: the spans (rows) or columns of a set-up polygon inside a clip rectangle, with
// all-integer stepping. Both walkers cover exactly the pixels covers() accepts.
#pragma once

#include <stdint.h>

#include "kernel/core/setup.h"

namespace raster {

enum class Axis : uint8_t { Rows, Columns };

// Rows: pixels (x .. x+count-1, y). Columns: pixels (x, y .. y+count-1). count >= 1.
struct Span {
    int32_t x, y, count;
};

// One edge's bound on the minor coordinate of a line (its first or last inside pixel):
// floor(m / d) for d > 0, where m grows by a constant each line, stepped exactly: quotient q,
// remainder r < d, and the step's quotient and remainder. A walker's bound is live on the lines
// whose centre lies within its edge's closed extent (first..last); there the bound lies within the
// edge's own extent, so 32 bits hold it. The NASM run loop steps these in place (fast.inc).
struct EdgeBound {
    int32_t first, last;
    int32_t q, dq;
    uint32_t r, dr, d;  // r < d, dr < d <= 2^31
    template <typename I>  // int32_t or int64_t: the walker's width
    void init(I m, I divisor, I increment);
    void step() {
        q += dq;
        r += dr;  // r < d and dr < d, so no wrap below 2^32
        if (r >= d) {
            r -= d;
            ++q;
        }
    }
    // A bound that stays at q on every line.
    static EdgeBound constant(int32_t q) { return EdgeBound{0, 0, q, 0, 0, 0, 1}; }
};

// A small triangle's row bounds, as EdgeWalker builds them in 32 bits (its box under 64 pixels a
// side): the block asm/walk.asm's triangle_rows_asm takes. The chains come back in `lower` and
// `upper` (room for three each: two bounds and the sentinel), in order of first line.
struct TriangleRowsArgs {
    const Edge* edges;           // the setup's three
    int32_t first, last;         // the rows to walk, first <= last
    int32_t origin_x, origin_y;  // the pixel corner the arithmetic is relative to (at or below the box)
    EdgeBound* lower;
    EdgeBound* upper;
};
// The C++ twin: the bounds of a triangle none of whose edges lies along a row; false, and nothing
// written, where one does (the walker's own build takes those).
bool triangle_rows(const TriangleRowsArgs* a);
#if defined(MODEXLAB_ASM_LOOPS)
extern "C" int triangle_rows_asm(const TriangleRowsArgs* a);
#endif

// The lines whose centre lies within a box's sides lo..hi along them (subpixels; the first at or
// after lo, the last at or before hi: ceil and floor of (p - 128) / 256, as arithmetic shifts),
// inside the clip's clip_lo..clip_hi; first > last where none.
inline void box_lines(int32_t lo, int32_t hi, int32_t clip_lo, int32_t clip_hi, int32_t* first, int32_t* last) {
    constexpr int32_t HALF = int32_t(SUBPIXEL_HALF), ONE = int32_t(SUBPIXEL_ONE);
    *first = (lo - HALF + ONE - 1) >> SUBPIXEL_BITS;
    *last = (hi - HALF) >> SUBPIXEL_BITS;
    if (*first < clip_lo) *first = clip_lo;
    if (*last > clip_hi) *last = clip_hi;
}
// Whether a box is under 64 pixels a side: the walkers' 32-bit builds (EdgeWalker's constructor).
inline bool small_box(int32_t min_x, int32_t min_y, int32_t max_x, int32_t max_y) {
    constexpr int32_t SMALL = 64 << SUBPIXEL_BITS;
    return max_x - min_x < SMALL && max_y - min_y < SMALL;
}

// A run from `line` on (EdgeWalker::run's work, on chains built as the walker builds them): each
// cursor moved to its side's bound live on `line`; the lines from `line` on (at most to `last`)
// where each side keeps that one live bound, or 0 where a side has two live on `line` (a vertex on
// its centre). The cursors and the sentinels stop the scans, as in tightest().
inline int32_t run_from(EdgeBound** lower, EdgeBound** upper, int32_t line, int32_t last) {
    EdgeBound* lo = *lower;
    while (lo->last < line) ++lo;
    *lower = lo;
    EdgeBound* hi = *upper;
    while (hi->last < line) ++hi;
    *upper = hi;
    if (lo[1].first <= line || hi[1].first <= line) return 0;
    int32_t end = last;
    if (lo->last < end) end = lo->last;
    if (hi->last < end) end = hi->last;
    if (lo[1].first - 1 < end) end = lo[1].first - 1;  // (sentinels: first = INT32_MAX)
    if (hi[1].first - 1 < end) end = hi[1].first - 1;
    return end - line + 1;
}

// A set-up triangle's rows as the fast drivers walk them, in one call: EdgeWalker's work on it
// (the rows whose centre lies in its box, inside the clip; the 32-bit chains of a box under 64
// pixels a side) and then its runs (run_from), at most two.
struct TriangleRunsArgs {
    const PolygonSetup* setup;  // a triangle's (edge_count 3)
    int32_t clip_lo, clip_hi;   // the clip's rows, inclusive
    EdgeBound* lower;           // room for three each: the chains
    EdgeBound* upper;
    // Out, where 1 is returned: `lines` rows from `line` between run_lower and run_upper, then
    // next_lines rows between next_lower and next_upper (a triangle's two runs); `lines` 0: no row
    // to walk; next_lines 0: no second run. The pointers of an absent run are null.
    int32_t line, lines;
    EdgeBound* run_lower;
    EdgeBound* run_upper;
    int32_t next_lines;
    EdgeBound* next_lower;
    EdgeBound* next_upper;
};
// True with the runs, or false where EdgeWalker must walk the triangle (its box 64 pixels or more
// a side, an edge along a row, a vertex on a row's centre between two edges of a side), the
// outputs and the chains then unspecified. (The fast drivers' NASM routine fast_triangle_asm does
// this after the setup: its twin calls this.)
bool triangle_runs(TriangleRunsArgs* a);

class EdgeWalker {
public:
    EdgeWalker(const PolygonSetup& s, Axis axis, const ClipRect& clip);
    // The same with the axis known where it is written: inline, no call and no test of the axis (a
    // fast driver's walker; the constructor above is this out of line).
    template <Axis AXIS>
    struct Along {};
    template <Axis AXIS>
    EdgeWalker(const PolygonSetup& s, Along<AXIS>, const ClipRect& clip) : axis_(AXIS) {
        init<AXIS == Axis::Rows>(s, clip);
    }

    // The next non-empty span, in increasing row (or column) order; false when done. (Inline: it
    // runs once a line, and the fast mappers' drivers want it in their loop.)
    bool next(Span* out) {
        while (line_ <= last_line_) {
            const int32_t line = line_++;
            int32_t lo = tightest<true>(&lower_cur_, line, minor_lo_);
            int32_t hi = tightest<false>(&upper_cur_, line, minor_hi_);
            if (lo > hi) continue;
            if (axis_ == Axis::Rows) *out = Span{lo, line, hi - lo + 1};
            else *out = Span{line, lo, hi - lo + 1};
            return true;
        }
        return false;
    }

    // A run: the lines from the current one on where each side has exactly one live bound (no
    // vertex on a line's centre in between), the clip not applied. Returns its length, with its
    // first line and the two bounds, which the caller steps once a line and then skips the run; 0
    // when the current line has two live bounds on a side (walk it with next()) or the walk is done.
    int32_t run(int32_t* line, EdgeBound** lower, EdgeBound** upper) {
        if (line_ > last_line_) return 0;
        const int32_t lines = run_from(&lower_cur_, &upper_cur_, line_, last_line_);
        if (lines == 0) return 0;
        *line = line_;
        *lower = lower_cur_;
        *upper = upper_cur_;
        return lines;
    }
    void skip(int32_t lines) { line_ += lines; }
    // The clip rectangle across a line, inclusive.
    int32_t minor_lo() const { return minor_lo_; }
    int32_t minor_hi() const { return minor_hi_; }

private:
    using Bound = EdgeBound;
    // The constructors' work.
    template <bool ROWS>
    void init(const PolygonSetup& s, const ClipRect& clip) {
        constexpr bool rows = ROWS;
        // (the box is within setup's range, 2^22 subpixels: 32 bits hold it and its sides)
        const int32_t min_x = int32_t(s.min_x), min_y = int32_t(s.min_y), max_x = int32_t(s.max_x), max_y = int32_t(s.max_y);
        int32_t first, last;
        box_lines(rows ? min_y : min_x, rows ? max_y : max_x, rows ? clip.y0 : clip.x0, (rows ? clip.y1 : clip.x1) - 1, &first, &last);
        minor_lo_ = rows ? clip.x0 : clip.y0;
        minor_hi_ = (rows ? clip.x1 : clip.y1) - 1;
        line_ = first;
        last_line_ = first - 1;  // empty (and the bounds never looked at) until proven otherwise
        if (first > last) return;
        // A polygon whose box is under 64 pixels a side is walked in 32 bits, its coordinates taken
        // from the pixel corner at or below its box (every product and numerator below 2^30; on
        // i686 64-bit products and divisions are several instructions or a libgcc call each). The
        // bounds come out the same: moving the polygon and the pixel grid by whole pixels moves
        // each bound's quotient by as many pixels and leaves its remainder.
        // (a triangle by its own build: most polygons of a mesh are small triangles)
        if (small_box(min_x, min_y, max_x, max_y)) {
            const int32_t ox = min_x >> SUBPIXEL_BITS, oy = min_y >> SUBPIXEL_BITS;  // (floors)
            if (s.edge_count == 3 && rows)
                build_triangle<true>(s, first, last, ox, oy);
            else if (s.edge_count == 3)
                build_triangle<false>(s, first, last, ox, oy);
            else
                build<int32_t>(s, first, last, ox, oy);
        } else {
            build<int64_t>(s, first, last, 0, 0);
        }
    }

    // Sorts by first line, then seals the list with a sentinel that is never live and never binds.
    static void seal(Bound* list, int32_t count, int32_t never);
    // The bounds of lines first..last (clipped), in integers of type I, coordinates taken relative
    // to the pixel (origin_x, origin_y).
    template <typename I>
    void build(const PolygonSetup& s, I first, I last, int64_t origin_x, int64_t origin_y);
    // The same for a triangle in 32 bits (its box under 64 pixels a side), written for the mesh's
    // small triangles: the axis fixed, one division a quotient and its remainder, the chains put in
    // order as they are built.
    template <bool ROWS>
    void build_triangle(const PolygonSetup& s, int32_t first, int32_t last, int32_t origin_x, int32_t origin_y);
    // The tightest of `bound` and the chain's bounds live on `line`; steps those to the next line.
    // Every walked line's centre lies within some edge of each chain, so the cursor stops at a live
    // bound, never at the sentinel; a second one is live only where a vertex lies on the centre.
    template <bool LOWER>
    static int32_t tightest(Bound** cursor, int32_t line, int32_t bound) {
        Bound* b = *cursor;
        while (b->last < line) ++b;
        *cursor = b;
        for (; b->first <= line; ++b) {
            if (LOWER ? b->q > bound : b->q < bound) bound = b->q;
            b->step();
        }
        return bound;
    }

    Axis axis_;
    int32_t line_, last_line_;     // current and last major coordinate (row y, or column x)
    int32_t minor_lo_, minor_hi_;  // the clip rectangle across a line, inclusive
    // Each side's bounds form one chain (the polygon is convex and winds once): by first line,
    // the spent ones behind the cursor, at most two live on a line (where a vertex lies exactly on
    // the line's centre) and those two next to each other.
    Bound lower_[MAX_POLYGON_VERTICES + 1];  // first inside pixel: lower bounds on the line
    Bound upper_[MAX_POLYGON_VERTICES + 1];  // last inside pixel: upper bounds
    Bound* lower_cur_ = lower_;
    Bound* upper_cur_ = upper_;
};

}  // namespace raster
