// Random polygons of every class of extreme, and a mapper drawing many of them: the same sequence
// and the same counts on the host (tests/unit/kernel/core/stability_test.cpp, under the sanitizers) and in the
// kernel (the `fuzz` command, between guard pages). Portable: no libm, its own random numbers.
// docs/fuzzing.md lists the classes.
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"
#include "kernel/core/random.h"
#include "kernel/core/render.h"
#include "kernel/core/setup.h"
#include "kernel/core/texture.h"

namespace raster {

constexpr int MAX_FUZZ_CORNERS = 12;

// The classes of extreme polygons (docs/fuzzing.md), in the share of the mixture next() draws.
enum class PolygonClass : uint8_t {
    Convex,       // 3 to 12 corners, 1 to 1024 pixels across, a third squashed to 1/256 (24/64)
    Sliver,       // slivers and needles: 1/256 to 4 pixels thick, 1 to 1024 long, any angle (12/64)
    Tiny,         // inside one pixel (8/64)
    Huge,         // corners at the coordinate limits (1/64)
    Degenerate,   // collinear or repeated corners (4/64)
    Perspective,  // w from near 2^-16 to near 2^24 across one quad (8/64)
    Anywhere,     // 3 to 8 corners anywhere within the limits (5/64)
    Beyond,       // one value beyond its limit or not finite: refused (2/64)
};
constexpr int POLYGON_CLASS_COUNT = 8;
const char* polygon_class_name(PolygonClass c);  // "convex", "sliver", ...

class RandomPolygons {
public:
    // coordinate_limit: the setup's +-16384 pixels, or the classics' +-8192; texture_inside > 0:
    // texture coordinates within 0..texture_inside (for mappers that cannot wrap)
    RandomPolygons(uint32_t seed, double coordinate_limit, int32_t texture_inside)
        : rng_(seed), limit_(coordinate_limit), inside_(texture_inside) {}
    // The next polygon's corners into out (MAX_FUZZ_CORNERS); returns their count. From the
    // mixture, or of one class.
    int next(Vertex* out);
    int next(Vertex* out, PolygonClass c);

private:
    Random rng_;
    double limit_;
    int32_t inside_;
};

// The textures fuzz_mapper draws with: these sizes, each repeating and clamped.
struct FuzzTextureSize {
    int32_t width, height;
};
constexpr FuzzTextureSize FUZZ_TEXTURE_SIZES[] = {{1, 1},     {2, 2},     {3, 5},     {64, 64},  {256, 256},
                                                  {1024, 1024}, {17, 256}, {256, 64}, {1024, 3}, {128, 1024}};
constexpr int FUZZ_TEXTURE_COUNT = 2 * int(sizeof(FUZZ_TEXTURE_SIZES) / sizeof(FUZZ_TEXTURE_SIZES[0]));
// Texture i of the bank: FUZZ_TEXTURE_SIZES[i / 2], repeating when i is even, clamped when odd.
inline FuzzTextureSize fuzz_texture_size(int i) { return FUZZ_TEXTURE_SIZES[i / 2]; }
inline Wrap fuzz_texture_wrap(int i) { return i % 2 ? Wrap::Clamp : Wrap::Repeat; }

constexpr uint32_t FUZZ_BATCH = 256;     // polygons with one texture, walker and surface
constexpr uint8_t FUZZ_FILL = 0xA5;      // the surface before a batch
constexpr ClipRect FUZZ_CLIP{1, 2, SCREEN_WIDTH - 3, SCREEN_HEIGHT - 4};  // its border must stay FUZZ_FILL

struct FuzzStats {
    uint32_t tried = 0, batches = 0;
    uint32_t by_status[7] = {};   // SetupStatus: Ok (drawn), then the refusals by reason
    uint64_t pixels = 0;
    uint32_t written_outside = 0;  // bytes outside the clip rectangle no longer FUZZ_FILL, all batches
    uint32_t first_bad_batch = 0;  // 1-based, 0 when none
    bool interrupted = false;
};

// A RAM surface of SCREEN_PIXELS bytes, linear or planar as asked.
using FuzzSurface = uint8_t* (*)(void* ctx, bool planar);

// Draws `count` polygons with the mapper, in batches: each batch takes a texture from the bank
// (FUZZ_TEXTURE_COUNT, as fuzz_texture_size and fuzz_texture_wrap say) that the mapper accepts, one
// of its walkers, and the surface for it filled with FUZZ_FILL; after the batch, the bytes outside
// FUZZ_CLIP are counted. With a watch, it may stop between batches (asked with the polygons done).
FuzzStats fuzz_mapper(const Mapper& mapper, uint32_t seed, uint32_t count, const Texture* bank, FuzzSurface surface, void* ctx,
                      Variant variant = Variant::Twin, const Watch* watch = nullptr);

}  // namespace raster
