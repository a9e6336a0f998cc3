// The accuracy metrics of docs/accuracy.md: a mapper's picture against the reference's.
#pragma once

#include <stdint.h>

#include "qemu/accuracy/reference.h"
#include "kernel/core/texture.h"

namespace raster {

struct AccuracyMetrics {
    uint32_t reference_pixels = 0;  // pixels the reference covers
    uint32_t drawn_pixels = 0;      // pixels the mapper drew
    uint32_t overdraw = 0;          // drawn, not covered by the reference
    uint32_t gaps = 0;              // covered by the reference, not drawn
    uint32_t overlaps = 0;          // drawn more often than the reference covers them (a mesh: twice or more)
    uint32_t compared = 0;          // covered by both: where texel errors are measured
    uint32_t max_texel_error = 0;   // Chebyshev distance in texels, wrap-aware
    double mean_texel_error = 0;
    uint32_t exact = 0;             // compared pixels with the reference's texel
    uint32_t within_one = 0;        // compared pixels at most one texel off
    uint32_t index_differs = 0;     // pixels (covered by either) whose palette index differs
    uint32_t union_pixels = 0;      // pixels covered by either
};

// The distance between texel columns (rows) a and b of a texture `size` wide (high): with repeat,
// 0 and size-1 are one texel apart.
uint32_t texel_distance(int32_t a, int32_t b, int32_t size, Wrap wrap);

// The pieces of the metrics, for measures built pixel by pixel elsewhere (3D frames): a compared
// pixel with texel error e (the caller sets mean_texel_error = *error_sum / compared at the end);
// a pixel the reference covers rc times and the mapper draws dc times.
void add_texel_error(AccuracyMetrics& m, uint32_t e, uint64_t* error_sum);
void add_coverage(AccuracyMetrics& m, uint32_t rc, uint32_t dc);
// Adds m into total (counts summed, the maximum kept, the mean weighted by compared pixels).
void accumulate(AccuracyMetrics& total, const AccuracyMetrics& m);

// Texture size and wrap give the distance: with repeat, 0 and width-1 are one texel apart.
AccuracyMetrics compare_to_reference(const PixelImage& reference, const PixelImage& drawn, int32_t tex_width,
                                     int32_t tex_height, Wrap wrap);

}  // namespace raster
