// The differential check of NASM loops that program the VGA: the loop draws into page 2 of the
// real Mode X memory, the twin into RAM planes, and the planes are read back and compared.
#pragma once

#include "kernel/core/selftest.h"

namespace vga_selftest {

// Needs Mode X on; draws over rows of page 2.
raster::LoopCheck check(const raster::Mapper& mapper, uint32_t seed, uint32_t cases, uint8_t* texels);

}  // namespace vga_selftest
