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

}  // namespace raster::quake
