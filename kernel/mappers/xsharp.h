// X-Sharp's texture mappers (Black Book ch. 56-58): polygon drivers for the registry.
#pragma once

#include "kernel/core/mapper.h"

namespace raster::xsharp {

SetupStatus draw_dda(const DrawContext& c, const Vertex* vertices, int count);      // listing 57.1
SetupStatus draw_row_out(const DrawContext& c, const Vertex* vertices, int count);  // listing 57.2 / 58.1
SetupStatus draw_column(const DrawContext& c, const Vertex* vertices, int count);   // listing 58.4, X-Sharp 22

}  // namespace raster::xsharp
