// The exact reference renderer (docs/accuracy.md): every pixel of the bounding box tested with
// covers(), every covered pixel textured with perspective_texel(). Slow and plain on purpose.
#pragma once

#include <stdint.h>

#include "kernel/scene/frame.h"
#include "kernel/scene/scene.h"
#include "kernel/core/setup.h"
#include "kernel/core/texture.h"

namespace raster {

// Per-pixel results, in caller-owned buffers of width x height entries each (row-major).
// The same shape describes what a mapper drew (qemu/measure.cpp fills it), so the two compare.
struct PixelImage {
    int32_t width = 0, height = 0;
    uint8_t* index = nullptr;     // palette index: the last polygon drawn wins
    uint8_t* coverage = nullptr;  // how many polygons drew the pixel, saturating at 255
    int32_t* tu = nullptr;        // texel column and row read for the pixel (after wrap or clamp)
    int32_t* tv = nullptr;
    float* footprint = nullptr;   // the reference's only: texel_footprint at the pixel (null: not wanted)
};

void clear_pixel_image(PixelImage& img, uint8_t background);

// Renders one polygon into img. Returns the setup status (nothing drawn unless Ok).
SetupStatus reference_polygon(const Vertex* vertices, int count, const Texture& tex, PixelImage& img);

// Renders every polygon of the scene in order; returns how many were rejected (not Ok and not degenerate).
int32_t reference_scene(const Scene& scene, const Texture& tex, PixelImage& img);

// The reference's picture of the frame (reference_polygon for each polygon in order, with its
// object's texture); returns how many polygons it rejected.
int32_t reference_frame(const Frame& frame, const TextureSet& textures, PixelImage& img);

}  // namespace raster
