// The accuracy metrics of docs/accuracy.md: a mapper's picture against the reference's.
#pragma once

#include <stdint.h>

#include <vector>

#include "kernel/core/texture.h"
#include "qemu/accuracy/reference.h"

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
    uint32_t p999_texel_error = 0;  // the 99.9th percentile (nearest rank) of the compared pixels' errors
    // The footprint error: the texel error divided by max(1, the pixel's footprint in texels):
    // screen pixels under minification, texels under magnification.
    double max_footprint_error = 0;
    double mean_footprint_error = 0;
    double p999_footprint_error = 0;
    // Compared pixels whose wrap-aware texel error is half the texture's period (with repeat): a
    // larger error folds into it, so there the footprint error is a lower bound.
    uint32_t folded = 0;
    uint32_t exact = 0;             // compared pixels with the reference's texel
    uint32_t within_one = 0;        // compared pixels at most one texel off
    uint32_t index_differs = 0;     // pixels (covered by either) whose palette index differs
    uint32_t union_pixels = 0;      // pixels covered by either

    // Every compared pixel's errors, for the means and percentiles (finish_metrics).
    std::vector<uint32_t> texel_errors;
    std::vector<float> footprint_errors;
};

// The distance between texel columns (rows) a and b of a texture `size` wide (high): with repeat,
// 0 and size-1 are one texel apart.
uint32_t texel_distance(int32_t a, int32_t b, int32_t size, Wrap wrap);

// The texel error of a compared pixel: the Chebyshev distance between the texel read (tu, tv) and
// the reference's (ru, rv), wrap-aware; *folded when it is half a period in either direction.
uint32_t texel_error(int32_t ru, int32_t rv, int32_t tu, int32_t tv, int32_t tex_width, int32_t tex_height, Wrap wrap, bool* folded);

// The footprint error of a compared pixel: its texel error e over max(1, the pixel's footprint).
inline double footprint_error(uint32_t e, double footprint) { return double(e) / (footprint > 1 ? footprint : 1.0); }

// The pieces of the metrics, for measures built pixel by pixel elsewhere (3D frames): a compared
// pixel with texel error e at a pixel whose footprint is `footprint` texels; a pixel the reference
// covers rc times and the mapper draws dc times. finish_metrics() then sets the means and
// percentiles from the samples.
void add_texel_error(AccuracyMetrics& m, uint32_t e, double footprint, bool folded);
void add_coverage(AccuracyMetrics& m, uint32_t rc, uint32_t dc);
void finish_metrics(AccuracyMetrics& m);
// Adds m into total: counts summed, the largest errors kept, the samples joined (finish_metrics
// then sets the means and percentiles); accumulate does both.
void merge(AccuracyMetrics& total, const AccuracyMetrics& m);
void accumulate(AccuracyMetrics& total, const AccuracyMetrics& m);

// One picture against the reference's (whose footprints it reads; 1 where the reference has none).
AccuracyMetrics compare_to_reference(const PixelImage& reference, const PixelImage& drawn, int32_t tex_width,
                                     int32_t tex_height, Wrap wrap);

}  // namespace raster
