// The reference: a bounding-box loop around the definitions in setup.h.
#include "qemu/accuracy/reference.h"

namespace raster {

void clear_pixel_image(PixelImage& img, uint8_t background) {
    int32_t n = img.width * img.height;
    for (int32_t i = 0; i < n; ++i) {
        img.index[i] = background;
        img.coverage[i] = 0;
        img.tu[i] = -1;
        img.tv[i] = -1;
        if (img.footprint) img.footprint[i] = 0;
    }
}

SetupStatus reference_polygon(const Vertex* vertices, int count, const Texture& tex, PixelImage& img) {
    PolygonSetup s;
    SetupStatus status = setup_polygon(vertices, count, &s);
    if (status != SetupStatus::Ok) return status;
    // pixels whose centre can be inside the box: floor((min - 128) / 256) .. floor((max - 128) / 256) + 1
    int64_t x0 = floor_div(s.min_x - SUBPIXEL_HALF, SUBPIXEL_ONE), x1 = floor_div(s.max_x - SUBPIXEL_HALF, SUBPIXEL_ONE) + 1;
    int64_t y0 = floor_div(s.min_y - SUBPIXEL_HALF, SUBPIXEL_ONE), y1 = floor_div(s.max_y - SUBPIXEL_HALF, SUBPIXEL_ONE) + 1;
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > img.width - 1) x1 = img.width - 1;
    if (y1 > img.height - 1) y1 = img.height - 1;
    for (int64_t y = y0; y <= y1; ++y) {
        for (int64_t x = x0; x <= x1; ++x) {
            if (!covers(s, int32_t(x), int32_t(y))) continue;
            int32_t tu, tv;
            double cx = centre_x(s, int32_t(x)), cy = centre_y(s, int32_t(y));
            perspective_texel(s, cx, cy, &tu, &tv);
            tu = wrap_coord(tu, tex.width, tex.wrap);
            tv = wrap_coord(tv, tex.height, tex.wrap);
            size_t i = size_t(y) * size_t(img.width) + size_t(x);
            img.index[i] = tex.texels[tv * tex.width + tu];
            if (img.coverage[i] < 255) ++img.coverage[i];
            img.tu[i] = tu;
            img.tv[i] = tv;
            if (img.footprint) img.footprint[i] = float(texel_footprint(s, cx, cy));
        }
    }
    return status;
}

int32_t reference_scene(const Scene& scene, const Texture& tex, PixelImage& img) {
    int32_t rejected = 0;
    const Vertex* v = scene.vertices;
    for (int32_t i = 0; i < scene.polygon_count; ++i) {
        SetupStatus s = reference_polygon(v, scene.polygon_size[i], tex, img);
        if (s != SetupStatus::Ok && s != SetupStatus::Degenerate) ++rejected;
        v += scene.polygon_size[i];
    }
    return rejected;
}

int32_t reference_frame(const Frame& frame, const TextureSet& textures, PixelImage& img) {
    int32_t rejected = 0;
    const Vertex* v = frame.vertices;
    for (int32_t i = 0; i < frame.polygon_count; ++i) {
        SetupStatus s = reference_polygon(v, frame.polygon_size[i], textures.objects[frame.polygon_object[i]], img);
        if (s != SetupStatus::Ok && s != SetupStatus::Degenerate) ++rejected;
        v += frame.polygon_size[i];
    }
    return rejected;
}

}  // namespace raster
