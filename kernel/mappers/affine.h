// affine: u and v linear in screen space (the affine planes), stepped in 16.16 from each span's
// first pixel centre; any texture, both walkers, C++ only.
#pragma once

#include <stdint.h>

#include "kernel/core/fixed.h"
#include "kernel/core/mapper.h"

namespace raster {

void affine_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);

// A texture coordinate in 16.16 at a span's start. With repeat, it is first reduced modulo the
// texture size (same texels, and far from the 16.16 limit of +-32768 texels); with clamp it
// saturates, which clamps to the same edge texel.
Fixed16_16 start_coordinate(double t, int32_t size, Wrap wrap);

}  // namespace raster
