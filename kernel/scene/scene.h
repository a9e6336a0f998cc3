// Screen-space scene files (docs/scene-format.md, version 1): a procedural texture, its wrap
// mode, and triangles and convex polygons with x y w u v per vertex. Portable: the host tools and
// the kernel parse the same text with the same code, and reject a bad file with the same message.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/core/setup.h"
#include "kernel/core/texture.h"
#include "kernel/lib/fmt.h"

namespace raster {

constexpr int32_t MAX_SCENE_POLYGONS = 8192;
constexpr int32_t MAX_SCENE_VERTICES = 3 * MAX_SCENE_POLYGONS;
constexpr size_t MAX_SCENE_BYTES = 1 << 20;
constexpr int MAX_DECIMALS = 6;

struct Scene {
    TextureKind texture_kind = TextureKind::Checker;
    int32_t texture_width = 0, texture_height = 0;
    Wrap wrap = Wrap::Repeat;
    int32_t polygon_count = 0;
    int32_t vertex_count = 0;
    uint8_t polygon_size[MAX_SCENE_POLYGONS];  // vertices of polygon i; they follow polygon i-1's
    Vertex vertices[MAX_SCENE_VERTICES];
};

struct ParseError {
    int32_t line = 0;  // 1-based; 0 when the error is about the whole file
    char message[lib::Fmt::CAPACITY + 1] = {};  // a message longer ends with Fmt::CUT (scene_text::fail)
};

// Parses `length` bytes of scene text. On failure returns false with the first error.
bool parse_scene(const char* text, size_t length, Scene* out, ParseError* error);

// The version a scene text declares on its first line (1: screen space, 2: 3D); 0 with an error
// when the text is not a scene.
int scene_version(const char* text, size_t length, ParseError* error);

}  // namespace raster
