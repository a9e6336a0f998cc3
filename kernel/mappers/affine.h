// affine: u and v linear in screen space (the affine planes), stepped in 16.16 from each span's
// first pixel centre; any texture, both walkers, C++ only.
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"

namespace raster {

void affine_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);
ErrorBound affine_bound(const BoundContext& c, const Vertex* vertices, int count);

}  // namespace raster
