// xsharp-dda, xsharp-row-out and xsharp-column: X-Sharp's texture mappers (Black Book listings 57.1,
// 57.2/58.1, 58.4) with their flaws (docs/mappers.md); the twins and the loops' checks.
#include "kernel/mappers/xsharp.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/selftest.h"

#include "kernel/mappers/classic.h"

namespace raster::xsharp {

namespace {

using classic::counting_fraction;
using classic::fixed_div;
using classic::fixed_mul;
using classic::round_fixed;
using classic::split;
using classic::SplitStep;
using classic::Vertex16;

// X-Sharp's texel coordinates put texel centres at integers.
constexpr double TEXEL_OFFSET = -0.5;

// One edge of the destination polygon, stepped one line (row or column) at a time: the source
// position in 16.16, and the destination's other coordinate by an all-integer Bresenham stepper.
struct Edge {
    int direction;             // through the vertex list
    int remaining, current_end;
    int32_t source_x, source_y, step_x, step_y;
    int32_t dest, int_step, dest_direction, err, adj_up, adj_down;
};

struct Polygon {
    Vertex16 v[classic::MAX_VERTICES];
    int n;
    int max_vert;
    bool columns;  // scanning columns: the roles of x and y swap
};

int32_t along(const Vertex16& v, bool columns) { return columns ? v.x : v.y; }   // the scan direction
int32_t across(const Vertex16& v, bool columns) { return columns ? v.y : v.x; }  // within a line

// The polygon in X-Sharp's terms (whole-pixel vertices, texture coordinates shifted into the
// texture), refused unless monotone along the scan; its first and last vertex along the scan
// (DRAWTEXP.C's MinVert and MaxVert, the first of equals).
SetupStatus prepare(const DrawContext& c, const Vertex* vertices, int count, bool columns, Polygon* p, int* min_vert) {
    p->columns = columns;
    SetupStatus status = classic::convert(vertices, count, c.tex, TEXEL_OFFSET, p->v, &p->n);
    if (status != SetupStatus::Ok) return status;
    if (!classic::monotone(p->v, p->n, columns)) return SetupStatus::NotConvex;
    int lo = 0, hi = 0;
    for (int i = 1; i < p->n; ++i) {
        if (along(p->v[i], columns) < along(p->v[lo], columns)) lo = i;
        if (along(p->v[i], columns) > along(p->v[hi], columns)) hi = i;
    }
    if (along(p->v[lo], columns) >= along(p->v[hi], columns)) return SetupStatus::Degenerate;
    *min_vert = lo;
    p->max_vert = hi;
    return SetupStatus::Ok;
}

// DRAWTEXP.C's SetUpEdge, rows (X-Sharp 21) or columns (X-Sharp 22). Returns false when the edge
// chain has reached the far vertex.
bool set_up_edge(Edge& e, int start, const Polygon& p) {
    for (;;) {
        if (start == p.max_vert) return false;
        int next = start + e.direction;
        if (next >= p.n) next = 0;
        else if (next < 0) next = p.n - 1;
        e.remaining = along(p.v[next], p.columns) - along(p.v[start], p.columns);
        if (e.remaining != 0) {
            int32_t length = e.remaining << 16;
            e.current_end = next;
            e.source_x = p.v[start].u_16_16;
            e.source_y = p.v[start].v_16_16;
            e.step_x = fixed_div(p.v[next].u_16_16 - e.source_x, length);
            e.step_y = fixed_div(p.v[next].v_16_16 - e.source_y, length);
            int32_t width = across(p.v[next], p.columns) - across(p.v[start], p.columns);
            if (!p.columns) {
                // rows: DestX = ceil of the true edge x, both directions
                e.dest = across(p.v[start], false);
                if (width < 0) {
                    e.dest_direction = -1;
                    width = -width;
                    e.err = 1 - e.remaining;
                    e.int_step = -(width / e.remaining);
                } else {
                    e.dest_direction = 1;
                    e.err = 0;
                    e.int_step = width / e.remaining;
                }
            } else {
                // columns: floor(y) + 1 going down, ceil(y) going up or level, which keeps the
                // row filler's top-left convention ("tweaking the edge-scanning code", ch. 58)
                if (width <= 0) {
                    e.dest_direction = -1;
                    width = -width;
                    e.int_step = -(width / e.remaining);
                    e.dest = across(p.v[start], true);
                } else {
                    e.dest_direction = 1;
                    e.int_step = width / e.remaining;
                    e.dest = across(p.v[start], true) + 1;
                }
                e.err = 1 - e.remaining;
            }
            e.adj_up = width % e.remaining;
            e.adj_down = e.remaining;
            return true;
        }
        start = next;
    }
}

bool step_edge(Edge& e, const Polygon& p) {
    if (--e.remaining == 0) return set_up_edge(e, e.current_end, p);
    e.source_x += e.step_x;
    e.source_y += e.step_y;
    e.dest += e.int_step;
    if ((e.err += e.adj_up) > 0) {
        e.dest += e.dest_direction;
        e.err -= e.adj_down;
    }
    return true;
}

// The span between two row edges, common to 57.1 and 57.2: steps from the unclipped width, the
// half-step, then the clip. Returns false when nothing is left to draw.
struct SpanSetup {
    int32_t x, count;
    int32_t source_x, source_y, step_x, step_y;
};

bool span_setup(const Edge& left, const Edge& right, const ClipRect& clip, SpanSetup* s) {
    int32_t x_max = right.dest, x = left.dest;
    if (x_max <= clip.x0 || x >= clip.x1) return false;
    if (x_max - x <= 0) return false;
    int32_t width = (x_max - x) << 16;
    s->step_x = fixed_div(right.source_x - left.source_x, width);
    s->step_y = fixed_div(right.source_y - left.source_y, width);
    s->source_x = left.source_x + (s->step_x >> 1);  // the half-step prestep (57.1)
    s->source_y = left.source_y + (s->step_y >> 1);
    if (x_max > clip.x1) x_max = clip.x1;
    if (x < clip.x0) {
        s->source_x += fixed_mul(s->step_x, (clip.x0 - x) << 16);
        s->source_y += fixed_mul(s->step_y, (clip.x0 - x) << 16);
        x = clip.x0;
    }
    s->x = x;
    s->count = x_max - x;
    return true;
}

using RowSpanFn = void (*)(const DrawContext& c, const SpanSetup& s, int32_t y);

// 57.1: ScanOutLine in C; WritePixelX per pixel.
void dda_span(const DrawContext& c, const SpanSetup& s, int32_t y) {
    const uint8_t* origin = bordered_origin(c.tex);
    const int32_t pitch = bordered_pitch(c.tex);
    int32_t sx = s.source_x, sy = s.source_y;
    for (int32_t x = s.x; x < s.x + s.count; ++x) {
        *pixel_at(c.target, x, y) = origin[round_fixed(sy) * pitch + round_fixed(sx)];
        sx = int32_t(uint32_t(sx) + uint32_t(s.step_x));
        sy = int32_t(uint32_t(sy) + uint32_t(s.step_y));
    }
}

// 57.2: the rounding folded into the initial texel pointer, only fractions stepped.
void row_out_span(const DrawContext& c, const SpanSetup& s, int32_t y) {
    const int32_t pitch = bordered_pitch(c.tex);
    int32_t sx = int32_t(uint32_t(s.source_x) + 0x8000), sy = int32_t(uint32_t(s.source_y) + 0x8000);
    SplitStep xs = split(s.step_x), ys = split(s.step_y);
    XSharpRowArgs a;
    const Target& t = c.target;
    a.dst = t.base + y * t.row_bytes + (s.x >> 2);
    a.plane_bytes = t.plane_bytes;
    a.count = s.count;
    a.mask = 0x11u << (s.x & 3);
    a.texel = bordered_origin(c.tex) + (sy >> 16) * pitch + (sx >> 16);
    a.x_frac = counting_fraction(sx, s.step_x);
    a.y_frac = counting_fraction(sy, s.step_y);
    a.x_step = xs.fraction;
    a.y_step = ys.fraction;
    a.x_base = xs.whole;
    a.x_carry = xs.carry_advance;
    a.y_base = ys.whole * pitch;
    a.y_carry = ys.carry_advance * pitch;
    a.select_plane = t.select_plane;
    a.ctx = t.ctx;
    c.loop(&a);
}

SetupStatus draw_rows(const DrawContext& c, const Vertex* vertices, int count, RowSpanFn span) {
    Polygon p;
    int min_vert;
    SetupStatus status = prepare(c, vertices, count, false, &p, &min_vert);
    if (status != SetupStatus::Ok) return status;
    Edge left, right;
    left.direction = -1;
    right.direction = 1;
    set_up_edge(left, min_vert, p);
    set_up_edge(right, min_vert, p);
    setup_done(c);
    const ClipRect& clip = c.target.clip;
    for (int32_t y = p.v[min_vert].y;; ++y) {
        if (y >= clip.y1) break;
        SpanSetup s;
        if (y >= clip.y0 && span_setup(left, right, clip, &s)) {
            emit(c.stats->probe, c.stats, 1, uint32_t(s.count), [&] { span(c, s, y); });  // the span routine is the inner loop
        }
        if (!step_edge(left, p) || !step_edge(right, p)) break;
    }
    return SetupStatus::Ok;
}

// X-Sharp 22's column ScanOutLine: steps from the column's pixel count, half-step, clip, the
// rounding folded into the pointer, the fractions packed for the 58.4 loop.
void column_span(const DrawContext& c, const Edge& top, const Edge& bottom, int32_t x) {
    const ClipRect& clip = c.target.clip;
    int32_t y_max = bottom.dest, y = top.dest;
    if (y_max <= clip.y0 || y >= clip.y1 || y_max - y <= 0) return;
    int32_t height = (y_max - y) << 16;
    int32_t step_x = fixed_div(bottom.source_x - top.source_x, height);
    int32_t step_y = fixed_div(bottom.source_y - top.source_y, height);
    int32_t sx = top.source_x + (step_x >> 1), sy = top.source_y + (step_y >> 1);
    if (y_max > clip.y1) y_max = clip.y1;
    if (y < clip.y0) {
        sx += fixed_mul(step_x, (clip.y0 - y) << 16);
        sy += fixed_mul(step_y, (clip.y0 - y) << 16);
        y = clip.y0;
    }
    const int32_t pitch = bordered_pitch(c.tex);
    sx = int32_t(uint32_t(sx) + 0x8000);
    sy = int32_t(uint32_t(sy) + 0x8000);
    SplitStep xs = split(step_x), ys = split(step_y);
    XSharpColumnArgs a;
    Target& t = c.target;
    int plane = x & 3;
    if (t.select_plane) t.select_plane(t.ctx, plane);  // the map mask, once per column
    a.dst = t.base + plane * t.plane_bytes + y * t.row_bytes + (x >> 2);
    a.count = y_max - y;
    a.texel = bordered_origin(c.tex) + (sy >> 16) * pitch + (sx >> 16);
    a.fractions = (counting_fraction(sx, step_x) << 16) | (counting_fraction(sy, step_y) >> 1);
    a.steps = (xs.fraction << 16) | (ys.fraction >> 1);  // the Y fraction keeps 15 bits
    a.base = xs.whole + ys.whole * pitch;
    a.row = ys.carry_advance * pitch;
    a.backwards = step_x < 0;
    emit(c, &a, 1, uint32_t(a.count));
}

}  // namespace

SetupStatus draw_dda(const DrawContext& c, const Vertex* vertices, int count) { return draw_rows(c, vertices, count, dda_span); }

SetupStatus draw_row_out(const DrawContext& c, const Vertex* vertices, int count) {
    return draw_rows(c, vertices, count, row_out_span);
}

SetupStatus draw_column(const DrawContext& c, const Vertex* vertices, int count) {
    Polygon p;
    int min_vert;
    SetupStatus status = prepare(c, vertices, count, true, &p, &min_vert);
    if (status != SetupStatus::Ok) return status;
    Edge top, bottom;
    top.direction = 1;
    bottom.direction = -1;
    set_up_edge(top, min_vert, p);
    set_up_edge(bottom, min_vert, p);
    setup_done(c);
    for (int32_t x = p.v[min_vert].x;; ++x) {
        if (x >= c.target.clip.x1) break;
        if (x >= c.target.clip.x0) column_span(c, top, bottom, x);
        if (!step_edge(top, p) || !step_edge(bottom, p)) break;
    }
    return SetupStatus::Ok;
}

}  // namespace raster::xsharp

namespace raster {

void xsharp_row_loop(const void* raw) {
    const auto& a = *static_cast<const XSharpRowArgs*>(raw);
    uint8_t* dst = a.dst;
    const uint8_t* texel = a.texel;
    uint32_t mask = a.mask & 0xFF, x_frac = a.x_frac, y_frac = a.y_frac;
    for (int32_t n = 0; n < a.count; ++n) {
        int plane = (mask & 0x0F) == 1 ? 0 : (mask & 0x0F) == 2 ? 1 : (mask & 0x0F) == 4 ? 2 : 3;  // the Map Mask's plane
        if (a.select_plane) a.select_plane(a.ctx, plane);  // out dx, al
        dst[plane * a.plane_bytes] = *texel;
        texel += a.x_base;
        x_frac += a.x_step;
        if (x_frac > 0xFFFF) {
            x_frac &= 0xFFFF;
            texel += a.x_carry;
        }
        texel += a.y_base;
        y_frac += a.y_step;
        if (y_frac > 0xFFFF) {
            y_frac &= 0xFFFF;
            texel += a.y_carry;
        }
        uint32_t carry = mask >> 7;  // rol al, 1; adc edi, 0
        mask = ((mask << 1) | carry) & 0xFF;
        dst += carry;
    }
}

void xsharp_column_loop(const void* raw) {
    const auto& a = *static_cast<const XSharpColumnArgs*>(raw);
    uint8_t* dst = a.dst;
    const uint8_t* texel = a.texel;
    uint32_t f = a.fractions;
    for (int32_t n = 0; n < a.count; ++n) {
        uint8_t b = *texel;
        uint32_t sum = f + a.steps;
        int32_t carry = sum < f;  // out of bit 31: the X fraction's carry
        f = sum;
        texel += a.backwards ? a.base - carry : a.base + carry;
        *dst = b;
        if (f & 0x8000) {  // the Y fraction's carry, caught in bit 15
            texel += a.row;
            f &= ~0x8000u;
        }
        dst += XSHARP_SCANWIDTH;
    }
}

// The loop's random cases (core/selftest.h).
LoopCheck check_xsharp_column(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<XSharpColumnArgs>(m, other, seed, cases, buf, [&](Random& r, XSharpColumnArgs& a) {
        int32_t pitch = random_texture_size(r) + 2;  // a bordered texture's pitch: 3..1026
        a.count = random_count(r, 1, 3, 240);
        a.texel = buf.texels + CHECK_TEXEL_MID + r.range(-1000, 1000);
        a.fractions = (r.next() & 0xFFFF0000u) | (r.next() & 0x7FFF);
        a.steps = (r.next() & 0xFFFF0000u) | (r.next() & 0x7FFF);
        if (r.below(4) == 0) a.steps &= 0xFFFF7FFFu & (r.below(2) ? 0x0000FFFFu : 0xFFFF0000u);  // one axis without a fraction
        a.base = r.range(-2, 2) + r.range(-1, 1) * pitch;
        a.row = r.below(2) ? pitch : -pitch;
        a.backwards = int32_t(r.below(2));
        return place_span(buf, a, XSHARP_SCANWIDTH);
    });
}

void random_xsharp_row(Random& r, const uint8_t* texels, XSharpRowArgs* a, int32_t* x, int32_t* y) {
    int32_t pitch = r.range(3, 600);
    *y = r.range(0, 239);
    *x = r.range(0, 319);
    a->count = r.range(1, 320 - *x);
    a->mask = 0x11u << (*x & 3);
    a->texel = texels + CHECK_TEXEL_MID + r.range(-1000, 1000);
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

#if defined(MODEXLAB_OFFSETS)
// The block layouts asm/xsharp.asm reads (core/asm_offsets.h).
void xsharp_offsets() {
    ASM_FIELDS(XROW, XSharpRowArgs, dst, count, mask, texel, x_frac, y_frac, x_step, y_step, x_base, x_carry, y_base, y_carry)
    ASM_FIELDS(XCOL, XSharpColumnArgs, dst, count, texel, fractions, steps, base, row, backwards)
    ASM_SIZE(XROW_ARGS_SIZE, XSharpRowArgs);
    ASM_CONSTANT(XSHARP_SCANWIDTH, XSHARP_SCANWIDTH);
}
#endif

}  // namespace raster
