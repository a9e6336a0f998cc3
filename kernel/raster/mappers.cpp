// affine and exact, and the registry.
#include "kernel/raster/mappers.h"

namespace raster {

namespace {

// A texture coordinate in 16.16 at a span's start. With repeat, it is first reduced modulo the
// texture size (same texels, and far from the 16.16 limit of +-32768 texels); with clamp it
// saturates, which clamps to the same edge texel.
Fixed16_16 start_coordinate(double t, int32_t size, Wrap wrap) {
    if (wrap == Wrap::Repeat) {
        double period = double(size);
        t -= period * double(floor_i64(t / period));  // exact: the result is a multiple of t's ulp below 2*size
    }
    return Fixed16_16::from_double(t);
}

}  // namespace

void affine_span(const PolygonSetup& setup, const Texture& tex, Axis axis, const Span& s, uint8_t* dst, int32_t stride) {
    double x = centre_x(setup, s.x), y = centre_y(setup, s.y);
    Fixed16_16 u = start_coordinate(setup.u.at(x, y), tex.width, tex.wrap);
    Fixed16_16 v = start_coordinate(setup.v.at(x, y), tex.height, tex.wrap);
    double per_pixel = double(SUBPIXEL_ONE);
    Fixed16_16 du = Fixed16_16::from_double((axis == Axis::Rows ? setup.u.gx : setup.u.gy) * per_pixel);
    Fixed16_16 dv = Fixed16_16::from_double((axis == Axis::Rows ? setup.v.gx : setup.v.gy) * per_pixel);
    for (int32_t n = 0; n < s.count; ++n) {
        *dst = texel(tex, u.floor_int(), v.floor_int());
        dst += stride;
        u = u + du;
        v = v + dv;
    }
}

void exact_span(const PolygonSetup& setup, const Texture& tex, Axis axis, const Span& s, uint8_t* dst, int32_t stride) {
    double x = centre_x(setup, s.x), y = centre_y(setup, s.y);
    double& moving = axis == Axis::Rows ? x : y;
    for (int32_t n = 0; n < s.count; ++n) {
        int32_t tu, tv;
        perspective_texel(setup, x, y, &tu, &tv);
        *dst = texel(tex, tu, tv);
        dst += stride;
        moving += double(SUBPIXEL_ONE);  // exact: integers below 2^53
    }
}

const Mapper MAPPERS[] = {
    {"affine", "exact coverage; u, v affine in screen space (16.16 steps), error grows with depth variation", affine_span},
    {"exact", "equal to the reference: per-pixel perspective divide in double precision", exact_span},
};
const int MAPPER_COUNT = sizeof(MAPPERS) / sizeof(MAPPERS[0]);

const Mapper* find_mapper(lib::StrView name) {
    for (int i = 0; i < MAPPER_COUNT; ++i)
        if (name.equals(MAPPERS[i].name)) return &MAPPERS[i];
    return nullptr;
}

}  // namespace raster
