// Random cases for each loop with a NASM twin, and the byte-for-byte comparison.
#include "kernel/raster/selftest.h"

#include "kernel/raster/setup.h"
#include "kernel/raster/texture.h"

namespace raster {

namespace {

constexpr uint8_t GUARD = 0xC3;
constexpr size_t GUARD_BYTES = 64;

// A texture size the loops accept: 1..1024, often a power of two, sometimes an extreme.
int32_t random_size(Random& r) {
    switch (r.below(4)) {
    case 0: return int32_t(1) << r.below(11);
    case 1: return r.range(1, 1024);
    case 2: return r.below(2) ? 1 : 1024;
    default: return r.range(1, 64);
    }
}

// Random texels once per check; each case views the first width x height of them.
void fill_texels(Random& r, uint8_t* texels) {
    for (size_t i = 0; i < CHECK_TEXEL_BYTES; ++i) texels[i] = uint8_t(r.next());
}

// Runs both implementations on the same block, each with its own destination buffer, and compares
// the window [lo, hi) of the buffers: the span and GUARD_BYTES of guard on either side.
bool run_both(LoopFn twin, LoopFn other, void* args_a, void* args_b, const CheckBuffers& buf, size_t lo, size_t hi) {
    for (size_t i = lo; i < hi; ++i) buf.a[i] = buf.b[i] = GUARD;
    twin(args_a);
    other(args_b);
    for (size_t i = lo; i < hi; ++i)
        if (buf.a[i] != buf.b[i]) return false;
    return true;
}

// A plane: from a real set-up triangle most of the time, else raw values up to the extremes.
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

}  // namespace

LoopCheck check_exact(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    LoopCheck result;
    result.loop = loop.name;
    Random r(seed);
    fill_texels(r, buf.texels);
    for (uint32_t c = 0; c < cases; ++c) {
        ExactArgs a;
        int32_t w = random_size(r), h = random_size(r);
        a.texels = buf.texels;
        a.width = w;
        a.height = h;
        a.clamp = int32_t(r.below(2));
        a.reserved = 0;
        a.count = r.below(8) == 0 ? r.range(0, 3) : r.range(1, 320);
        a.stride = r.below(2) ? 1 : r.range(-330, 330);
        if (a.stride == 0) a.stride = 80;
        // the destination's first pixel, so that all count pixels stay between the guards
        size_t extent = size_t(a.count > 0 ? a.count - 1 : 0) * size_t(a.stride < 0 ? -a.stride : a.stride);
        size_t first = GUARD_BYTES + (a.stride < 0 ? extent : 0);
        double sign = r.below(4) == 0 ? -1.0 : 1.0;
        bool rows = r.below(2) == 0;
        a.step_x = rows ? sign * 256 : 0;
        a.step_y = rows ? 0 : sign * 256;
        a.x = double(r.range(-120000, 120000)) + 128;
        a.y = double(r.range(-90000, 90000)) + 128;
        random_planes(r, a.q, a.pu, a.pv);
        ExactArgs b = a;
        a.dst = buf.a + first;
        b.dst = buf.b + first;
        ++result.cases;
        result.pixels += uint32_t(a.count > 0 ? a.count : 0);
        if (!run_both(loop.twin, other, &a, &b, buf, first - (a.stride < 0 ? extent : 0) - GUARD_BYTES,
                      first + (a.stride < 0 ? 0 : extent) + 1 + GUARD_BYTES)) {
            if (result.mismatches++ == 0) result.first_mismatch = c;
        }
    }
    return result;
}

namespace {

// Texture walks of the pointer loops start in the middle of the 1 MiB texel buffer; every random
// advance is bounded so that no walk can leave it: count * (|base| + 1 + |row|) < 512 KiB.
constexpr int32_t MID = int32_t(CHECK_TEXEL_BYTES / 2);

}  // namespace

LoopCheck check_xsharp_column(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    LoopCheck result;
    result.loop = loop.name;
    Random r(seed);
    fill_texels(r, buf.texels);
    for (uint32_t c = 0; c < cases; ++c) {
        XSharpColumnArgs a;
        int32_t pitch = random_size(r) + 2;  // a bordered texture's pitch: 3..1026
        a.count = r.below(8) == 0 ? r.range(1, 3) : r.range(1, 240);
        a.texel = buf.texels + MID + r.range(-1000, 1000);
        a.fractions = (r.next() & 0xFFFF0000u) | (r.next() & 0x7FFF);
        a.steps = (r.next() & 0xFFFF0000u) | (r.next() & 0x7FFF);
        if (r.below(4) == 0) a.steps &= 0xFFFF7FFFu & (r.below(2) ? 0x0000FFFFu : 0xFFFF0000u);  // one axis without a fraction
        a.base = r.range(-2, 2) + r.range(-1, 1) * pitch;
        a.row = r.below(2) ? pitch : -pitch;
        a.backwards = int32_t(r.below(2));
        size_t extent = size_t(a.count - 1) * XSHARP_SCANWIDTH;
        size_t first = GUARD_BYTES;
        XSharpColumnArgs b = a;
        a.dst = buf.a + first;
        b.dst = buf.b + first;
        ++result.cases;
        result.pixels += uint32_t(a.count);
        if (!run_both(loop.twin, other, &a, &b, buf, 0, first + extent + 1 + GUARD_BYTES))
            if (result.mismatches++ == 0) result.first_mismatch = c;
    }
    return result;
}

LoopCheck check_hecker(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    LoopCheck result;
    result.loop = loop.name;
    Random r(seed);
    fill_texels(r, buf.texels);
    for (uint32_t c = 0; c < cases; ++c) {
        HeckerArgs a;
        int32_t pitch = r.range(3, 600);  // any width: the step table holds the pitch
        a.count = r.below(8) == 0 ? r.range(0, 3) : r.range(1, 320);
        a.texel = buf.texels + MID + r.range(-1000, 1000);
        a.u_frac = r.next() & 0xFFFF0000u;
        a.v_frac = r.next() & 0xFFFF0000u;
        a.du_frac = r.below(8) == 0 ? 0 : r.next() & 0xFFFF0000u;
        a.dv_frac = r.below(8) == 0 ? 0 : r.next() & 0xFFFF0000u;
        a.step_no_carry = r.range(-3, 3) + r.range(-1, 1) * pitch;
        a.step_carry = a.step_no_carry + (r.below(2) ? pitch : -pitch);
        size_t extent = size_t(a.count > 0 ? a.count - 1 : 0);
        HeckerArgs b = a;
        a.dst = buf.a + GUARD_BYTES;
        b.dst = buf.b + GUARD_BYTES;
        ++result.cases;
        result.pixels += uint32_t(a.count > 0 ? a.count : 0);
        if (!run_both(loop.twin, other, &a, &b, buf, 0, GUARD_BYTES + extent + 1 + GUARD_BYTES))
            if (result.mismatches++ == 0) result.first_mismatch = c;
    }
    return result;
}

LoopCheck check_fatmap(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    LoopCheck result;
    result.loop = loop.name;
    Random r(seed);
    fill_texels(r, buf.texels);
    // the loops need their texture on a 64 KiB boundary: the first such address in the buffer
    const uint8_t* texture = reinterpret_cast<const uint8_t*>((reinterpret_cast<uintptr_t>(buf.texels) + 0xFFFF) & ~uintptr_t(0xFFFF));
    for (uint32_t c = 0; c < cases; ++c) {
        FatmapArgs a;
        a.count = r.below(8) == 0 ? r.range(0, 3) : r.range(1, 320);
        a.texture = texture;
        a.u = int32_t(r.next());
        a.v = int32_t(r.next());
        a.du = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        a.dv = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        size_t extent = size_t(a.count > 0 ? a.count - 1 : 0);
        FatmapArgs b = a;
        a.dst = buf.a + GUARD_BYTES;
        b.dst = buf.b + GUARD_BYTES;
        ++result.cases;
        result.pixels += uint32_t(a.count > 0 ? a.count : 0);
        if (!run_both(loop.twin, other, &a, &b, buf, 0, GUARD_BYTES + extent + 1 + GUARD_BYTES))
            if (result.mismatches++ == 0) result.first_mismatch = c;
    }
    return result;
}

LoopCheck check_fast_column(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    LoopCheck result;
    result.loop = loop.name;
    Random r(seed);
    fill_texels(r, buf.texels);
    const uint8_t* texture = reinterpret_cast<const uint8_t*>((reinterpret_cast<uintptr_t>(buf.texels) + 0xFFFF) & ~uintptr_t(0xFFFF));
    for (uint32_t c = 0; c < cases; ++c) {
        FastColumnArgs a;
        a.count = r.below(8) == 0 ? r.range(0, 9) : r.range(1, 240);
        a.texture = texture;
        a.u = int32_t(r.next());
        a.v = int32_t(r.next());
        a.du = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        a.dv = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        size_t extent = size_t(a.count > 0 ? a.count - 1 : 0) * MODEX_ROW_BYTES;
        FastColumnArgs b = a;
        a.dst = buf.a + GUARD_BYTES;
        b.dst = buf.b + GUARD_BYTES;
        ++result.cases;
        result.pixels += uint32_t(a.count > 0 ? a.count : 0);
        if (!run_both(loop.twin, other, &a, &b, buf, 0, GUARD_BYTES + extent + 1 + GUARD_BYTES))
            if (result.mismatches++ == 0) result.first_mismatch = c;
    }
    return result;
}

LoopCheck check_fatmap_lut(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    LoopCheck result;
    result.loop = loop.name;
    Random r(seed);
    fill_texels(r, buf.texels);
    static int32_t table[321];  // count entries and the one the NASM loop reads past the last
    for (uint32_t c = 0; c < cases; ++c) {
        FatmapLutArgs a;
        a.count = r.below(8) == 0 ? r.range(0, 3) : r.range(1, 320);
        a.source = buf.texels + MID + r.range(-1000, 1000);
        int32_t du = r.range(-512, 512), dv = r.range(-512, 512), u = 0, v = 0;
        for (int32_t k = 0; k <= a.count; ++k) {  // as fatmap builds it (24:8 steps, pitch 256)
            table[k] = (u >> 8) + int32_t(uint32_t(v) & 0xFFFFFF00u);
            u += du;
            v += dv;
        }
        a.table = table;
        size_t extent = size_t(a.count > 0 ? a.count - 1 : 0);
        FatmapLutArgs b = a;
        a.dst = buf.a + GUARD_BYTES;
        b.dst = buf.b + GUARD_BYTES;
        ++result.cases;
        result.pixels += uint32_t(a.count > 0 ? a.count : 0);
        if (!run_both(loop.twin, other, &a, &b, buf, 0, GUARD_BYTES + extent + 1 + GUARD_BYTES))
            if (result.mismatches++ == 0) result.first_mismatch = c;
    }
    return result;
}

LoopCheck check_quake(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    LoopCheck result;
    result.loop = loop.name;
    Random r(seed);
    fill_texels(r, buf.texels);
    for (uint32_t c = 0; c < cases; ++c) {
        QuakeArgs a;
        int32_t w = random_size(r), h = random_size(r);
        a.texels = buf.texels;
        a.pitch = w;
        a.bbextents = (w << 16) - 1;
        a.bbextentt = (h << 16) - 1;
        a.sadjust = r.below(2) ? 0 : r.range(-4, 4) * (w << 16);
        a.tadjust = r.below(2) ? 0 : r.range(-4, 4) * (h << 16);
        a.shift = r.below(2) ? 4 : 3;
        a.reserved = 0;
        a.count = r.below(8) == 0 ? r.range(1, 20) : r.range(1, 320);
        a.x = r.range(0, 319);
        a.y = r.range(0, 239);
        // planes from a real triangle most of the time (then s/z * z is u in 16.16), else raw values
        double q[3], pu[3], pv[3];
        random_planes(r, q, pu, pv);
        auto per_pixel = [&](const double* p, double* origin, double* stepu, double* stepv) {
            *stepu = p[1] * 256, *stepv = p[2] * 256;
            *origin = p[0] + double(r.range(-100000, 100000)) * 1e-3 * (*stepu);
        };
        per_pixel(pu, &a.s_origin, &a.s_stepu, &a.s_stepv);
        per_pixel(pv, &a.t_origin, &a.t_stepu, &a.t_stepv);
        per_pixel(q, &a.z_origin, &a.z_stepu, &a.z_stepv);
        double n = double(1 << a.shift);
        a.s_stepu_n = a.s_stepu * n, a.t_stepu_n = a.t_stepu * n, a.z_stepu_n = a.z_stepu * n;
        size_t extent = size_t(a.count - 1);
        QuakeArgs b = a;
        a.dst = buf.a + GUARD_BYTES;
        b.dst = buf.b + GUARD_BYTES;
        ++result.cases;
        result.pixels += uint32_t(a.count);
        if (!run_both(loop.twin, other, &a, &b, buf, 0, GUARD_BYTES + extent + 1 + GUARD_BYTES))
            if (result.mismatches++ == 0) result.first_mismatch = c;
    }
    return result;
}

void random_xsharp_row(Random& r, const uint8_t* texels, XSharpRowArgs* a, int32_t* x, int32_t* y) {
    int32_t pitch = r.range(3, 600);
    *y = r.range(0, 239);
    *x = r.range(0, 319);
    a->count = r.range(1, 320 - *x);
    a->mask = 0x11u << (*x & 3);
    a->texel = texels + MID + r.range(-1000, 1000);
    a->x_frac = r.next() & 0xFFFF;
    a->y_frac = r.next() & 0xFFFF;
    a->x_step = r.below(4) == 0 ? 0 : r.next() & 0xFFFF;
    a->y_step = r.below(4) == 0 ? 0 : r.next() & 0xFFFF;
    a->x_base = r.range(-3, 3);
    a->x_carry = r.below(2) ? 1 : -1;
    a->y_base = r.range(-1, 1) * pitch;
    a->y_carry = r.below(2) ? pitch : -pitch;
    a->select_plane = nullptr;
    a->ctx = nullptr;
}

const CheckedLoop CHECKED_LOOPS[] = {
    {"exact", exact_loop, MODEXLAB_ASM(exact_loop_asm), check_exact, false},
    {"xsharp-row-out", xsharp_row_loop, MODEXLAB_ASM(xsharp_row_asm), nullptr, true},
    {"xsharp-column", xsharp_column_loop, MODEXLAB_ASM(xsharp_column_asm), check_xsharp_column, false},
    {"hecker-steptable", hecker_loop, MODEXLAB_ASM(hecker_loop_asm), check_hecker, false},
    {"fatmap-256", fatmap_loop, MODEXLAB_ASM(fatmap_loop_asm), check_fatmap, false},
    {"fatmap-256-16", fatmap16_loop, MODEXLAB_ASM(fatmap16_loop_asm), check_fatmap, false},
    {"fatmap-lut", fatmap_lut_loop, MODEXLAB_ASM(fatmap_lut_loop_asm), check_fatmap_lut, false},
    {"quake-subdiv", quake_span_loop, MODEXLAB_ASM(quake_span_asm), check_quake, false},
    {"fast-affine", fatmap16_loop, MODEXLAB_ASM(fast_row_asm), check_fatmap, false},
    {"fast-columns", fast_column_loop, MODEXLAB_ASM(fast_column_asm), check_fast_column, false},
};
const int CHECKED_LOOP_COUNT = sizeof(CHECKED_LOOPS) / sizeof(CHECKED_LOOPS[0]);

}  // namespace raster
