// Drawing the named test patterns into a VGA page of the current mode.
#pragma once

#include "kernel/scene/pattern.h"

namespace patterns {

// Mode X: one map-mask change per plane, then that plane's pixels of the page; mode 13h: linear.
void draw(raster::Pattern p, int page);

}  // namespace patterns
