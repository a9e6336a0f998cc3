// Our fastest affine mappers, for 256 x 256 repeating textures (docs/mappers.md):
//   fast-affine:  rows into a linear surface, by runs of rows that the NASM loop walks itself;
//   fast-columns: columns into Mode X planes (the map mask set once per column).
// Each is its own polygon driver: the setup computes only the affine planes, and each span starts
// from the polygon's 16.16 planes at its first pixel centre (subpixel-correct, exact coverage, no
// per-span floating point). The pixel core is fatmap2's 8:16 loop (16-bit fractions, the wholes in
// bl and bh of a pointer to the 64 KiB-aligned texture) unrolled eight times, entered part-way for
// the remainder, with no per-pixel loop counter.
#include "kernel/mappers/fast.h"

namespace raster::fast {

namespace {

// A polygon's u and v in 16.16 at pixel (x, y): origin + x * dx + y * dy, wrapping.
struct Planes {
    uint32_t u0, v0, udx, udy, vdx, vdy;
    explicit Planes(const PolygonSetup& s)
        : u0(uint32_t(s.u_fx.value(0, 0))), v0(uint32_t(s.v_fx.value(0, 0))), udx(uint32_t(s.u_fx.dx)),
          udy(uint32_t(s.u_fx.dy)), vdx(uint32_t(s.v_fx.dx)), vdy(uint32_t(s.v_fx.dy)) {}
    uint32_t u(int32_t x, int32_t y) const { return u0 + uint32_t(x) * udx + uint32_t(y) * udy; }
    uint32_t v(int32_t x, int32_t y) const { return v0 + uint32_t(x) * vdx + uint32_t(y) * vdy; }
};

}  // namespace

// Rows go by runs: a run's rows have one live bound a side, so the run loop walks them itself. A
// row with a vertex on its centre (two live bounds on a side) is walked by next() and drawn as a
// run of one row between constant bounds.
SetupStatus draw_rows(const DrawContext& c, const Vertex* vertices, int count) {
    PolygonSetup s;
    SetupStatus status = setup_polygon(vertices, count, &s, PLANES_AFFINE);
    if (status != SetupStatus::Ok) return status;
    EdgeWalker walker(s, Axis::Rows, c.target.clip);
    const Planes p(s);
    setup_done(c);
    uint32_t tally[2] = {0, 0};
    FastRunArgs a;
    a.pitch = c.target.pitch;
    a.clip_lo = walker.minor_lo();
    a.clip_hi = walker.minor_hi();
    a.texture = c.tex.aligned256;
    a.u_row = p.udy;
    a.v_row = p.vdy;
    a.du = int32_t(p.udx);
    a.dv = int32_t(p.vdx);
    a.tally = tally;
    for (;;) {
        int32_t line;
        EdgeBound lone_lower, lone_upper;
        a.lines = walker.run(&line, &a.lower, &a.upper);
        if (a.lines > 0) {
            walker.skip(a.lines);
        } else {
            Span span;
            if (!walker.next(&span)) break;
            lone_lower = EdgeBound::constant(span.x);
            lone_upper = EdgeBound::constant(span.x + span.count - 1);
            a.lower = &lone_lower;
            a.upper = &lone_upper;
            a.lines = 1;
            line = span.y;
        }
        a.row = c.target.base + line * c.target.pitch;
        a.u = p.u(0, line);
        a.v = p.v(0, line);
        run_loop(c, &a);
    }
    c.stats->spans += tally[0];
    c.stats->pixels += tally[1];
    return SetupStatus::Ok;
}

// Columns: the walker's spans, one fast_column_loop call each (the map mask set once a column).
SetupStatus draw_columns(const DrawContext& c, const Vertex* vertices, int count) {
    PolygonSetup s;
    SetupStatus status = setup_polygon(vertices, count, &s, PLANES_AFFINE);
    if (status != SetupStatus::Ok) return status;
    EdgeWalker walker(s, Axis::Columns, c.target.clip);
    const Planes p(s);
    setup_done(c);
    FastColumnArgs a;
    a.texture = c.tex.aligned256;
    a.du = int32_t(p.udy);
    a.dv = int32_t(p.vdy);
    uint32_t spans = 0, pixels = 0;
    Span span;
    while (walker.next(&span)) {
        int32_t stride;
        a.dst = span_start(c.target, Axis::Columns, span, &stride);
        a.count = span.count;
        a.u = int32_t(p.u(span.x, span.y));
        a.v = int32_t(p.v(span.x, span.y));
        run_loop(c, &a);
        ++spans;
        pixels += uint32_t(span.count);
    }
    c.stats->spans += spans;
    c.stats->pixels += pixels;
    return SetupStatus::Ok;
}

}  // namespace raster::fast

namespace raster {

namespace {

uint8_t texel256(const uint8_t* texture, uint32_t u, uint32_t v) { return texture[((v >> 8) & 0xFF00) | ((u >> 16) & 0xFF)]; }

}  // namespace

void fast_run_loop(const void* raw) {
    const auto& a = *static_cast<const FastRunArgs*>(raw);
    uint8_t* row = a.row;
    uint32_t u = a.u, v = a.v;
    for (int32_t n = 0; n < a.lines; ++n) {
        int32_t lo = a.lower->q > a.clip_lo ? a.lower->q : a.clip_lo;
        int32_t hi = a.upper->q < a.clip_hi ? a.upper->q : a.clip_hi;
        a.lower->step();
        a.upper->step();
        if (lo <= hi) {
            uint32_t su = u + uint32_t(lo) * uint32_t(a.du), sv = v + uint32_t(lo) * uint32_t(a.dv);
            for (int32_t x = lo; x <= hi; ++x) {
                row[x] = texel256(a.texture, su, sv);
                su += uint32_t(a.du);
                sv += uint32_t(a.dv);
            }
            a.tally[0] += 1;
            a.tally[1] += uint32_t(hi - lo + 1);
        }
        row += a.pitch;
        u += a.u_row;
        v += a.v_row;
    }
}

void fast_column_loop(const void* raw) {
    const auto& a = *static_cast<const FastColumnArgs*>(raw);
    uint32_t u = uint32_t(a.u), v = uint32_t(a.v);
    uint8_t* dst = a.dst;
    for (int32_t n = 0; n < a.count; ++n) {
        *dst = texel256(a.texture, u, v);
        dst += MODEX_ROW_BYTES;
        u += uint32_t(a.du);
        v += uint32_t(a.dv);
    }
}

}  // namespace raster
