// Drawing polygons: setup, the walker for the axis, the mapper per span, into a target.
#pragma once

#include <stdint.h>

#include "kernel/raster/mappers.h"
#include "kernel/raster/scene.h"
#include "kernel/raster/setup.h"
#include "kernel/raster/surface.h"

namespace raster {

struct RenderStats {
    uint32_t polygons = 0;   // set up and walked
    uint32_t skipped = 0;    // degenerate (zero area): nothing to draw
    uint32_t rejected = 0;   // not convex, too many vertices, out of range
    uint32_t spans = 0;
    uint32_t pixels = 0;
};

// Draws one convex polygon. Returns the setup status; nothing is drawn (and the polygon counts as
// rejected) unless it is Ok, the target can take spans along `axis` (not rows on a planar
// target), the mapper walks that axis and accepts the texture.
SetupStatus draw_polygon(const Vertex* vertices, int count, const Texture& tex, const Mapper& mapper, Axis axis,
                         Target& target, RenderStats* stats, Variant variant = Variant::Twin);

// Draws every polygon of the scene in order.
RenderStats render_scene(const Scene& scene, const Texture& tex, const Mapper& mapper, Axis axis, Target& target,
                         Variant variant = Variant::Twin);

}  // namespace raster
