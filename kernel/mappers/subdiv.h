// persp-subdiv-N: exact u, v every N pixels (N = 4, 8, 16, 32) and at each span's last pixel,
// affine in 16.16 between; any texture, both walkers; the loop in NASM (asm/subdiv.asm). constant-depth is the same with
// one segment a span (N = SPAN_LONG): exact along lines of constant depth. persp-adaptive-B: runs
// as long as the bound keeps them within B footprints (B = QUARTERS / 4).
#pragma once

#include <stdint.h>

#include "kernel/core/bound.h"
#include "kernel/core/footprint.h"
#include "kernel/core/mapper.h"
#include "kernel/core/spanline.h"
#include "kernel/core/spread.h"

namespace raster {

// Longer than any span: one segment, exact at the span's first and last pixels.
constexpr int SPAN_LONG = 1 << 24;

// The inner loop of persp-subdiv-N and constant-depth, one piece between exact points: count
// pixels, each the texel at (floor(u), floor(v)) wrapped or clamped as texel() does, then u += du,
// v += dv in 16.16 (wrapping adds). A size's mask is size - 1 for a power of two, else 0: the NASM
// loop then wraps by `and` instead of idiv (the same texel: two's complement).
struct StepArgs {
    uint8_t* dst;
    int32_t stride;
    int32_t count;
    const uint8_t* texels;
    int32_t width, height;
    int32_t clamp;  // 0: repeat, 1: clamp
    uint32_t width_mask, height_mask;
    int32_t u_16_16, v_16_16, du_16_16, dv_16_16;
};
Loop step_loop;
Check check_step;

template <int N>
void subdiv_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);
template <int N>
ErrorBound subdiv_bound(const BoundContext& c, const Vertex* vertices, int count);

// The bound of any mapper whose u and v follow, along each span of its walker, chords between the
// exact values at pixels 0, N, 2N, ... and the last (persp-subdiv-N, constant-depth, Quake's), with
// its arithmetic: how far the drawn coordinates may be from the chord, and whether they wrap.
struct SegmentArithmetic {
    bool wraps = true;                 // 16.16 that may wrap (fits_16_16 must hold); false: clamped, nothing to check
    double fixed = HALF_ULP_16_16;     // texels at every pixel (ours: half a 16.16 unit at the start)
    double per_step = HALF_ULP_16_16;  // texels each step from the segment's first pixel adds (ours: half a unit)
    double chord = 1e300;              // |t1 - t0| between a chord's exact ends must stay below this (fast-subdiv: 32767)
    constexpr double at(double steps) const { return fixed + steps * per_step; }
};
ErrorBound segments_bound(const BoundContext& c, const Vertex* vertices, int count, double N, const SegmentArithmetic& arithmetic);
// Its bound on one span, from the span's line (bound_by_spans' span_bound_of): clears *fits where
// 16.16 may not hold it.
double segments_span_bound(const BoundContext& c, const SpanLine& line, bool* fits, double N, const SegmentArithmetic& arithmetic);
// Whether 16.16 holds chords of up to `steps` steps, each of less than `chord` texels between its
// exact ends, anywhere on the polygon (the whole-polygon bounds).
bool chords_fit(const BoundContext& c, PolygonSpread& p, const PolygonSetup& s, double steps, double chord);

// persp-adaptive-B's run from pixel k of the span (line l): the longest, up to ADAPTIVE_LONGEST
// pixels and the span's end, whose chord chords_bound keeps within `budget` footprints; one pixel
// where none is.
constexpr int32_t ADAPTIVE_LONGEST = 256;
int32_t adaptive_run(const SpanLine& l, const ChordTerms& terms, int32_t k, double budget);
template <int QUARTERS>
void adaptive_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);
template <int QUARTERS>
ErrorBound adaptive_bound(const BoundContext& c, const Vertex* vertices, int count);

}  // namespace raster

extern "C" {
raster::Loop step_loop_asm;
}
