// Quake's perspective span drawer (WinQuake d_scan.c, d_draw16.s): the polygon drivers for the registry.
#pragma once

#include "kernel/core/mapper.h"

namespace raster::quake {

SetupStatus draw16(const DrawContext& c, const Vertex* vertices, int count);  // quake-subdiv16
SetupStatus draw8(const DrawContext& c, const Vertex* vertices, int count);   // quake-subdiv8

}  // namespace raster::quake
