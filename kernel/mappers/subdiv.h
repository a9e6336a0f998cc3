// persp-subdiv-N: exact u, v every N pixels (N = 4, 8, 16, 32) and at each span's last pixel,
// affine in 16.16 between; any texture, both walkers, C++ only.
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"

namespace raster {

template <int N>
void subdiv_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);
template <int N>
ErrorBound subdiv_bound(const BoundContext& c, const Vertex* vertices, int count);

}  // namespace raster
