// The texture mappers written in C++ so far, in one registry. A mapper draws one span (a row or a
// column run of pixels) of a set-up polygon; the walker and the target decide where.
#pragma once

#include <stdint.h>

#include "kernel/lib/words.h"
#include "kernel/raster/setup.h"
#include "kernel/raster/texture.h"
#include "kernel/raster/walk.h"

namespace raster {

// Draws span `s` (in `axis` direction) starting at dst, `stride` bytes between pixels.
using SpanFn = void (*)(const PolygonSetup& setup, const Texture& tex, Axis axis, const Span& s, uint8_t* dst, int32_t stride);

struct Mapper {
    const char* name;
    const char* promise;  // what it promises about accuracy
    SpanFn span;
};

// affine: u and v linear in screen space, stepped in 16.16 from their value at each span's first
//         pixel centre; texel = floor. Exact coverage; texel error grows with depth variation.
// exact:  perspective_texel() at every pixel: equal to the reference, pixel for pixel.
void affine_span(const PolygonSetup& setup, const Texture& tex, Axis axis, const Span& s, uint8_t* dst, int32_t stride);
void exact_span(const PolygonSetup& setup, const Texture& tex, Axis axis, const Span& s, uint8_t* dst, int32_t stride);

extern const Mapper MAPPERS[];
extern const int MAPPER_COUNT;
const Mapper* find_mapper(lib::StrView name);

}  // namespace raster
