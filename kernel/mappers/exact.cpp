// exact: the span function, its loop (the specification of asm/exact.asm) and the loop's checks.
#include "kernel/mappers/exact.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/bound.h"
#include "kernel/core/selftest.h"

namespace raster {

static_assert(sizeof(Plane) == 3 * sizeof(double), "ExactArgs copies planes as three doubles");

// exact: the argument block for exact_loop / exact_loop_asm.
void exact_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride) {
    const PolygonSetup& setup = c.setup;
    ExactArgs a;
    a.dst = dst;
    a.stride = stride;
    a.count = s.count;
    a.texels = c.tex.texels;
    a.width = c.tex.width;
    a.height = c.tex.height;
    a.clamp = c.tex.wrap == Wrap::Clamp;
    a.reserved = 0;
    a.x = span_centre_x(setup, s.x);
    a.y = span_centre_y(setup, s.y);
    a.step_x = c.axis == Axis::Rows ? double(SUBPIXEL_ONE) : 0.0;
    a.step_y = c.axis == Axis::Rows ? 0.0 : double(SUBPIXEL_ONE);
    const Plane* planes[3] = {&setup.q, &setup.pu, &setup.pv};
    double* out[3] = {a.q, a.pu, a.pv};
    for (int k = 0; k < 3; ++k) {
        out[k][0] = planes[k]->a0;
        out[k][1] = planes[k]->gx;
        out[k][2] = planes[k]->gy;
    }
    c.loop(&a);
}

void exact_loop(const void* raw) {
    const auto& a = *static_cast<const ExactArgs*>(raw);
    const Plane q{a.q[0], a.q[1], a.q[2]}, pu{a.pu[0], a.pu[1], a.pu[2]}, pv{a.pv[0], a.pv[1], a.pv[2]};
    const Texture tex{a.texels, a.width, a.height, a.clamp ? Wrap::Clamp : Wrap::Repeat};
    uint8_t* dst = a.dst;
    double x = a.x, y = a.y;
    for (int32_t n = 0; n < a.count; ++n) {
        int32_t tu, tv;
        perspective_texel(q, pu, pv, x, y, &tu, &tv);
        *dst = texel(tex, tu, tv);
        dst += a.stride;
        x += a.step_x;  // exact: integers below 2^53, and adding 0 changes nothing
        y += a.step_y;
    }
}

// The bound: the reference's definition, bit for bit (a test on thousands of triangles).
ErrorBound exact_bound(const BoundContext& c, const Vertex* vertices, int count) {
    ErrorBound b;
    b.draws = setup_takes(c, vertices, count);
    b.exact_coverage = true;
    b.footprint = 0;
    return b;
}

// The loop's random cases (core/selftest.h).
LoopCheck check_exact(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<ExactArgs>(m, other, seed, cases, buf, [&](Random& r, ExactArgs& a) {
        random_check_texture(r, buf, a);
        a.reserved = 0;
        a.count = random_count(r, 0, 3, 320);
        a.stride = random_stride(r);
        CheckWindow window = place_span(buf, a, a.stride);
        double sign = r.below(4) == 0 ? -1.0 : 1.0;
        bool rows = r.below(2) == 0;
        a.step_x = rows ? sign * 256 : 0;
        a.step_y = rows ? 0 : sign * 256;
        a.x = double(r.range(-120000, 120000)) + 128;
        a.y = double(r.range(-90000, 90000)) + 128;
        random_planes(r, a.q, a.pu, a.pv);
        return window;
    });
}

#if defined(MODEXLAB_OFFSETS)
// The block layouts asm/exact.asm reads (core/asm_offsets.h).
void exact_offsets() {
    ASM_FIELDS(EXACT, ExactArgs, dst, stride, count, texels, width, height, clamp, x, y, step_x, step_y, q, pu, pv)
    ASM_SIZE(EXACT_ARGS_SIZE, ExactArgs);
}
#endif

}  // namespace raster
