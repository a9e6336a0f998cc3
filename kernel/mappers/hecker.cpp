// hecker-steptable: Chris Hecker's subdividing perspective mapper (SUBAFXFL setup, part V's step-table
// loop), with its rules and flaws (docs/classics.md); the twin and the loop's checks.
#include "kernel/mappers/hecker.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/bound.h"
#include "kernel/core/footprint.h"
#include "kernel/core/selftest.h"

#include "kernel/mappers/classic.h"

namespace raster::hecker {

namespace {

constexpr int AFFINE_LENGTH = 8;
constexpr int32_t HALF = 0x8000;

struct Vertex28 {
    int32_t x_28_4, y_28_4;  // pixel centres at integers (plain ints: a Fixed28_4 would zero every vertex first)
    double one_over_z;  // 1/w
    double u_over_z, v_over_z;
};

struct Gradients {
    double one_over_z[3], u_over_z[3], v_over_z[3];
    double d_one_over_z_dx, d_one_over_z_dy, d_u_over_z_dx, d_u_over_z_dy, d_v_over_z_dx, d_v_over_z_dy;
    int32_t du_dx_modifier, dv_dx_modifier;
};

// ceil(v / 16) for a 28.4 value (Hecker's Ceil28_4)
int64_t ceil28_4(int64_t v) { return floor_div(v - 1 + 16, 16); }

// Hecker's FloorDivMod: the mathematical floor and a non-negative remainder.
void floor_div_mod(int64_t numerator, int64_t denominator, int64_t* floor, int64_t* mod) {
    *floor = floor_div(numerator, denominator);
    *mod = numerator - *floor * denominator;
}

// C's float-to-int cast in 16.16: truncation toward zero, saturated where the cast would be undefined.
int32_t to_fixed16_16(double x) {
    double t = x * 65536.0;
    if (!(t == t)) return 0;
    if (t >= 2147483647.0) return INT32_MAX;
    if (t <= -2147483648.0) return INT32_MIN;
    return int32_t(t);
}

// Returns false for a triangle whose 28.4 cross product is zero (Hecker would divide by zero).
bool make_gradients(const Vertex28* v, Gradients* g) {
    for (int i = 0; i < 3; ++i) {
        g->one_over_z[i] = v[i].one_over_z;
        g->u_over_z[i] = v[i].u_over_z;
        g->v_over_z[i] = v[i].v_over_z;
    }
    // Fixed28_4Mul: (a * b) / 16, C division
    int64_t x1y0 = (int64_t(v[1].x_28_4 - v[2].x_28_4) * (v[0].y_28_4 - v[2].y_28_4)) / 16;
    int64_t x0y1 = (int64_t(v[0].x_28_4 - v[2].x_28_4) * (v[1].y_28_4 - v[2].y_28_4)) / 16;
    if (x1y0 - x0y1 == 0) return false;
    double one_over_dx = 1.0 / (double(x1y0 - x0y1) / 16.0);
    double one_over_dy = -one_over_dx;
    double y0y2 = double(v[0].y_28_4 - v[2].y_28_4) / 16.0, y1y2 = double(v[1].y_28_4 - v[2].y_28_4) / 16.0;
    double x0x2 = double(v[0].x_28_4 - v[2].x_28_4) / 16.0, x1x2 = double(v[1].x_28_4 - v[2].x_28_4) / 16.0;
    auto ddx = [&](const double* c) { return one_over_dx * (((c[1] - c[2]) * y0y2) - ((c[0] - c[2]) * y1y2)); };
    auto ddy = [&](const double* c) { return one_over_dy * (((c[1] - c[2]) * x0x2) - ((c[0] - c[2]) * x1x2)); };
    g->d_one_over_z_dx = ddx(g->one_over_z);
    g->d_one_over_z_dy = ddy(g->one_over_z);
    g->d_u_over_z_dx = ddx(g->u_over_z);
    g->d_u_over_z_dy = ddy(g->u_over_z);
    g->d_v_over_z_dx = ddx(g->v_over_z);
    g->d_v_over_z_dy = ddy(g->v_over_z);
    // GRADIENT.TXT: the sign of du/dx's numerator picks floor(u + 1/2) or ceil(u - 1/2)
    auto modifier = [&](double d_dx, double d_dy, const double* c) {
        double x_indicator = d_dx * g->one_over_z[0] - c[0] * g->d_one_over_z_dx;
        if (x_indicator > 0) return HALF;
        if (x_indicator < 0) return HALF - 1;
        double y_indicator = d_dy * g->one_over_z[0] - c[0] * g->d_one_over_z_dy;
        return y_indicator >= 0 ? HALF : HALF - 1;
    };
    g->du_dx_modifier = modifier(g->d_u_over_z_dx, g->d_u_over_z_dy, g->u_over_z);
    g->dv_dx_modifier = modifier(g->d_v_over_z_dx, g->d_v_over_z_dy, g->v_over_z);
    return true;
}

// An edge from top to bottom: x by the floor-div/mod DDA, the interpolants prestepped to the
// first pixel centre and stepped along with it (with the extra x-gradient on a DDA carry).
struct Edge {
    int64_t x, x_step, numerator, denominator, error_term;
    int64_t y, height;
    double one_over_z, one_over_z_step, one_over_z_extra;
    double u_over_z, u_over_z_step, u_over_z_extra;
    double v_over_z, v_over_z_step, v_over_z_extra;

    Edge(const Gradients& g, const Vertex28* v, int top, int bottom) {
        y = ceil28_4(v[top].y_28_4);
        int64_t y_end = ceil28_4(v[bottom].y_28_4);
        height = y_end - y;
        x = 0, x_step = 0, numerator = 0, denominator = 1, error_term = 0;
        one_over_z = u_over_z = v_over_z = 0;
        one_over_z_step = u_over_z_step = v_over_z_step = 0;
        one_over_z_extra = u_over_z_extra = v_over_z_extra = 0;
        if (!height) return;
        int64_t dn = int64_t(v[bottom].y_28_4) - v[top].y_28_4, dm = int64_t(v[bottom].x_28_4) - v[top].x_28_4;
        int64_t initial = dm * 16 * y - dm * v[top].y_28_4 + dn * v[top].x_28_4 - 1 + dn * 16;
        floor_div_mod(initial, dn * 16, &x, &error_term);
        floor_div_mod(dm * 16, dn * 16, &x_step, &numerator);
        denominator = dn * 16;
        double y_prestep = double(y * 16 - v[top].y_28_4) / 16.0;
        double x_prestep = double(x * 16 - v[top].x_28_4) / 16.0;
        one_over_z = g.one_over_z[top] + y_prestep * g.d_one_over_z_dy + x_prestep * g.d_one_over_z_dx;
        one_over_z_step = double(x_step) * g.d_one_over_z_dx + g.d_one_over_z_dy;
        one_over_z_extra = g.d_one_over_z_dx;
        u_over_z = g.u_over_z[top] + y_prestep * g.d_u_over_z_dy + x_prestep * g.d_u_over_z_dx;
        u_over_z_step = double(x_step) * g.d_u_over_z_dx + g.d_u_over_z_dy;
        u_over_z_extra = g.d_u_over_z_dx;
        v_over_z = g.v_over_z[top] + y_prestep * g.d_v_over_z_dy + x_prestep * g.d_v_over_z_dx;
        v_over_z_step = double(x_step) * g.d_v_over_z_dx + g.d_v_over_z_dy;
        v_over_z_extra = g.d_v_over_z_dx;
    }

    void step() {
        x += x_step;
        ++y;
        --height;
        one_over_z += one_over_z_step;
        u_over_z += u_over_z_step;
        v_over_z += v_over_z_step;
        error_term += numerator;
        if (error_term >= denominator) {
            ++x;
            error_term -= denominator;
            one_over_z += one_over_z_extra;
            u_over_z += u_over_z_extra;
            v_over_z += v_over_z_extra;
        }
    }
};

// Draws pixels [x0, x0 + n) of the row with u, v starting at the 16.16 values u and v (pixel x0)
// and stepping du, dv; only the part inside [clip_lo, clip_hi) is drawn, the state advanced past
// the rest exactly as stepping would.
void affine_piece(const DrawContext& c, uint8_t* row, int64_t x0, int64_t n, int32_t u, int32_t v, int32_t du, int32_t dv) {
    int64_t lo = x0 < c.target.clip.x0 ? c.target.clip.x0 : x0;
    int64_t hi = x0 + n > c.target.clip.x1 ? c.target.clip.x1 : x0 + n;
    if (lo >= hi) return;
    uint32_t skip = uint32_t(lo - x0);
    u = int32_t(uint32_t(u) + skip * uint32_t(du));
    v = int32_t(uint32_t(v) + skip * uint32_t(dv));
    const int32_t pitch = bordered_pitch(c.tex);
    // His loop reads wherever the piece points: texel floor((u + k du) / 65536) along u (the
    // fractions' carries make it exactly that), likewise v, monotonic in k. Where the piece's first
    // or last pixel would read outside the bordered copy (-1 .. size: his truncated 28.4 vertices
    // and rounding modifier extrapolated over a steep gradient; the fuzzer found one), the memory
    // he would have read is not ours: each pixel takes the nearest texel of the copy instead, and
    // his bound has none there (within_border).
    const int64_t last = hi - lo - 1;
    auto index = [](int32_t t, int32_t dt, int64_t k) { return (int64_t(t) + k * dt) >> 16; };
    auto inside = [&](int64_t i, int32_t size) { return i >= -1 && i <= size; };
    if (!inside(index(u, du, 0), c.tex.width) || !inside(index(u, du, last), c.tex.width) || !inside(index(v, dv, 0), c.tex.height) ||
        !inside(index(v, dv, last), c.tex.height)) {
        auto clamp = [](int64_t i, int32_t size) { return i < -1 ? -1 : i > size ? size : i; };
        for (int64_t k = 0; k <= last; ++k)
            row[lo + k] = bordered_origin(c.tex)[clamp(index(u, du, k), c.tex.width) + clamp(index(v, dv, k), c.tex.height) * pitch];
        tally(c.stats, 1, uint32_t(last + 1));
        return;
    }
    HeckerArgs a;
    a.dst = row + lo;
    a.count = int32_t(hi - lo);
    a.texel = bordered_origin(c.tex) + (u >> 16) + (v >> 16) * pitch;
    a.u_frac = uint32_t(u) << 16;
    a.v_frac = uint32_t(v) << 16;
    a.du_frac = uint32_t(du) << 16;
    a.dv_frac = uint32_t(dv) << 16;
    a.step_no_carry = (du >> 16) + (dv >> 16) * pitch;
    a.step_carry = a.step_no_carry + pitch;
    c.loop(&a);  // inside the scan line's emit(): the whole routine is the inner loop
    tally(c.stats, 1, uint32_t(a.count));
}

// SUBAFXFL's DrawScanLine: subdivide every 8 pixels; the last piece aims at the last pixel. Calls
// piece(x0, n, u, v, du, dv) for each affine piece: pixels [x0, x0 + n) from 16.16 u, v at x0.
template <typename F>
void scan_line_pieces(const Gradients& g, const Edge& left, const Edge& right, F&& piece) {
    int64_t x_start = left.x, width = right.x - x_start;
    if (width <= 0) return;
    double one_over_z_left = left.one_over_z, u_over_z_left = left.u_over_z, v_over_z_left = left.v_over_z;
    double d_one_over_z_aff = g.d_one_over_z_dx * AFFINE_LENGTH;
    double d_u_over_z_aff = g.d_u_over_z_dx * AFFINE_LENGTH, d_v_over_z_aff = g.d_v_over_z_dx * AFFINE_LENGTH;
    double one_over_z_right = one_over_z_left + d_one_over_z_aff;
    double u_over_z_right = u_over_z_left + d_u_over_z_aff, v_over_z_right = v_over_z_left + d_v_over_z_aff;
    double z_left = 1 / one_over_z_left, u_left = z_left * u_over_z_left, v_left = z_left * v_over_z_left;
    int64_t subdivisions = width / AFFINE_LENGTH, width_mod_length = width % AFFINE_LENGTH;
    if (!width_mod_length) {
        --subdivisions;
        width_mod_length = AFFINE_LENGTH;
    }
    int64_t x = x_start;
    while (subdivisions-- > 0) {
        double z_right = 1 / one_over_z_right;
        double u_right = z_right * u_over_z_right, v_right = z_right * v_over_z_right;
        int32_t u = to_fixed16_16(u_left) + g.du_dx_modifier, v = to_fixed16_16(v_left) + g.dv_dx_modifier;
        int32_t du = to_fixed16_16(u_right - u_left) / AFFINE_LENGTH, dv = to_fixed16_16(v_right - v_left) / AFFINE_LENGTH;
        piece(x, int64_t(AFFINE_LENGTH), u, v, du, dv);
        x += AFFINE_LENGTH;
        u_left = u_right;
        v_left = v_right;
        one_over_z_right += d_one_over_z_aff;
        u_over_z_right += d_u_over_z_aff;
        v_over_z_right += d_v_over_z_aff;
    }
    // the last piece: from the current left values to the last pixel of the span
    double z_right = 1 / (right.one_over_z - g.d_one_over_z_dx);
    double u_right = z_right * (right.u_over_z - g.d_u_over_z_dx), v_right = z_right * (right.v_over_z - g.d_v_over_z_dx);
    int32_t u = to_fixed16_16(u_left) + g.du_dx_modifier, v = to_fixed16_16(v_left) + g.dv_dx_modifier;
    int32_t du = 0, dv = 0;  // a 1-pixel piece never steps (Hecker left them unset)
    if (width_mod_length > 1) {
        du = to_fixed16_16(u_right - u_left) / int32_t(width_mod_length - 1);
        dv = to_fixed16_16(v_right - v_left) / int32_t(width_mod_length - 1);
    }
    piece(x, width_mod_length, u, v, du, dv);
}

// A triangle as Hecker walks it: the gradients, the three edges, then `ready()` (the setup done)
// and line(g, left, right) for every scan line inside the clip, the upper half between top-middle
// and top-bottom, then the lower half (his two loops).
template <typename R, typename F>
void walk_triangle(const Vertex28* v, const ClipRect& clip, R&& ready, F&& line) {
    Gradients g;
    if (!make_gradients(v, &g)) return;
    // top, middle, bottom by y; the middle vertex is on the left when it lies left of top-bottom
    int top = 0, middle = 1, bottom = 2;
    if (v[middle].y_28_4 < v[top].y_28_4) { int t = top; top = middle; middle = t; }
    if (v[bottom].y_28_4 < v[middle].y_28_4) { int t = middle; middle = bottom; bottom = t; }
    if (v[middle].y_28_4 < v[top].y_28_4) { int t = top; top = middle; middle = t; }
    int64_t side = int64_t(v[bottom].x_28_4 - v[top].x_28_4) * (v[middle].y_28_4 - v[top].y_28_4) - int64_t(v[bottom].y_28_4 - v[top].y_28_4) * (v[middle].x_28_4 - v[top].x_28_4);
    bool middle_is_left = side > 0;
    Edge top_to_bottom(g, v, top, bottom), top_to_middle(g, v, top, middle), middle_to_bottom(g, v, middle, bottom);
    ready();
    auto scan = [&](Edge& short_edge) {
        Edge* left = middle_is_left ? &short_edge : &top_to_bottom;
        Edge* right = middle_is_left ? &top_to_bottom : &short_edge;
        for (int64_t h = short_edge.height; h-- > 0;) {
            if (left->y >= clip.y0 && left->y < clip.y1) line(g, *left, *right);
            short_edge.step();
            top_to_bottom.step();
        }
    };
    scan(top_to_middle);
    scan(middle_to_bottom);
}

void draw_triangle(const DrawContext& c, const Vertex28* tri) {
    const Target& t = c.target;
    walk_triangle(tri, t.clip, [&] { setup_done(c); }, [&](const Gradients& g, const Edge& left, const Edge& right) {
        uint8_t* row = t.base + left.y * t.pitch;
        // the span routine (its divides and pieces) is the inner loop
        emit(c.stats->probe, c.stats, 0, 0, [&] {
            scan_line_pieces(g, left, right, [&](int64_t x0, int64_t n, int32_t u, int32_t v, int32_t du, int32_t dv) {
                affine_piece(c, row, x0, n, u, v, du, dv);
            });
        });
    });
}

// The polygon in his vertices (28.4, texel centres at integers) after the checks the driver makes;
// shift: the whole periods added to u and v.
SetupStatus convert_polygon(const Vertex* vertices, int count, const Texture& tex, Vertex28* v, double* shift) {
    SetupStatus status = classic::texture_shift(vertices, count, tex, &shift[0], &shift[1]);
    if (status != SetupStatus::Ok) return status;
    // A convex polygon must really be one: Hecker drew triangles, here its fan.
    PolygonSetup check;
    status = setup_polygon(vertices, count, &check, PLANES_NONE);
    if (status != SetupStatus::Ok) return status;
    for (int i = 0; i < count; ++i) {
        const Vertex& in = vertices[i];
        // 28.4 with pixel centres at integers: (x - 1/2) * 16, truncated as FloatToFixed28_4 did
        v[i].x_28_4 = (in.x.raw - int32_t(SUBPIXEL_HALF)) / 16;
        v[i].y_28_4 = (in.y.raw - int32_t(SUBPIXEL_HALF)) / 16;
        v[i].one_over_z = 1.0 / in.w;
        v[i].u_over_z = (in.u + shift[0] - 0.5) / in.w;  // texel centres at integers
        v[i].v_over_z = (in.v + shift[1] - 0.5) / in.w;
    }
    return SetupStatus::Ok;
}

}  // namespace

SetupStatus draw(const DrawContext& c, const Vertex* vertices, int count) {
    Vertex28 v[classic::MAX_VERTICES];
    double shift[2];
    SetupStatus status = convert_polygon(vertices, count, c.tex, v, shift);
    if (status != SetupStatus::Ok) return status;
    for (int k = 1; k + 1 < count; ++k) {
        Vertex28 tri[3] = {v[0], v[k], v[k + 1]};
        draw_triangle(c, tri);
    }
    return SetupStatus::Ok;
}

// The bound (docs/bounds.md, "Hecker's pieces"): his walk and his divides run again, and each
// affine piece's texel indices, floor((u + k du) / 65536) along u and v (the loop's 16-bit
// fractions carry into the texel pointer: exactly that), against the exact mapping at its pixel
// centres (lines_bound) over every pixel he draws. The bordered copy as for X-Sharp: one texel
// more where a piece reaches the border, no bound beyond it or where Q is not positive.
ErrorBound bound(const BoundContext& c, const Vertex* vertices, int count) {
    ErrorBound b;
    Vertex28 v[classic::MAX_VERTICES];
    double shift[2];
    if (!mapper_accepts(c.mapper, c.tex) || convert_polygon(vertices, count, c.tex, v, shift) != SetupStatus::Ok) return b;
    PolygonSetup own;
    const PolygonSetup* s = exact_setup(c, vertices, count, &own, &b);
    if (!s) return b;
    const double size[2] = {double(c.tex.width), double(c.tex.height)};
    double worst = 0;
    bool fits = true;
    for (int k = 1; k + 1 < count && fits && !c.settled(worst); ++k) {
        Vertex28 tri[3] = {v[0], v[k], v[k + 1]};
        walk_triangle(tri, c.clip, [] {}, [&](const Gradients& g, const Edge& left, const Edge& right) {
            scan_line_pieces(g, left, right, [&](int64_t x0, int64_t n, int32_t u, int32_t pv, int32_t du, int32_t dv) {
                const int64_t lo = x0 < c.clip.x0 ? c.clip.x0 : x0, hi = x0 + n > c.clip.x1 ? c.clip.x1 : x0 + n;
                if (lo >= hi || !fits || c.settled(worst)) return;
                const int32_t start[2] = {u, pv}, delta[2] = {du, dv};
                double a[2], step[2], border = 0;
                for (int t = 0; t < 2; ++t) {
                    a[t] = double(int64_t(start[t]) + (lo - x0) * delta[t]) / 65536, step[t] = double(delta[t]) / 65536;
                    fits = fits && within_border(a[t], step[t], double(hi - lo - 1), size[t], &border);
                    a[t] -= shift[t];  // the unshifted coordinates, as the reference's
                }
                if (fits) worst = larger(worst, drawn_line_bound(*s, Axis::Rows, Span{int32_t(lo), int32_t(left.y), int32_t(hi - lo)}, a, step, border));
                fits = fits && worst < NO_BOUND;
            });
        });
    }
    b.footprint = fits ? worst : NO_BOUND;
    return b;
}

}  // namespace raster::hecker

namespace raster {

void hecker_loop(const void* raw) {
    const auto& a = *static_cast<const HeckerArgs*>(raw);
    uint8_t* dst = a.dst;
    const uint8_t* texel = a.texel;
    uint32_t u = a.u_frac, v = a.v_frac;
    for (int32_t n = 0; n < a.count; ++n) {
        *dst++ = *texel;
        uint32_t v_next = v + a.dv_frac;
        bool v_carry = v_next < v;  // add; sbb ebp, ebp
        v = v_next;
        uint32_t u_next = u + a.du_frac;
        int32_t u_carry = u_next < u;
        u = u_next;
        texel += (v_carry ? a.step_carry : a.step_no_carry) + u_carry;  // adc esi, [table + 4*ebp]
    }
}

// The loop's random cases (core/selftest.h).
LoopCheck check_hecker(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<HeckerArgs>(m, other, seed, cases, buf, [&](Random& r, HeckerArgs& a) {
        int32_t pitch = r.range(3, 600);  // any width: the step table holds the pitch
        a.count = random_count(r, 0, 3, 320);
        a.texel = buf.texels + CHECK_TEXEL_MID + r.range(-1000, 1000);
        a.u_frac = r.next() & 0xFFFF0000u;
        a.v_frac = r.next() & 0xFFFF0000u;
        a.du_frac = r.below(8) == 0 ? 0 : r.next() & 0xFFFF0000u;
        a.dv_frac = r.below(8) == 0 ? 0 : r.next() & 0xFFFF0000u;
        a.step_no_carry = r.range(-3, 3) + r.range(-1, 1) * pitch;
        a.step_carry = a.step_no_carry + (r.below(2) ? pitch : -pitch);
        return place_span(buf, a, 1);
    });
}

#if defined(MODEXLAB_OFFSETS)
// The block layouts asm/hecker.asm reads (core/asm_offsets.h).
void hecker_offsets() {
    ASM_FIELDS(HECKER, HeckerArgs, dst, count, texel, u_frac, v_frac, du_frac, dv_frac, step_carry, step_no_carry)
}
#endif

}  // namespace raster
