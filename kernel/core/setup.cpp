// Polygon setup: orientation, repeated-vertex removal, range and convexity checks, edges, planes.
#include "kernel/core/setup.h"

#if defined(MODEXLAB_OFFSETS)
#include "kernel/core/asm_offsets.h"
#endif

namespace raster {

namespace {

// Each test is written so that NaN fails it (every comparison with NaN is false), and infinities
// lie outside every range: no separate finiteness test.
bool in_range(const Vertex& v) {
    constexpr int32_t LIMIT = MAX_COORD_PIXELS << SUBPIXEL_BITS;
    if (v.x.raw > LIMIT || v.x.raw < -LIMIT || v.y.raw > LIMIT || v.y.raw < -LIMIT) return false;
    return v.w >= MIN_W && v.w <= MAX_W && magnitude(v.u) <= MAX_UV && magnitude(v.v) <= MAX_UV;
}

int64_t edge_function(const Edge& e, int64_t x, int64_t y) { return int64_t(e.dx) * (y - e.py) - int64_t(e.dy) * (x - e.px); }

// Twice the signed area of triangle (a, b, c): the cross product (b - a) x (c - a). The corners are
// in range (within 2^22 subpixels): the differences fit in 32 bits, and each product of two is one
// 32 x 32 -> 64-bit multiply on i686 (three for a 64 x 64 one).
int64_t fan_area2(const Vertex& a, const Vertex& b, const Vertex& c) {
    int32_t xb = b.x.raw - a.x.raw, yb = b.y.raw - a.y.raw;
    int32_t xc = c.x.raw - a.x.raw, yc = c.y.raw - a.y.raw;
    return int64_t(xb) * yc - int64_t(xc) * yb;
}

// How often the outline's direction along y (or x) reverses, going once round; edges along the
// other axis do not count.
int direction_changes(const PolygonSetup& s, bool along_y) {
    int changes = 0, last = 0;
    for (int pass = 0; pass < 2; ++pass)
        for (int i = 0; i < s.edge_count; ++i) {
            int64_t d = along_y ? s.edges[i].dy : s.edges[i].dx;
            int sign = d > 0 ? 1 : d < 0 ? -1 : 0;
            if (sign == 0) continue;
            if (pass == 1 && last != 0 && sign != last) ++changes;
            last = sign;
        }
    return changes;
}

}  // namespace

Plane plane_through(double ra, double rb, double rc, double xb, double yb, double xc, double yc, double d) {
    Plane p;
    p.a0 = ra;
    p.gx = ((rb - ra) * yc - (rc - ra) * yb) / d;
    p.gy = ((rc - ra) * xb - (rb - ra) * xc) / d;
    return p;
}

const char* setup_status_name(SetupStatus s) {
    switch (s) {
    case SetupStatus::Ok: return "ok";
    case SetupStatus::Degenerate: return "degenerate";
    case SetupStatus::NotConvex: return "not convex";
    case SetupStatus::TooManyVertices: return "too many vertices";
    case SetupStatus::OutOfRange: return "out of range";
    case SetupStatus::OutsideTexture: return "outside the texture";
    case SetupStatus::Unsupported: return "unsupported by the mapper";
    case SetupStatus::Unproven: return "not within the envelope";
    }
    return "?";
}

namespace {

// What setup does once the outline is known: v[0..n-1] clockwise (y down), no vertex repeating
// its predecessor, area2 twice its (positive) area, and (n > 3) convexity still to check. N: the
// corners where known (a triangle's 3, a quad's 4: the loops unrolled), else 0 (n = count).
template <int N>
[[gnu::always_inline]] inline SetupStatus finish_setup(const Vertex* const* v, int count, int64_t area2, PolygonSetup* out, SetupPlanes planes) {
    const int n = N ? N : count;
    PolygonSetup& s = *out;
    s.edge_count = n;
    s.area2 = area2;
#pragma GCC unroll 4
    for (int i = 0; i < n; ++i) {
        const Vertex& a = *v[i];
        const Vertex& b = *v[i + 1 < n ? i + 1 : 0];
        Edge& e = s.edges[i];
        e.px = a.x.raw;
        e.py = a.y.raw;
        e.dx = b.x.raw - a.x.raw;
        e.dy = b.y.raw - a.y.raw;
        // top edge: horizontal with the inside below (dx > 0); left edge: going up (dy < 0)
        e.threshold = (e.dy < 0 || (e.dy == 0 && e.dx > 0)) ? 0 : 1;
    }
    int32_t min_x = v[0]->x.raw, max_x = min_x, min_y = v[0]->y.raw, max_y = min_y;  // (in 32 bits, then widened)
#pragma GCC unroll 4
    for (int i = 1; i < n; ++i) {
        if (v[i]->x.raw < min_x) min_x = v[i]->x.raw;
        if (v[i]->x.raw > max_x) max_x = v[i]->x.raw;
        if (v[i]->y.raw < min_y) min_y = v[i]->y.raw;
        if (v[i]->y.raw > max_y) max_y = v[i]->y.raw;
    }
    s.min_x = min_x, s.max_x = max_x, s.min_y = min_y, s.max_y = max_y;
    if (n > 3) {  // (a triangle with positive area is convex and winds once)
        // Convex: every vertex on the inner side of (or on) every edge. Exact; rejects stars too.
        // (An edge's own ends lie on it. Within a box under 2^15 subpixels a side, 128 pixels,
        // each product is below 2^30 and their difference fits in 32 bits: on i686 a 64-bit
        // product is three multiplies.)
        constexpr int64_t SMALL = int64_t(1) << 15;
        const bool small = s.max_x - s.min_x < SMALL && s.max_y - s.min_y < SMALL;
        for (int i = 0; i < n; ++i) {
            const Edge& e = s.edges[i];
            for (int k = i + 2; k < i + n; ++k) {
                const Vertex& p = *v[k < n ? k : k - n];
                const bool outside = small ? int32_t(e.dx) * (p.y.raw - int32_t(e.py)) - int32_t(e.dy) * (p.x.raw - int32_t(e.px)) < 0
                                           : edge_function(e, p.x.raw, p.y.raw) < 0;
                if (outside) return SetupStatus::NotConvex;
            }
        }
        // ... and winding once: going round, y (and x) turns back exactly twice. A convex outline
        // traced twice passes the test above; the walkers rely on one chain of edges a side.
        if (direction_changes(s, true) != 2 || direction_changes(s, false) != 2) return SetupStatus::NotConvex;
    }

    s.ref_x = v[0]->x.raw;
    s.ref_y = v[0]->y.raw;
    if (planes == PLANES_NONE) return SetupStatus::Ok;

    // The planes come from the fan triangle (0, k, k+1) of largest area: the best-conditioned one.
    int best = 1;
    int64_t best_area = area2;  // a triangle's own
    if (n > 3) {
        best_area = -1;
        for (int k = 1; k + 1 < n; ++k) {
            int64_t a = fan_area2(*v[0], *v[k], *v[k + 1]);
            if (a > best_area) {
                best_area = a;
                best = k;
            }
        }
    }
    const Vertex& va = *v[0];
    const Vertex& vb = *v[best];
    const Vertex& vc = *v[best + 1];
    // (differences within 2^23: in 32 bits, converted from 32 bits)
    const double xb = double(vb.x.raw - va.x.raw), yb = double(vb.y.raw - va.y.raw);
    const double xc = double(vc.x.raw - va.x.raw), yc = double(vc.y.raw - va.y.raw);
    double d = double(best_area);
    if (planes & PLANES_PERSPECTIVE) {
        double qa = 1.0 / va.w, qb = 1.0 / vb.w, qc = 1.0 / vc.w;
        s.q = plane_through(qa, qb, qc, xb, yb, xc, yc, d);
        s.pu = plane_through(va.u / va.w, vb.u / vb.w, vc.u / vc.w, xb, yb, xc, yc, d);
        s.pv = plane_through(va.v / va.w, vb.v / vb.w, vc.v / vc.w, xb, yb, xc, yc, d);
    }
    if (!(planes & PLANES_AFFINE)) return SetupStatus::Ok;
    s.u = plane_through(va.u, vb.u, vc.u, xb, yb, xc, yc, d);
    s.v = plane_through(va.v, vb.v, vc.v, xb, yb, xc, yc, d);
    // the fixed-point planes: anchored at the pixel whose centre is nearest the reference vertex;
    // the anchor value reduced modulo 65536 texels (what 16.16 holds), which changes no texel
    // (the shifts floor; the anchor pixel holds the reference vertex, so its centre is within a
    // pixel of it, in 32 bits as for a span)
    const int32_t x0 = int32_t(s.ref_x >> SUBPIXEL_BITS), y0 = int32_t(s.ref_y >> SUBPIXEL_BITS);
    const double ax = span_centre_x(s, x0), ay = span_centre_y(s, y0);
    const Plane* affine[2] = {&s.u, &s.v};
    FixedPlane* fixed[2] = {&s.u_fx, &s.v_fx};
    for (int k = 0; k < 2; ++k) {
        fixed[k]->x0 = x0;
        fixed[k]->y0 = y0;
        fixed[k]->dx = Fixed16_16::from_double(affine[k]->gx * double(SUBPIXEL_ONE)).raw;
        fixed[k]->dy = Fixed16_16::from_double(affine[k]->gy * double(SUBPIXEL_ONE)).raw;
        double at = affine[k]->at(ax, ay);
        if (at >= 0 && at < 16384.0) {  // the reduction below leaves it as it is: one 32-bit floor
            fixed[k]->at = floor_small(at * 65536.0 + 0.5);
            continue;
        }
        at -= 65536.0 * double(floor_i64(at / 65536.0));
        fixed[k]->at = int32_t(uint32_t(floor_i64(at * 65536.0 + 0.5)));
    }
    return SetupStatus::Ok;
}

bool same_point(const Vertex& a, const Vertex& b) { return a.x.raw == b.x.raw && a.y.raw == b.y.raw; }

}  // namespace

bool vertices_in_range(const Vertex* vertices, int count) {
    for (int i = 0; i < count; ++i)
        if (!in_range(vertices[i])) return false;
    return true;
}

SetupStatus setup_polygon_cpp(const Vertex* in, int count, PolygonSetup* out, SetupPlanes planes, Input input) {
    if (count > MAX_POLYGON_VERTICES) return SetupStatus::TooManyVertices;
    if (count < 3) return SetupStatus::Degenerate;
    if (input == Input::Any && !vertices_in_range(in, count)) return SetupStatus::OutOfRange;

    if (count == 3) {
        // a triangle: any two corners at one point leave fewer than three (degenerate), as does a
        // zero area; a triangle with positive area is convex and winds once. Clockwise as below
        // (the order reversed: c, b, a).
        if (same_point(in[0], in[1]) || same_point(in[1], in[2]) || same_point(in[2], in[0])) return SetupStatus::Degenerate;
        const int64_t area2 = fan_area2(in[0], in[1], in[2]);
        if (area2 == 0) return SetupStatus::Degenerate;
        const Vertex* v[3] = {&in[0], &in[1], &in[2]};
        if (area2 < 0) v[0] = &in[2], v[2] = &in[0];
        return finish_setup<3>(v, 3, area2 < 0 ? -area2 : area2, out, planes);
    }

    // Drop vertices that repeat their predecessor (a zero-length edge would exclude everything).
    const Vertex* v[MAX_POLYGON_VERTICES];
    int n = 0;
    for (int i = 0; i < count; ++i)
        if (n == 0 || !same_point(in[i], *v[n - 1])) v[n++] = &in[i];
    while (n > 1 && same_point(*v[n - 1], *v[0])) --n;
    if (n < 3) return SetupStatus::Degenerate;

    // Twice the signed area, as the fan of triangles (0, k, k+1); positive is clockwise on the
    // y-down screen.
    int64_t area2 = 0;
    for (int k = 1; k + 1 < n; ++k) area2 += fan_area2(*v[0], *v[k], *v[k + 1]);
    if (area2 == 0) {
        // all on one line: degenerate; otherwise lobes of opposite winding (a bow tie): malformed
        for (int i = 2; i < n; ++i) {
            int64_t cross = (int64_t(v[1]->x.raw) - v[0]->x.raw) * (int64_t(v[i]->y.raw) - v[0]->y.raw) -
                            (int64_t(v[1]->y.raw) - v[0]->y.raw) * (int64_t(v[i]->x.raw) - v[0]->x.raw);
            if (cross != 0) return SetupStatus::NotConvex;
        }
        return SetupStatus::Degenerate;
    }
    if (area2 < 0) {
        for (int i = 0, j = n - 1; i < j; ++i, --j) {
            const Vertex* t = v[i];
            v[i] = v[j];
            v[j] = t;
        }
    }
    if (area2 < 0) area2 = -area2;
    return n == 4 ? finish_setup<4>(v, 4, area2, out, planes) : finish_setup<0>(v, n, area2, out, planes);
}

bool covers(const PolygonSetup& s, int32_t x, int32_t y) {
    int64_t px = int64_t(x) * SUBPIXEL_ONE + SUBPIXEL_HALF;
    int64_t py = int64_t(y) * SUBPIXEL_ONE + SUBPIXEL_HALF;
    for (int i = 0; i < s.edge_count; ++i)
        if (edge_function(s.edges[i], px, py) < s.edges[i].threshold) return false;
    return true;
}

#if defined(MODEXLAB_OFFSETS)
// The layouts asm/setup.asm and the fast mappers' one-call triangle read (asm_offsets.h).
void setup_offsets() {
    ASM_FIELDS(VERT, Vertex, x, y, u, v)
    ASM_SIZE(VERT_SIZE, Vertex);
    ASM_FIELDS(CLIP, ClipRect, x0, y0, x1, y1)
    ASM_FIELDS(EDGE, Edge, px, py, dx, dy, threshold)
    ASM_SIZE(EDGE_SIZE, Edge);
    ASM_FIELDS(PLANE, Plane, a0, gx, gy)
    ASM_FIELDS(FIX, FixedPlane, x0, y0, at, dx, dy)
    ASM_FIELDS(PS, PolygonSetup, edge_count, edges, area2, ref_x, ref_y, min_x, min_y, max_x, max_y, u, v, u_fx, v_fx)
}
#endif

}  // namespace raster
