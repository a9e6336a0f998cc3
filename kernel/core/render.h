// Drawing polygons: setup, the walker for the axis, the mapper per span, into a target.
#pragma once

#include <stdint.h>

#include "kernel/core/choice.h"
#include "kernel/core/mapper.h"
#include "kernel/scene/scene.h"
#include "kernel/core/setup.h"
#include "kernel/core/surface.h"

namespace raster {

// Draws one convex polygon. Returns the setup status; nothing is drawn (and the polygon counts as
// rejected) unless it is Ok, the mapper walks `axis`, accepts the texture and can draw into the
// target (mapper_targets). `auto` draws it with the mapper choose_mapper picks for the budget.
SetupStatus draw_polygon(const Vertex* vertices, int count, const Texture& tex, const Mapper& mapper, Axis axis,
                         Target& target, RenderStats* stats, Variant variant = Variant::Twin, const Budget& budget = DEFAULT_BUDGET);

// Draws every polygon of the scene in order; with a probe, times the phases (probe.h). Screen-space
// scenes have no budget line: auto takes the default.
RenderStats render_scene(const Scene& scene, const Texture& tex, const Mapper& mapper, Axis axis, Target& target,
                         Variant variant = Variant::Twin, Probe* probe = nullptr);

}  // namespace raster
