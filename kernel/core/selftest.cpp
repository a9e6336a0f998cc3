// What the loop checks share: texels, windows, texture sizes and planes at random, and the list
// of loops to check.
#include "kernel/core/selftest.h"

namespace raster {

void fill_check_texels(Random& r, uint8_t* texels) {
    for (size_t i = 0; i < CHECK_TEXEL_BYTES; ++i) texels[i] = uint8_t(r.next());
}

int32_t random_texture_size(Random& r) {
    switch (r.below(4)) {
    case 0: return int32_t(1) << r.below(11);
    case 1: return r.range(1, 1024);
    case 2: return r.below(2) ? 1 : 1024;
    default: return r.range(1, 64);
    }
}

void random_doubled_sides(Random& r, int32_t* w, int32_t* h, bool above256) {
    do {
        *w = 1 << r.range(0, 10), *h = 1 << r.range(0, 10);
    } while ((above256 && !beyond_tile(*w, *h)) || size_t(doubled_bytes(*w, *h)) > CHECK_TEXEL_BYTES);
}

void fill_check_doubled(const CheckBuffers& buf, int32_t w, int32_t h, uint32_t salt) {
    const int32_t pitch = doubled_pitch(w), rows = 2 * h + 2 * DOUBLED_LEAD;
    for (int32_t r = 0; r < rows; ++r)
        for (int32_t c = 0; c < pitch; ++c) {
            const uint32_t u = uint32_t(c - DOUBLED_LEAD) & uint32_t(w - 1), v = uint32_t(r - DOUBLED_LEAD) & uint32_t(h - 1);
            buf.texels[size_t(r) * size_t(pitch) + size_t(c)] = uint8_t((u * 0x9E3779B1u ^ v * 0x85EBCA77u ^ salt) >> 24);
        }
}

uint8_t* check_span(const CheckBuffers& buf, int32_t count, int32_t stride, CheckWindow* w) {
    size_t extent = size_t(count > 0 ? count - 1 : 0) * size_t(stride < 0 ? -stride : stride);
    *w = CheckWindow{0, CHECK_GUARD_BYTES + extent + 1 + CHECK_GUARD_BYTES, uint32_t(count > 0 ? count : 0)};
    return buf.a + CHECK_GUARD_BYTES + (stride < 0 ? extent : 0);  // a backward span starts at its far end
}

int32_t random_stride(Random& r) {
    int32_t stride = r.below(2) ? 1 : r.range(-330, 330);
    return stride ? stride : 80;
}

const uint8_t* check_aligned_texture(const CheckBuffers& buf) {
    return reinterpret_cast<const uint8_t*>((reinterpret_cast<uintptr_t>(buf.texels) + 0xFFFF) & ~uintptr_t(0xFFFF));
}

void random_planes(Random& r, double* q, double* pu, double* pv) {
    if (r.below(4) != 0) {
        Vertex v[3];
        for (Vertex& x : v) {
            x.x = Fixed24_8::from_raw(r.range(-80 * 256, 400 * 256));
            x.y = Fixed24_8::from_raw(r.range(-80 * 256, 320 * 256));
            x.w = 0.01 + 64 * r.unit() * r.unit();
            x.u = (r.unit() - 0.5) * (r.below(8) ? 4000 : 2 * MAX_UV);
            x.v = (r.unit() - 0.5) * (r.below(8) ? 4000 : 2 * MAX_UV);
        }
        PolygonSetup s;
        if (setup_polygon(v, 3, &s) == SetupStatus::Ok) {
            const Plane* p[3] = {&s.q, &s.pu, &s.pv};
            double* out[3] = {q, pu, pv};
            for (int k = 0; k < 3; ++k) out[k][0] = p[k]->a0, out[k][1] = p[k]->gx, out[k][2] = p[k]->gy;
            return;
        }
    }
    double* out[3] = {q, pu, pv};
    for (double* o : out)
        for (int k = 0; k < 3; ++k) {
            double scale = r.below(3) == 0 ? 1e12 : r.below(2) ? 1.0 : 1e-9;
            o[k] = (r.unit() - 0.5) * scale;
        }
    if (r.below(16) == 0) q[0] = 0, q[1] = 0, q[2] = 0;  // division by zero: infinities and NaN
}

int checked_loops(const Mapper** out, int capacity) {
    int n = 0;
    for (int i = 0; i < MAPPER_COUNT; ++i) {
        const Mapper& m = MAPPERS[i];
        bool first = m.check != nullptr || (m.needs & NEED_VGA_FOR_ASM);  // it has a NASM loop
        for (int k = 0; k < i && first; ++k) first = MAPPERS[k].twin != m.twin;
        if (first && n < capacity) out[n++] = &m;
    }
    return n;
}

}  // namespace raster
