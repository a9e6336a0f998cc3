// Targets and the linear/planar conversions.
#include "kernel/core/surface.h"

#if defined(MODEXLAB_OFFSETS)
#include "kernel/core/asm_offsets.h"
#endif

namespace raster {

Target linear_target(uint8_t* pixels, int32_t width, int32_t height, int32_t pitch) {
    Target t;
    t.base = pixels;
    t.pitch = pitch;
    t.clip = ClipRect{0, 0, width, height};
    return t;
}

Target planar_target(uint8_t* planes) {
    Target t;
    t.base = planes;
    t.planar = true;
    t.plane_bytes = PLANE_BYTES;
    t.row_bytes = PLANE_ROW_BYTES;
    t.clip = ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
    return t;
}

void planar_from_linear(const uint8_t* linear, uint8_t* planes) {
    for (int32_t plane = 0; plane < 4; ++plane)
        for (int32_t i = 0; i < PLANE_BYTES; ++i) planes[plane * PLANE_BYTES + i] = linear[4 * i + plane];
}

void linear_from_planar(const uint8_t* planes, uint8_t* linear) {
    for (int32_t plane = 0; plane < 4; ++plane)
        for (int32_t i = 0; i < PLANE_BYTES; ++i) linear[4 * i + plane] = planes[plane * PLANE_BYTES + i];
}

#if defined(MODEXLAB_OFFSETS)
// The target's layout, for the NASM loops that draw into one (asm_offsets.h).
void surface_offsets() {
    ASM_FIELDS(TGT, Target, base, pitch, clip, plane_bytes, select_plane, ctx)
}
#endif

}  // namespace raster
