// Mats Byggmastar's fatmap.txt mappers (1996): the polygon drivers, the loops' argument blocks, the
// twins and the NASM loops (asm/fatmap.asm).
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"

namespace raster {

// fatmap-256 and fatmap-256-16 (fatmap.txt's 5-tick loop; fatmap2's 8:16 loop): a 256 x 256
// texture at a 64 KiB boundary, the texel pointer's low 16 bits v:u, wrapping in both directions.
// Both take u, v and the deltas in 16:16 and keep what their registers hold of them.
struct FatmapArgs {
    uint8_t* dst;            // count pixels left to right
    int32_t count;
    const uint8_t* texture;  // aligned to 64 KiB
    int32_t u_16_16, v_16_16;
    int32_t du_16_16, dv_16_16;  // per pixel
};
Loop fatmap_loop;    // 8-bit fractions
Loop fatmap16_loop;  // 16-bit fractions

// fatmap-lut: texel n is source[table[n]]: the triangle's table of offsets from its first pixel.
struct FatmapLutArgs {
    uint8_t* dst;
    int32_t count;
    const uint8_t* source;   // the scanline's first texel
    const int32_t* table;    // the offsets, one per pixel
};
Loop fatmap_lut_loop;

Check check_fatmap;
Check check_fatmap_lut;

}  // namespace raster

extern "C" {
raster::Loop fatmap_loop_asm;
raster::Loop fatmap16_loop_asm;
raster::Loop fatmap_lut_loop_asm;
}

namespace raster::fatmap {

SetupStatus draw_256(const DrawContext& c, const Vertex* vertices, int count);  // fatmap-256, fatmap-256-16
SetupStatus draw_lut(const DrawContext& c, const Vertex* vertices, int count);  // fatmap-lut
// Their error bounds: his rows set up again and each row's lines against the exact mapping.
ErrorBound bound_256(const BoundContext& c, const Vertex* vertices, int count);     // fatmap-256
ErrorBound bound_256_16(const BoundContext& c, const Vertex* vertices, int count);  // fatmap-256-16
ErrorBound bound_lut(const BoundContext& c, const Vertex* vertices, int count);     // fatmap-lut

}  // namespace raster::fatmap
