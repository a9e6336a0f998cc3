// Fixed-point helpers of the 1990s and the polygon conversion for the classic mappers.
#include "kernel/mappers/classic.h"

namespace raster::classic {

int32_t fixed_div(int32_t a, int32_t b) {
    int64_t q = (int64_t(a) * 65536) / int64_t(b);  // C division truncates, as idiv did
    return q > INT32_MAX ? INT32_MAX : q < INT32_MIN ? INT32_MIN : int32_t(q);
}

int32_t fixed_mul(int32_t a, int32_t b) {
    int64_t p = int64_t(a) * int64_t(b) + 0x8000;
    return int32_t(p >> 16);
}

namespace {

// The shift by whole periods that puts the smallest coordinate in [0, size), for repeat.
double period_shift(double lo, int32_t size, Wrap wrap) {
    if (wrap == Wrap::Clamp) return 0;
    return -double(size) * double(floor_i64(lo / double(size)));
}

}  // namespace

SetupStatus texture_shift(const Vertex* in, int n, const Texture& tex, double* shift_u, double* shift_v) {
    return texture_shift(in, n, tex, double(tex.width), double(tex.height), shift_u, shift_v);
}

SetupStatus texture_shift(const Vertex* in, int n, const Texture& tex, double limit_u, double limit_v, double* shift_u, double* shift_v) {
    if (n > MAX_VERTICES) return SetupStatus::TooManyVertices;
    if (n < 3) return SetupStatus::Degenerate;
    for (int i = 0; i < n; ++i) {
        const Vertex& v = in[i];
        if (!(v.u == v.u) || !(v.v == v.v) || v.u > MAX_UV || v.u < -MAX_UV || v.v > MAX_UV || v.v < -MAX_UV) return SetupStatus::OutOfRange;
        constexpr int32_t LIMIT = MAX_COORD << SUBPIXEL_BITS;
        if (v.x.raw > LIMIT || v.x.raw < -LIMIT || v.y.raw > LIMIT || v.y.raw < -LIMIT) return SetupStatus::OutOfRange;
    }
    double lo_u = in[0].u, lo_v = in[0].v;
    for (int i = 1; i < n; ++i) {
        if (in[i].u < lo_u) lo_u = in[i].u;
        if (in[i].v < lo_v) lo_v = in[i].v;
    }
    *shift_u = period_shift(lo_u, tex.width, tex.wrap);
    *shift_v = period_shift(lo_v, tex.height, tex.wrap);
    for (int i = 0; i < n; ++i) {
        double u = in[i].u + *shift_u, t = in[i].v + *shift_v;
        if (u < 0 || u > limit_u || t < 0 || t > limit_v) return SetupStatus::OutsideTexture;
    }
    return SetupStatus::Ok;
}

SetupStatus convert(const Vertex* in, int n, const Texture& tex, double texel_offset, Vertex16* out, int* count, double* shift) {
    *count = 0;
    double shift_u, shift_v;
    SetupStatus status = texture_shift(in, n, tex, &shift_u, &shift_v);
    if (status != SetupStatus::Ok) return status;
    if (shift) shift[0] = shift_u, shift[1] = shift_v;
    for (int i = 0; i < n; ++i) {
        const Vertex& v = in[i];
        out[i].x = (v.x.raw + int32_t(SUBPIXEL_HALF)) >> SUBPIXEL_BITS;
        out[i].y = (v.y.raw + int32_t(SUBPIXEL_HALF)) >> SUBPIXEL_BITS;
        out[i].u_16_16 = Fixed16_16::from_double(v.u + shift_u + texel_offset).raw;
        out[i].v_16_16 = Fixed16_16::from_double(v.v + shift_v + texel_offset).raw;
        out[i].w = v.w;
    }
    int64_t area2 = 0;
    for (int i = 0; i < n; ++i) {
        const Vertex16& a = out[i];
        const Vertex16& b = out[(i + 1) % n];
        area2 += int64_t(a.x) * b.y - int64_t(b.x) * a.y;
    }
    if (area2 == 0) return SetupStatus::Degenerate;
    if (area2 < 0)  // counter-clockwise on the y-down screen: reverse
        for (int i = 0, j = n - 1; i < j; ++i, --j) {
            Vertex16 t = out[i];
            out[i] = out[j];
            out[j] = t;
        }
    *count = n;
    return SetupStatus::Ok;
}

bool monotone(const Vertex16* v, int n, bool columns) {
    auto key = [&](int i) { return columns ? v[i].x : v[i].y; };
    int lo = 0, hi = 0;
    for (int i = 1; i < n; ++i) {
        if (key(i) < key(lo)) lo = i;
        if (key(i) > key(hi)) hi = i;
    }
    for (int direction = 1; direction >= -1; direction -= 2) {
        for (int i = lo; i != hi;) {
            int next = (i + direction + n) % n;
            if (key(next) < key(i)) return false;
            i = next;
        }
    }
    return true;
}

}  // namespace raster::classic
