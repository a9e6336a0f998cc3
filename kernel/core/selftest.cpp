// Random cases for each loop with a NASM twin, and the byte-for-byte comparison.
#include "kernel/core/selftest.h"

#include "kernel/core/setup.h"
#include "kernel/core/texture.h"

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

// A case's destination window [lo, hi) of the buffers (its pixels and GUARD_BYTES of guard on
// either side), and the pixels it draws.
struct Window {
    size_t lo, hi;
    uint32_t pixels;
};

// The pointers of b, a copy of a, moved from buffer a to buffer b.
template <typename Args>
void move_to_b(Args& b, const Args& a, const CheckBuffers& buf) {
    b.dst = buf.b + (a.dst - buf.a);
}

// What a loop gives back besides pixels: nothing, for most.
template <typename Args>
bool same_results(const Args&, const Args&) {
    return true;
}
template <typename Args>
const void* block(const Args& a) {
    return &a;
}

// Runs `cases` random cases: make(r, a) fills an argument block drawing into buffer a and returns
// its window; both implementations run it, each into its own buffer, and the windows must agree
// byte for byte (and any other results).
template <typename Args, typename Make>
LoopCheck check_cases(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf, Make make) {
    LoopCheck result;
    result.loop = loop.name;
    Random r(seed);
    fill_texels(r, buf.texels);
    for (uint32_t c = 0; c < cases; ++c) {
        Args a;
        Window w = make(r, a);
        Args b = a;
        move_to_b(b, a, buf);
        for (size_t i = w.lo; i < w.hi; ++i) buf.a[i] = buf.b[i] = GUARD;
        loop.twin(block(a));
        other(block(b));
        bool same = same_results(a, b);
        for (size_t i = w.lo; i < w.hi && same; ++i) same = buf.a[i] == buf.b[i];
        ++result.cases;
        result.pixels += w.pixels;
        if (!same && result.mismatches++ == 0) result.first_mismatch = c;
    }
    return result;
}

// A span of count pixels `stride` bytes apart (count >= 0, stride > 0) starting GUARD_BYTES into
// buffer a: its first pixel and its window.
uint8_t* span_in_a(const CheckBuffers& buf, int32_t count, int32_t stride, Window* w) {
    size_t extent = size_t(count > 0 ? count - 1 : 0) * size_t(stride);
    *w = Window{0, GUARD_BYTES + extent + 1 + GUARD_BYTES, uint32_t(count > 0 ? count : 0)};
    return buf.a + GUARD_BYTES;
}

// The 64 KiB-aligned texture the fatmap-style loops need: the first such address in the buffer.
const uint8_t* aligned_texture(const CheckBuffers& buf) {
    return reinterpret_cast<const uint8_t*>((reinterpret_cast<uintptr_t>(buf.texels) + 0xFFFF) & ~uintptr_t(0xFFFF));
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
    return check_cases<ExactArgs>(loop, other, seed, cases, buf, [&](Random& r, ExactArgs& a) {
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
        a.dst = buf.a + first;
        return Window{0, GUARD_BYTES + extent + 1 + GUARD_BYTES, uint32_t(a.count > 0 ? a.count : 0)};
    });
}

namespace {

// Texture walks of the pointer loops start in the middle of the 1 MiB texel buffer; every random
// advance is bounded so that no walk can leave it: count * (|base| + 1 + |row|) < 512 KiB.
constexpr int32_t MID = int32_t(CHECK_TEXEL_BYTES / 2);

}  // namespace

LoopCheck check_xsharp_column(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<XSharpColumnArgs>(loop, other, seed, cases, buf, [&](Random& r, XSharpColumnArgs& a) {
        int32_t pitch = random_size(r) + 2;  // a bordered texture's pitch: 3..1026
        a.count = r.below(8) == 0 ? r.range(1, 3) : r.range(1, 240);
        a.texel = buf.texels + MID + r.range(-1000, 1000);
        a.fractions = (r.next() & 0xFFFF0000u) | (r.next() & 0x7FFF);
        a.steps = (r.next() & 0xFFFF0000u) | (r.next() & 0x7FFF);
        if (r.below(4) == 0) a.steps &= 0xFFFF7FFFu & (r.below(2) ? 0x0000FFFFu : 0xFFFF0000u);  // one axis without a fraction
        a.base = r.range(-2, 2) + r.range(-1, 1) * pitch;
        a.row = r.below(2) ? pitch : -pitch;
        a.backwards = int32_t(r.below(2));
        Window w;
        a.dst = span_in_a(buf, a.count, XSHARP_SCANWIDTH, &w);
        return w;
    });
}

LoopCheck check_hecker(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<HeckerArgs>(loop, other, seed, cases, buf, [&](Random& r, HeckerArgs& a) {
        int32_t pitch = r.range(3, 600);  // any width: the step table holds the pitch
        a.count = r.below(8) == 0 ? r.range(0, 3) : r.range(1, 320);
        a.texel = buf.texels + MID + r.range(-1000, 1000);
        a.u_frac = r.next() & 0xFFFF0000u;
        a.v_frac = r.next() & 0xFFFF0000u;
        a.du_frac = r.below(8) == 0 ? 0 : r.next() & 0xFFFF0000u;
        a.dv_frac = r.below(8) == 0 ? 0 : r.next() & 0xFFFF0000u;
        a.step_no_carry = r.range(-3, 3) + r.range(-1, 1) * pitch;
        a.step_carry = a.step_no_carry + (r.below(2) ? pitch : -pitch);
        Window w;
        a.dst = span_in_a(buf, a.count, 1, &w);
        return w;
    });
}

namespace {

// Random 16.16 coordinates and steps for the 8:16 loops: anything at all a quarter of the time,
// else steps up to 4 texels a pixel.
template <typename Args>
void random_uv(Random& r, Args& a) {
    a.u = int32_t(r.next());
    a.v = int32_t(r.next());
    a.du = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
    a.dv = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
}

}  // namespace

LoopCheck check_fatmap(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<FatmapArgs>(loop, other, seed, cases, buf, [&](Random& r, FatmapArgs& a) {
        a.count = r.below(8) == 0 ? r.range(0, 3) : r.range(1, 320);
        a.texture = aligned_texture(buf);
        random_uv(r, a);
        Window w;
        a.dst = span_in_a(buf, a.count, 1, &w);
        return w;
    });
}

LoopCheck check_fast_column(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<FastColumnArgs>(loop, other, seed, cases, buf, [&](Random& r, FastColumnArgs& a) {
        a.count = r.below(8) == 0 ? r.range(0, 9) : r.range(1, 240);
        a.texture = aligned_texture(buf);
        random_uv(r, a);
        Window w;
        a.dst = span_in_a(buf, a.count, MODEX_ROW_BYTES, &w);
        return w;
    });
}

namespace {

// fast_run_loop's block with the bounds and the tally it updates, which must come out the same.
struct RunCase {
    FastRunArgs args;
    EdgeBound lower, upper;
    uint32_t tally[2];
};

template <>
void move_to_b(RunCase& b, const RunCase& a, const CheckBuffers& buf) {
    b.args.row = buf.b + (a.args.row - buf.a);
    b.args.lower = &b.lower;
    b.args.upper = &b.upper;
    b.args.tally = b.tally;
}

template <>
bool same_results(const RunCase& a, const RunCase& b) {
    auto same = [](const EdgeBound& x, const EdgeBound& y) { return x.q == y.q && x.r == y.r; };
    return same(a.lower, b.lower) && same(a.upper, b.upper) && a.tally[0] == b.tally[0] && a.tally[1] == b.tally[1];
}

template <>
const void* block(const RunCase& a) {
    return &a.args;
}

// A random bound: q anywhere near the rows (often far outside the clip), steps of either sign,
// any remainder and divisor.
EdgeBound random_bound(Random& r, int32_t pitch) {
    EdgeBound b;
    b.first = b.last = 0;
    b.q = r.below(4) == 0 ? r.range(-100000, 100000) : r.range(-20, pitch + 20);
    b.dq = r.below(4) == 0 ? r.range(-400, 400) : r.range(-3, 3);
    b.d = r.below(4) == 0 ? 1 + r.next() % 0x80000000u : uint32_t(r.range(1, 4096));
    b.r = r.next() % b.d;
    b.dr = r.next() % b.d;
    return b;
}

}  // namespace

LoopCheck check_fast_run(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<RunCase>(loop, other, seed, cases, buf, [&](Random& r, RunCase& c) {
        FastRunArgs& a = c.args;
        // rows of up to 330 bytes; 240 of them fit the buffer with its guards
        a.pitch = r.below(2) ? 320 : r.range(1, 330);
        a.lines = r.below(8) == 0 ? r.range(0, 3) : r.range(1, 240);
        a.clip_lo = r.range(0, a.pitch - 1);
        a.clip_hi = r.below(8) == 0 ? a.clip_lo - 1 : r.range(a.clip_lo, a.pitch - 1);  // sometimes nothing
        c.lower = random_bound(r, a.pitch);
        c.upper = random_bound(r, a.pitch);
        if (r.below(2)) c.upper.q = c.lower.q + r.range(0, a.pitch), c.upper.dq = c.lower.dq + r.range(-2, 2);  // a real-looking span
        a.texture = aligned_texture(buf);
        a.u = r.next();
        a.v = r.next();
        a.u_row = r.next();
        a.v_row = r.next();
        a.du = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        a.dv = r.below(4) == 0 ? int32_t(r.next()) : r.range(-0x40000, 0x40000);
        c.tally[0] = c.tally[1] = 0;
        a.lower = &c.lower;
        a.upper = &c.upper;
        a.tally = c.tally;
        a.row = buf.a + GUARD_BYTES;
        int32_t lines = a.lines > 0 ? a.lines : 0;
        uint32_t pixels = 0;  // what the rows will draw
        EdgeBound lo = c.lower, hi = c.upper;
        for (int32_t n = 0; n < lines; ++n) {
            int32_t x0 = lo.q > a.clip_lo ? lo.q : a.clip_lo, x1 = hi.q < a.clip_hi ? hi.q : a.clip_hi;
            if (x0 <= x1) pixels += uint32_t(x1 - x0 + 1);
            lo.step();
            hi.step();
        }
        return Window{0, GUARD_BYTES + size_t(lines) * size_t(a.pitch) + GUARD_BYTES, pixels};
    });
}

LoopCheck check_fatmap_lut(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    static int32_t table[321];  // count entries and the one the NASM loop reads past the last
    return check_cases<FatmapLutArgs>(loop, other, seed, cases, buf, [&](Random& r, FatmapLutArgs& a) {
        a.count = r.below(8) == 0 ? r.range(0, 3) : r.range(1, 320);
        a.source = buf.texels + MID + r.range(-1000, 1000);
        int32_t du = r.range(-512, 512), dv = r.range(-512, 512), u = 0, v = 0;
        for (int32_t k = 0; k <= a.count; ++k) {  // as fatmap builds it (24:8 steps, pitch 256)
            table[k] = (u >> 8) + int32_t(uint32_t(v) & 0xFFFFFF00u);
            u += du;
            v += dv;
        }
        a.table = table;
        Window w;
        a.dst = span_in_a(buf, a.count, 1, &w);
        return w;
    });
}

LoopCheck check_quake(const CheckedLoop& loop, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<QuakeArgs>(loop, other, seed, cases, buf, [&](Random& r, QuakeArgs& a) {
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
        Window win;
        a.dst = span_in_a(buf, a.count, 1, &win);
        return win;
    });
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
    {"fast-affine", fast_run_loop, MODEXLAB_ASM(fast_run_asm), check_fast_run, false},
    {"fast-columns", fast_column_loop, MODEXLAB_ASM(fast_column_asm), check_fast_column, false},
};
const int CHECKED_LOOP_COUNT = sizeof(CHECKED_LOOPS) / sizeof(CHECKED_LOOPS[0]);

}  // namespace raster
