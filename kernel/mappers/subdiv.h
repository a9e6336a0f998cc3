// persp-subdiv-N: exact u, v every N pixels (N = 4, 8, 16, 32) and at each span's last pixel,
// affine in 16.16 between; any texture, both walkers, C++ only. constant-depth is the same with
// one segment a span (N = SPAN_LONG): exact along lines of constant depth.
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"

namespace raster {

// Longer than any span: one segment, exact at the span's first and last pixels.
constexpr int SPAN_LONG = 1 << 24;

template <int N>
void subdiv_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);
template <int N>
ErrorBound subdiv_bound(const BoundContext& c, const Vertex* vertices, int count);

}  // namespace raster
