// Our fastest affine mappers (256 x 256 repeating textures): span functions for the registry.
#pragma once

#include "kernel/raster/mappers.h"

namespace raster::fast {

void row_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);     // fast-affine
void column_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);  // fast-columns

}  // namespace raster::fast
