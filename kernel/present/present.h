// Presenting a drawing: the surface a mapper draws through (a RAM surface, linear or planar, or the
// VGA page itself) cleared and handed over as a target, then blitted to the page, each step timed.
#pragma once

#include <stdint.h>

#include "kernel/core/policy.h"
#include "kernel/core/render.h"

namespace present {

struct RenderResult {
    raster::RenderStats stats;
    uint64_t ticks_clear, ticks_draw, ticks_blit;
    bool used_asm;  // the NASM loop ran (else the C++ twin)
};

// One drawing between begin and finish: the target to draw into and the axis the mapper walks.
struct Canvas {
    raster::Target target;
    raster::Axis axis;
    raster::Surface surface;
    int page;
    bool used_asm;
    uint64_t t0, t1;  // clock at begin, and when the target was ready
};

// Clears `surface` (for page `page`) to 0 and returns its target; the drawing's time starts here.
Canvas begin(const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant);
// Ends the drawing with its stats: blits a RAM surface to the page, and returns the times of the
// clear, the drawing and the blit.
RenderResult finish(const Canvas& canvas, const raster::RenderStats& stats);

// auto's candidate lists, the kernel's one set: the screen scene's budget and the world's name it
// (Budget::lists), so that a scene's load builds them once (prepare_choice).
raster::ChoiceLists* choice_lists();

}  // namespace present
