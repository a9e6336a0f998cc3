// The kernel's current 3D scene (a version 2 scene file): loaded from the file table, its textures
// prepared once, its frames built and drawn into Mode X pages.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/scene/frame.h"
#include "kernel/scenes.h"

namespace worlds {

// Parses a version 2 scene text (its texture files found in the file table) and makes it the
// current one; loads its palette into the DAC when a graphics mode is on. On failure no 3D scene
// is loaded (the parser works in place) and `error` says why.
bool load(const char* name, const uint8_t* text, size_t length, raster::ParseError* error);
bool loaded();
const raster::World& world();
const char* name();

struct FrameResult {
    raster::FrameStats frame;
    scenes::RenderResult render;
    uint64_t ticks_geometry;
};

// The budget auto draws the frames to: the scene's, or the one the `budget` command set, until it
// is cleared (nullptr) or another 3D scene is loaded.
void set_budget(const raster::Budget* override);
raster::Budget budget();
bool budget_overridden();

// Builds frame `n` and draws it with `mapper` into `page` through `surface`; with a probe, times
// the drawing's phases (the probe's clock must be set); with a watch, the drawing may stop early.
FrameResult render(int32_t n, const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant,
                   raster::Probe* probe = nullptr, const raster::Watch* watch = nullptr);

}  // namespace worlds
