// Mats Byggmastar's fatmap.txt mappers (1996): the polygon drivers for the registry.
#pragma once

#include "kernel/core/mapper.h"

namespace raster::fatmap {

SetupStatus draw_256(const DrawContext& c, const Vertex* vertices, int count);  // fatmap-256, fatmap-256-16
SetupStatus draw_lut(const DrawContext& c, const Vertex* vertices, int count);  // fatmap-lut

}  // namespace raster::fatmap
