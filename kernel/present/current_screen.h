// The kernel's current screen-space scene: uploaded over COM1, parsed by the portable parser, its
// texture generated; and rendering it into a Mode X page through one of three surfaces.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/core/policy.h"
#include "kernel/core/render.h"
#include "kernel/scene/scene.h"

namespace scenes {

// Parses a version 1 scene text and makes it the current one (its texture generated). On failure
// the previous scene stays and `error` says why (parser errors carry a line).
bool load(const char* text, size_t length, raster::ParseError* error);

bool loaded();
const raster::Scene& scene();

struct RenderResult {
    raster::RenderStats stats;
    uint64_t ticks_clear, ticks_draw, ticks_blit;
    bool used_asm;  // the NASM loop ran (else the C++ twin)
};

// The kernel's texture for the current scene (with its bordered copy).
const raster::Texture& texture();

// Clears the surface to 0, draws the scene with `mapper`, and blits (unless drawn in place); with a
// watch, the drawing may stop early (core/render.h).
RenderResult render(const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant,
                    const raster::Watch* watch = nullptr);

// The same for any drawing: clears the surface, calls draw(target, axis), blits; times each step.
using DrawFn = raster::RenderStats (*)(void* ctx, raster::Target& target, raster::Axis axis, raster::Variant variant);
RenderResult render_with(const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant, DrawFn draw, void* ctx);

}  // namespace scenes
