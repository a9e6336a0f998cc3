// Quake's d_draw16.s as id shipped it: the loop's argument block, the twin at the x87's single
// precision with chop, the NASM loop (asm/quake_draw16.asm), its driver and bound.
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"

namespace raster {

// quake-d_draw16: one span, all its segments. The planes are floats, as Quake's d_sdivzstepu and
// the others are; the loop runs them under Quake's single_cw (24-bit precision, chop).
struct QuakeDraw16Args {
    uint8_t* dst;             // the span's first pixel; count pixels to the right
    int32_t count;            // >= 1
    int32_t x, y;             // the span's first pixel on screen (Quake's u, v)
    const uint8_t* texels;    // the texture (Quake's cacheblock), pitch bytes a row (cachewidth)
    int32_t pitch;
    int32_t sadjust_16_16, tadjust_16_16;  // added after s/z * z
    int32_t bbextents, bbextentt;          // size * 65536 - 1
    float s_origin, s_stepu, s_stepv;      // s/z at pixel (0, 0) and per pixel across and down
    float t_origin, t_stepu, t_stepv;
    float z_origin, z_stepu, z_stepv;      // 1/z
};
Loop quake_draw16_loop;

Check check_quake_draw16;

}  // namespace raster

extern "C" {
raster::Loop quake_draw16_loop_asm;
}

// The x87 at 24-bit precision with chop on doubles (the twin's arithmetic; its derivation in
// quake_draw16.cpp): operands of at most 24 significant bits, each result as the x87 gives it.
namespace raster::single_chop {
double chop24(double x);
double mul(double a, double b);
double add(double a, double b);
double quotient_65536(double zi);
}  // namespace raster::single_chop

namespace raster::quake {

SetupStatus draw_d_draw16(const DrawContext& c, const Vertex* vertices, int count);  // quake-d_draw16
// Its error bound: the chords of persp-subdiv-16 with d_draw16.s's arithmetic (docs/bounds.md).
ErrorBound bound_d_draw16(const BoundContext& c, const Vertex* vertices, int count);

}  // namespace raster::quake
