// Where pixels go: a linear 320x240 surface in RAM, a Mode X planar surface in RAM, or a VGA page
// (planar, with a callback that selects the plane). Portable: the VGA specifics stay in drivers/.
#pragma once

#include <stdint.h>

#include "kernel/core/setup.h"
#include "kernel/core/walk.h"

namespace raster {

constexpr int32_t SCREEN_WIDTH = 320;
constexpr int32_t SCREEN_HEIGHT = 240;
constexpr int32_t PLANE_ROW_BYTES = SCREEN_WIDTH / 4;                 // 80
constexpr int32_t PLANE_BYTES = PLANE_ROW_BYTES * SCREEN_HEIGHT;      // 19200 = 0x4B00
constexpr int32_t SCREEN_PIXELS = SCREEN_WIDTH * SCREEN_HEIGHT;

struct Target {
    uint8_t* base = nullptr;
    // linear: pixel (x, y) at base + y * pitch + x
    int32_t pitch = 0;
    // planar: pixel (x, y) in plane x & 3, at base + plane * plane_bytes + y * row_bytes + x / 4
    bool planar = false;
    int32_t plane_bytes = 0, row_bytes = 0;
    // planar: called before drawing into another plane than the last (the VGA map mask)
    void (*select_plane)(void* ctx, int plane) = nullptr;
    void* ctx = nullptr;
    bool vga = false;           // a real VGA page (drivers/vga.cpp): loops may program the VGA
    ClipRect clip{0, 0, 0, 0};  // inside the surface
};

Target linear_target(uint8_t* pixels, int32_t width, int32_t height, int32_t pitch);
// Four planes of PLANE_BYTES each, one after the other (a RAM copy of a Mode X page).
Target planar_target(uint8_t* planes);

// Rows need a linear target; columns work on both.
inline bool target_supports(const Target& t, Axis axis) { return axis == Axis::Columns || !t.planar; }

// The first pixel of a span and the distance between its pixels. Planar targets select the plane.
inline uint8_t* span_start(Target& t, Axis axis, const Span& s, int32_t* stride) {
    if (!t.planar) {
        *stride = axis == Axis::Rows ? 1 : t.pitch;
        return t.base + s.y * t.pitch + s.x;
    }
    int plane = s.x & 3;
    if (t.select_plane) t.select_plane(t.ctx, plane);
    *stride = t.row_bytes;
    return t.base + plane * t.plane_bytes + s.y * t.row_bytes + (s.x >> 2);
}

// The address of pixel (x, y); a planar target gets the plane selected (the VGA: an OUT).
inline uint8_t* pixel_at(Target& t, int32_t x, int32_t y) {
    if (!t.planar) return t.base + y * t.pitch + x;
    int plane = x & 3;
    if (t.select_plane) t.select_plane(t.ctx, plane);
    return t.base + plane * t.plane_bytes + y * t.row_bytes + (x >> 2);
}

// Where a picture of w x h pixels goes in a screen of sw x sh (a UEFI framebuffer, drivers/vga.h):
// scaled by the largest whole factor that fits (at least 1), centred.
struct ScaledPlacement {
    uint32_t scale, x, y;
};
constexpr ScaledPlacement scaled_placement(uint32_t sw, uint32_t sh, uint32_t w, uint32_t h) {
    uint32_t scale = sw / w < sh / h ? sw / w : sh / h;
    scale = scale < 1 ? 1 : scale;
    return ScaledPlacement{scale, sw > w * scale ? (sw - w * scale) / 2 : 0, sh > h * scale ? (sh - h * scale) / 2 : 0};
}

// Converts a linear 320x240 picture to the four-plane layout (the RAM side of a blit).
void planar_from_linear(const uint8_t* linear, uint8_t* planes);
// And back: the four planes of a page to a linear picture.
void linear_from_planar(const uint8_t* planes, uint8_t* linear);

}  // namespace raster
