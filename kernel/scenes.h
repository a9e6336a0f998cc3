// The kernel's current screen-space scene: uploaded over COM1, parsed by the portable parser, its
// texture generated; and rendering it into a Mode X page through one of three surfaces.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/raster/render.h"
#include "kernel/raster/scene.h"

namespace scenes {

// Where a render goes on its way to the page.
enum class Surface : uint8_t {
    Linear,  // rows into a linear RAM surface, then blit_linear
    Planar,  // columns into a planar RAM surface, then blit_planar
    Vga,     // columns straight into the page
};
bool surface_from_name(lib::StrView name, Surface* out);
const char* surface_name(Surface s);

// Reads `length` raw bytes from COM1 (giving up after 5 s without a byte), checks the CRC-32 and
// parses them. On failure the previous scene stays and `error` says why (parser errors carry a line).
bool upload(size_t length, uint32_t crc32, raster::ParseError* error);

bool loaded();
const raster::Scene& scene();

struct RenderResult {
    raster::RenderStats stats;
    uint64_t ticks_clear, ticks_draw, ticks_blit;
    bool used_asm;  // the NASM loop ran (else the C++ twin)
};

// The kernel's texture for the current scene (with its bordered copy).
const raster::Texture& texture();

// The walker a render uses: the mapper's only one, or for mappers that walk both, rows into the
// linear surface and columns into the planar ones.
raster::Axis surface_axis(const raster::Mapper& mapper, Surface surface);

// A target of the kind `surface` renders into, for checking what a mapper can take (no pixels).
raster::Target probe_target(Surface surface);

// Clears the surface to 0, draws the scene with `mapper`, and blits (unless drawn in place).
RenderResult render(const raster::Mapper& mapper, Surface surface, int page, raster::Variant variant);

}  // namespace scenes
