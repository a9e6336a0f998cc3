// Quake's perspective span drawer (WinQuake d_scan.c, d_draw16.s): the polygon drivers, the loop's
// argument block, the twin and the NASM loop (asm/quake.asm).
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"

namespace raster {

// quake-subdiv16 / quake-subdiv8: one span, all its segments (d_scan.c's algorithm; the NASM loop
// starts the x87 divide for the next segment's end before drawing the current segment).
struct QuakeArgs {
    uint8_t* dst;             // the span's first pixel; count pixels to the right
    int32_t count;            // >= 1
    int32_t x, y;             // the span's first pixel on screen (Quake's du, dv)
    const uint8_t* texels;    // the texture (Quake's surface cache), pitch bytes a row
    int32_t pitch;
    int32_t sadjust_16_16, tadjust_16_16;  // added after s/z * z
    int32_t bbextents, bbextentt; // size * 65536 - 1
    int32_t shift;            // log2 of the segment length: 4 or 3
    int32_t reserved;
    double s_origin, s_stepu, s_stepv;  // s/z at pixel (0, 0) and per pixel across and down
    double t_origin, t_stepu, t_stepv;
    double z_origin, z_stepu, z_stepv;  // 1/z
    double s_stepu_n, t_stepu_n, z_stepu_n;  // the steps times the segment length
};
Loop quake_span_loop;

Check check_quake;

}  // namespace raster

extern "C" {
raster::Loop quake_span_loop_asm;
}

namespace raster::quake {

SetupStatus draw16(const DrawContext& c, const Vertex* vertices, int count);  // quake-subdiv16
SetupStatus draw8(const DrawContext& c, const Vertex* vertices, int count);   // quake-subdiv8
// Their error bounds: the chords of persp-subdiv-16 and -8 with Quake's arithmetic (the chop, the
// clamps, the floored steps, its own evaluation of s/z * z).
ErrorBound bound16(const BoundContext& c, const Vertex* vertices, int count);
ErrorBound bound8(const BoundContext& c, const Vertex* vertices, int count);

// What the Quake drivers settle for a polygon before its spans: the whole-period shifts (sadjust,
// tadjust) and extents in 16.16, and s/z, t/z, 1/z at pixel (0, 0) and per pixel across and down
// (D_CalcGradients), each as {origin, stepu, stepv}.
struct Gradients {
    int32_t sadjust_16_16, tadjust_16_16, bbextents, bbextentt;
    double s[3], t[3], z[3];
};
// Whether a Quake driver takes the polygon (the texture shift, |u| and |v| within 32000); then its
// setup (c.setup, or *own set up here) and its gradients.
SetupStatus prepare(const DrawContext& c, const Vertex* vertices, int count, PolygonSetup* own, const PolygonSetup** setup, Gradients* g);

// Each span of the polygon on our walker to the context's loop: the block's dst, count, x and y set
// a span at a time, the rest as the driver filled it.
template <typename Args>
void draw_spans(const DrawContext& c, const PolygonSetup& setup, Args& a) {
    EdgeWalker walker(setup, Axis::Rows, c.target.clip);
    setup_done(c);
    Span span;
    while (walker.next(&span)) {
        a.dst = c.target.base + span.y * c.target.pitch + span.x;
        a.count = span.count;
        a.x = span.x;
        a.y = span.y;
        emit(c, &a, 1, uint32_t(span.count));
    }
}

// A Quake loop's arithmetic, for its bound (docs/bounds.md, "Quake's spans"): in texels but `op`.
struct Rounding {
    double op;         // relative error of one x87 result (a sum into s/z, t/z, 1/z, the divide, the product)
    int inputs;        // roundings of the inputs besides the loop's own (the planes stored as floats)
    double low_clamp;  // the segment ends' low clamp
    double per_step;   // how far one step may be from the chord's slope
};
// The chords of persp-subdiv-n with that arithmetic (segments_bound).
ErrorBound bound_with(const BoundContext& c, const Vertex* vertices, int count, int n, const Rounding& r);

}  // namespace raster::quake
