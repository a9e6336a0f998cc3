// Chris Hecker's subdividing perspective mapper with the sbb/adc step-table loop (Game Developer
// 1995-96): the polygon driver for the registry.
#pragma once

#include "kernel/core/mapper.h"

namespace raster::hecker {

SetupStatus draw(const DrawContext& c, const Vertex* vertices, int count);

}  // namespace raster::hecker
