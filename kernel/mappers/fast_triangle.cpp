// A frame's triangle for the fast run loops in one call: its setup, its runs and the run loop's
// block (fast_triangle and its kin, the C++ twins of asm/fast_triangle.asm), and the layouts the
// NASM reads.
#include "kernel/mappers/fast.h"

#include "kernel/core/envelope.h"

#if defined(MODEXLAB_OFFSETS)
#include "kernel/core/asm_offsets.h"
#endif

namespace raster {

TriangleTaken fast_triangle(FastTriangleArgs* a) {
    if (setup_polygon_cpp(a->in, 3, a->setup, PLANES_AFFINE, Input::InRange) != SetupStatus::Ok) return TRIANGLE_TO_SETUP;
    return fast_triangle_runs(a);
}

TriangleTaken fast_triangle_enveloped(FastTriangleArgs* a) {
    if (setup_polygon_cpp(a->in, 3, a->setup, PLANES_AFFINE, Input::InRange) != SetupStatus::Ok) return TRIANGLE_TO_SETUP;
    if (!within_envelope(*a->setup, *a->envelope)) return TRIANGLE_OUTSIDE_ENVELOPE;
    return fast_triangle_runs(a);
}

TriangleTaken fast_triangle_runs(FastTriangleArgs* a) {
    const PolygonSetup& s = *a->setup;
    const Target& target = *a->target;
    TriangleRunsArgs t;
    t.setup = &s, t.clip_lo = target.clip.y0, t.clip_hi = target.clip.y1 - 1, t.lower = a->lower, t.upper = a->upper;
    if (!triangle_runs(&t)) return TRIANGLE_TO_WALKER;
    FastRunArgs& r = *a->run;
    r.lines = t.lines;
    if (t.lines == 0) return TRIANGLE_RUNS;
    r.lower = t.run_lower, r.upper = t.run_upper;
    r.next_lines = t.next_lines, r.next_lower = t.next_lower, r.next_upper = t.next_upper;
    r.pitch = target.pitch;
    r.clip_lo = target.clip.x0, r.clip_hi = target.clip.x1 - 1;
    r.row = target.base + t.line * target.pitch;
    r.u_16_16 = uint32_t(s.u_fx.value(0, t.line));
    r.v_16_16 = uint32_t(s.v_fx.value(0, t.line));
    r.u_row_16_16 = uint32_t(s.u_fx.dy), r.v_row_16_16 = uint32_t(s.v_fx.dy);
    r.du_16_16 = s.u_fx.dx, r.dv_16_16 = s.v_fx.dx;
    r.inside = fast::inside_columns(s, target.clip);
    return TRIANGLE_RUNS;
}

#if defined(MODEXLAB_OFFSETS)
// The block and the answers asm/fast_triangle.asm reads and gives (core/asm_offsets.h); the run
// loop's block from fast.inc, core's types' from kernel/core.
void fast_triangle_offsets() {
    ASM_FIELDS(FTRI, FastTriangleArgs, in, setup, run, target, envelope, lower, upper)
    ASM_CONSTANT(TRIANGLE_TO_SETUP, TRIANGLE_TO_SETUP);
    ASM_CONSTANT(TRIANGLE_RUNS, TRIANGLE_RUNS);
    ASM_CONSTANT(TRIANGLE_TO_WALKER, TRIANGLE_TO_WALKER);
    ASM_CONSTANT(TRIANGLE_OUTSIDE_ENVELOPE, TRIANGLE_OUTSIDE_ENVELOPE);
}
#endif

}  // namespace raster
