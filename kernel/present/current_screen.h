// The kernel's current screen-space scene (a version 1 scene file): uploaded over COM1, parsed by the
// portable parser, its texture generated; and drawing it into a page (present.h).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/core/policy.h"
#include "kernel/core/render.h"
#include "kernel/present/present.h"
#include "kernel/scene/scene.h"

namespace current_screen {

// Parses a version 1 scene text and makes it the current one (its texture generated), its buffers
// sized to it (the 3D scene's given back first: it is then not loaded). On failure the previous
// scene stays and `error` says why (parser errors carry a line; a lack of memory line 0).
bool load(const char* text, size_t length, raster::ParseError* error);

bool loaded();
const raster::Scene& scene();

// The kernel's texture for the current scene (with its bordered copy).
const raster::Texture& texture();

// Clears the surface to 0, draws the scene with `mapper`, and blits (unless drawn in place); with a
// watch, the drawing may stop early (core/render.h).
present::RenderResult render(const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant,
                             const raster::Watch* watch = nullptr);

}  // namespace current_screen
