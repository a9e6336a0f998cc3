// Our fastest affine mappers (256 x 256 repeating textures): polygon drivers for the registry.
#pragma once

#include "kernel/core/mapper.h"

namespace raster::fast {

SetupStatus draw_rows(const DrawContext& c, const Vertex* vertices, int count);     // fast-affine
SetupStatus draw_columns(const DrawContext& c, const Vertex* vertices, int count);  // fast-columns

}  // namespace raster::fast
