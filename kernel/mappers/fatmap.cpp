// fatmap-256, fatmap-256-16 and fatmap-lut: Mats Byggmastar's fatmap.txt triangle function and his
// three inner loops, with their rules and flaws (docs/classics.md); the twins and the loops' checks.
#include "kernel/mappers/fatmap.h"

#include "kernel/core/asm_offsets.h"
#include "kernel/core/bound.h"
#include "kernel/core/footprint.h"
#include "kernel/core/selftest.h"

#include "kernel/mappers/classic.h"

namespace raster::fatmap {

namespace {

struct FVertex {
    int32_t x, y;  // whole pixels
    int32_t u_26_6, v_26_6;
};

// fatmap-lut's table of offsets, for scanlines up to 2 * 8192 pixels; the NASM loop reads one
// entry past the last pixel's.
constexpr int32_t MAX_LUT = 2 * classic::MAX_COORD + 2;
using LutTable = int32_t[MAX_LUT + 1];

// shl10idiv: (a << 10) / b with a 64-bit dividend, truncating like idiv; saturates where idiv
// would have raised a divide error.
int32_t shl10idiv(int64_t a, int32_t b) {
    int64_t q = (a * 1024) / b;
    return q > INT32_MAX ? INT32_MAX : q < INT32_MIN ? INT32_MIN : int32_t(q);
}

struct Section {
    const FVertex* array[3];
    int section;
    int height;
    int32_t x, dx, u, du, v, dv;
};

// RightSection / LeftSection: the deltas along the current section; 0 for a flat one.
int set_section(Section& s, bool left) {
    const FVertex* v1 = s.array[s.section];
    const FVertex* v2 = s.array[s.section - 1];
    int height = v2->y - v1->y;
    if (height == 0) return 0;
    s.dx = ((v2->x - v1->x) << 16) / height;
    s.x = v1->x << 16;
    if (left) {
        s.du = ((v2->u_26_6 - v1->u_26_6) << 10) / height;
        s.u = v1->u_26_6 << 10;
        s.dv = ((v2->v_26_6 - v1->v_26_6) << 10) / height;
        s.v = v1->v_26_6 << 10;
    }
    s.height = height;
    return height;
}

// A triangle as his function sets it up: the sections, the constant deltas across, its first row.
struct Triangle {
    Section left, right;
    int32_t dudx, dvdx, longest;
    int32_t y;
};

// His setup; false where he draws nothing (no height, no width, a flat section).
bool set_up_triangle(const FVertex* vtx, Triangle* out) {
    Triangle& t = *out;
    const FVertex* v1 = &vtx[0];
    const FVertex* v2 = &vtx[1];
    const FVertex* v3 = &vtx[2];
    if (v1->y > v2->y) { const FVertex* s = v1; v1 = v2; v2 = s; }
    if (v1->y > v3->y) { const FVertex* s = v1; v1 = v3; v3 = s; }
    if (v2->y > v3->y) { const FVertex* s = v2; v2 = v3; v3 = s; }
    int height = v3->y - v1->y;
    if (height == 0) return false;
    int32_t temp = ((v2->y - v1->y) << 16) / height;
    int32_t longest = temp * (v3->x - v1->x) + ((v1->x - v2->x) << 16);
    if (longest == 0) return false;
    Section& left = t.left;
    Section& right = t.right;
    if (longest < 0) {  // the middle vertex on the right
        right.array[0] = v3, right.array[1] = v2, right.array[2] = v1, right.section = 2;
        left.array[0] = v3, left.array[1] = v1, left.section = 1;
        if (set_section(left, true) <= 0) return false;
        if (set_section(right, false) <= 0) {
            right.section--;
            if (set_section(right, false) <= 0) return false;
        }
        if (longest > -0x1000) longest = -0x1000;  // "ugly compensation"
    } else {
        left.array[0] = v3, left.array[1] = v2, left.array[2] = v1, left.section = 2;
        right.array[0] = v3, right.array[1] = v1, right.section = 1;
        if (set_section(right, false) <= 0) return false;
        if (set_section(left, true) <= 0) {
            left.section--;
            if (set_section(left, true) <= 0) return false;
        }
        if (longest < 0x1000) longest = 0x1000;
    }
    t.dudx = shl10idiv(int64_t(temp) * (v3->u_26_6 - v1->u_26_6) + (int64_t(v1->u_26_6 - v2->u_26_6) << 16), longest);
    t.dvdx = shl10idiv(int64_t(temp) * (v3->v_26_6 - v1->v_26_6) + (int64_t(v1->v_26_6 - v2->v_26_6) << 16), longest);
    t.longest = longest;
    t.y = v1->y;
    return true;
}

// fatmap-lut's table length for the triangle: the longest scanline's pixels and one more.
int32_t lut_length(const Triangle& t) {
    int32_t length = ((t.longest < 0 ? -t.longest : t.longest) >> 16) + 2;
    return length > MAX_LUT ? MAX_LUT : length;
}

// A row he draws inside the clip: its first pixel, its pixels, the pixels section 17's clipping
// skipped at its left, and the edge's u, v there (16:16); fatmap-lut's first table entry.
struct Row {
    int32_t y, x, count, skipped;
    int32_t left_u, left_v;
    int32_t first;
};

// Calls row(Row) for each row of the triangle with pixels inside the clip, top down, as his loop
// walks them (the edges stepped by their deltas, the sections in turn); table_length: fatmap-lut's
// table (its rows end at the table's end), or 0.
template <typename F>
void for_each_row(Triangle& t, const ClipRect& clip, int32_t table_length, F&& row) {
    Section& left = t.left;
    Section& right = t.right;
    for (int32_t y = t.y;; ++y) {
        int32_t x1 = left.x >> 16;
        int32_t width = (right.x >> 16) - x1;
        if (width > 0 && y >= clip.y0 && y < clip.y1) {
            // section 17's clipping: pixels skipped at either end
            int32_t lo = x1 < clip.x0 ? clip.x0 : x1, hi = x1 + width > clip.x1 ? clip.x1 : x1 + width;
            if (lo < hi) {
                Row r{y, lo, hi - lo, lo - x1, left.u, left.v, 0};
                if (table_length > 0) {
                    r.first = r.skipped < table_length ? r.skipped : table_length - 1;
                    r.count = r.count < table_length - r.first ? r.count : table_length - r.first;
                }
                row(r);
            }
        }
        if (y >= clip.y1) return;
        if (--left.height <= 0) {
            if (--left.section <= 0) return;
            if (set_section(left, true) <= 0) return;
        } else {
            left.x += left.dx;
            left.u += left.du;
            left.v += left.dv;
        }
        if (--right.height <= 0) {
            if (--right.section <= 0) return;
            if (set_section(right, false) <= 0) return;
        } else {
            right.x += right.dx;
        }
    }
}

// lut: fatmap-lut's table, filled for each triangle; null for the other loops.
void draw_triangle(const DrawContext& c, const FVertex* vtx, int32_t* lut) {
    Triangle tri;
    if (!set_up_triangle(vtx, &tri)) return;
    int32_t table_length = 0;
    if (lut) {
        // one offset per pixel of the longest scanline, from u = v = 0 (24:8)
        int32_t du = tri.dudx >> 8, dv = tri.dvdx >> 8, u = 0, v = 0;
        table_length = lut_length(tri);
        for (int32_t k = 0; k < table_length; ++k) {
            lut[k] = (u >> 8) + int32_t(uint32_t(v) & 0xFFFFFF00u);
            u += du;
            v += dv;
        }
    }
    setup_done(c);
    const Target& t = c.target;
    for_each_row(tri, t.clip, table_length, [&](const Row& r) {
        uint8_t* dst = t.base + r.y * t.pitch + r.x;
        if (lut) {
            FatmapLutArgs a;
            a.dst = dst;
            a.count = r.count;
            // his C: bitmap + (left_u >> 16) + (left_v >> 16) * 256 (the table holds the rest)
            a.source = c.tex.aligned256 + (r.left_u >> 16) + (r.left_v >> 16) * 256;
            a.table = lut + r.first;
            emit(c, &a, 1, uint32_t(a.count));
        } else {
            FatmapArgs a;
            a.dst = dst;
            a.count = r.count;
            a.texture = c.tex.aligned256;
            a.u_16_16 = int32_t(uint32_t(r.left_u) + uint32_t(r.skipped) * uint32_t(tri.dudx));
            a.v_16_16 = int32_t(uint32_t(r.left_v) + uint32_t(r.skipped) * uint32_t(tri.dvdx));
            a.du_16_16 = tri.dudx;
            a.dv_16_16 = tri.dvdx;
            emit(c, &a, 1, uint32_t(a.count));
        }
    });
}

// The polygon in his vertices (whole pixels, 26:6 texture coordinates shifted by whole periods
// into [0, limit]), after the checks every driver makes; shift: the periods added to u and v.
SetupStatus convert_polygon(const Vertex* vertices, int count, const Texture& tex, double limit, FVertex* v, double* shift) {
    // the loops wrap at 256 (fatmap-lut does not): whole periods of the texture; the 16:16
    // arithmetic holds +-32768 texels
    SetupStatus status = classic::texture_shift(vertices, count, tex, limit, limit, &shift[0], &shift[1]);
    if (status != SetupStatus::Ok) return status;
    PolygonSetup check;  // a convex polygon, drawn as a fan of triangles
    status = setup_polygon(vertices, count, &check, PLANES_NONE);
    if (status != SetupStatus::Ok) return status;
    for (int i = 0; i < count; ++i) {
        v[i].x = (vertices[i].x.raw + int32_t(SUBPIXEL_HALF)) >> SUBPIXEL_BITS;
        v[i].y = (vertices[i].y.raw + int32_t(SUBPIXEL_HALF)) >> SUBPIXEL_BITS;
        v[i].u_26_6 = int32_t(floor_i64((vertices[i].u + shift[0]) * 64 + 0.5));
        v[i].v_26_6 = int32_t(floor_i64((vertices[i].v + shift[1]) * 64 + 0.5));
    }
    return SetupStatus::Ok;
}

SetupStatus draw(const DrawContext& c, const Vertex* vertices, int count, int32_t* lut, double limit) {
    FVertex v[classic::MAX_VERTICES];
    double shift[2];
    SetupStatus status = convert_polygon(vertices, count, c.tex, limit, v, shift);
    if (status != SetupStatus::Ok) return status;
    for (int k = 1; k + 1 < count; ++k) {
        FVertex tri[3] = {v[0], v[k], v[k + 1]};
        draw_triangle(c, tri, lut);
    }
    return SetupStatus::Ok;
}

// What each loop reads at pixel k of a row: the texel floor(a + b k) along u and v (t = 0, 1),
// with a, b from the row exactly (no rounding left over: the loops' arithmetic is integer);
// repeat wraps it at 256 (fatmap-lut's address does not wrap: the texel is that only while the
// line stays inside the texture, which its bound checks).
enum class Loop { Bits8, Bits16, Table };
struct RowLines {
    double a[2], b[2];
};
RowLines row_lines(Loop loop, const Triangle& t, const Row& r) {
    RowLines l;
    const int32_t left[2] = {r.left_u, r.left_v}, delta[2] = {t.dudx, t.dvdx};
    for (int i = 0; i < 2; ++i) {
        const int64_t start = int64_t(left[i]) + int64_t(r.skipped) * delta[i];  // 16:16, unwrapped (256 divides 65536)
        if (loop == Loop::Bits16) {  // 8:16: every bit of the 16:16 values kept
            l.a[i] = double(start) / 65536, l.b[i] = double(delta[i]) / 65536;
        } else if (loop == Loop::Bits8) {  // 24:8 (u) and two bytes (v): 8-bit fractions, floored
            l.a[i] = double(floor_div(start, 256)) / 256, l.b[i] = double(floor_div(delta[i], 256)) / 256;
        } else {  // the scanline's whole texel, then table entry first + k: floor((first + k) (delta >> 8) / 256) more
            const double step = double(delta[i] >> 8) / 256;
            l.a[i] = double(left[i] >> 16) + double(r.first) * step, l.b[i] = step;
        }
    }
    return l;
}

// The bound (docs/bounds.md, "fatmap's rows"): his setup run again, row by row, and each row's
// lines against the exact mapping at its pixel centres (lines_bound, pieces of BOUND_PIECE
// pixels), over every pixel he draws (the ones the reference covers among them). No bound where Q
// is not positive along a row, where fatmap-lut's table overflows 32 bits or its lines leave the
// texture. Coverage his own; he draws what the driver takes.
ErrorBound bound(const BoundContext& c, const Vertex* vertices, int count, Loop loop, double limit) {
    ErrorBound b;
    FVertex v[classic::MAX_VERTICES];
    double shift[2];
    if (!mapper_accepts(c.mapper, c.tex) || convert_polygon(vertices, count, c.tex, limit, v, shift) != SetupStatus::Ok) return b;
    PolygonSetup own;
    const PolygonSetup* s = exact_setup(c, vertices, count, &own, &b);
    if (!s) return b;
    double worst = 0;
    bool fits = true;
    for (int k = 1; k + 1 < count && fits && !c.settled(worst); ++k) {
        FVertex tri[3] = {v[0], v[k], v[k + 1]};
        Triangle t;
        if (!set_up_triangle(tri, &t)) continue;
        int32_t table_length = 0;
        if (loop == Loop::Table) {
            table_length = lut_length(t);
            const double reach = double(table_length) * 256;  // |k (delta >> 8)| within int32 for every entry (with room: delta, not delta >> 8)
            fits = fits && magnitude(double(t.dudx)) < 2147483647.0 * 256 / reach && magnitude(double(t.dvdx)) < 2147483647.0 * 256 / reach;
        }
        for_each_row(t, c.clip, table_length, [&](const Row& r) {
            if (!fits || c.settled(worst)) return;
            const double last = double(r.count - 1);
            RowLines lines = row_lines(loop, t, r);
            for (int i = 0; i < 2; ++i) {
                if (loop == Loop::Table) {  // the address is the texel's only inside the texture
                    const double lo = lines.a[i] + (lines.b[i] < 0 ? lines.b[i] * last : 0), hi = lines.a[i] + (lines.b[i] > 0 ? lines.b[i] * last : 0);
                    fits = fits && lo >= 0 && hi < 256;
                }
                lines.a[i] -= shift[i];  // the unshifted coordinates, as the reference's
            }
            if (fits) worst = larger(worst, drawn_line_bound(*s, Axis::Rows, Span{r.x, r.y, r.count}, lines.a, lines.b, 0));
            fits = fits && worst < NO_BOUND;
        });
    }
    b.footprint = fits ? worst : NO_BOUND;
    return b;
}

}  // namespace

// the 16:16 arithmetic of u << 10 holds 32768 texels; keep well inside
constexpr double WRAPPING_LIMIT = 16384;

SetupStatus draw_256(const DrawContext& c, const Vertex* vertices, int count) {
    return draw(c, vertices, count, nullptr, WRAPPING_LIMIT);
}

ErrorBound bound_256(const BoundContext& c, const Vertex* vertices, int count) {
    return bound(c, vertices, count, Loop::Bits8, WRAPPING_LIMIT);
}
ErrorBound bound_256_16(const BoundContext& c, const Vertex* vertices, int count) {
    return bound(c, vertices, count, Loop::Bits16, WRAPPING_LIMIT);
}
ErrorBound bound_lut(const BoundContext& c, const Vertex* vertices, int count) { return bound(c, vertices, count, Loop::Table, 256); }

SetupStatus draw_lut(const DrawContext& c, const Vertex* vertices, int count) {
    LutTable table;  // 64 KiB on the stack, not a global: the core keeps no state (boot/entry.asm sizes the stack for it)
    return draw(c, vertices, count, table, 256);
}

}  // namespace raster::fatmap

namespace raster {

void fatmap_loop(const void* raw) {
    const auto& a = *static_cast<const FatmapArgs*>(raw);
    // his 5-tick loop: u as 24:8 in ecx (bl = ch), v as the bytes dh (fraction) and bh (whole)
    uint32_t u = uint32_t(a.u_16_16) >> 8, du = uint32_t(a.du_16_16) >> 8;
    uint32_t v_frac = (uint32_t(a.v_16_16) >> 8) & 0xFF, v_whole = (uint32_t(a.v_16_16) >> 16) & 0xFF;
    uint32_t dv_frac = (uint32_t(a.dv_16_16) >> 8) & 0xFF, dv_whole = (uint32_t(a.dv_16_16) >> 16) & 0xFF;
    uint8_t* dst = a.dst;
    for (int32_t n = 0; n < a.count; ++n) {
        uint32_t u_whole = (u >> 8) & 0xFF;
        u += du;
        dst[n] = a.texture[(v_whole << 8) | u_whole];
        v_frac += dv_frac;  // add dh, dl; adc bh, ah
        v_whole = (v_whole + dv_whole + (v_frac >> 8)) & 0xFF;
        v_frac &= 0xFF;
    }
}

void fatmap16_loop(const void* raw) {
    const auto& a = *static_cast<const FatmapArgs*>(raw);
    // fatmap2's 8:16 loop: fractions in the high halves, wholes in bl (u) and bh (v)
    uint32_t u_frac = uint32_t(a.u_16_16) << 16, v_frac = uint32_t(a.v_16_16) << 16;
    uint32_t u_whole = (uint32_t(a.u_16_16) >> 16) & 0xFF, v_whole = (uint32_t(a.v_16_16) >> 16) & 0xFF;
    uint32_t du_frac = uint32_t(a.du_16_16) << 16, dv_frac = uint32_t(a.dv_16_16) << 16;
    uint32_t du_whole = (uint32_t(a.du_16_16) >> 16) & 0xFF, dv_whole = (uint32_t(a.dv_16_16) >> 16) & 0xFF;
    uint8_t* dst = a.dst;
    for (int32_t n = 0; n < a.count; ++n) {
        dst[n] = a.texture[(v_whole << 8) | u_whole];
        uint32_t v_next = v_frac + dv_frac;
        v_whole = (v_whole + dv_whole + (v_next < v_frac)) & 0xFF;
        v_frac = v_next;
        uint32_t u_next = u_frac + du_frac;
        u_whole = (u_whole + du_whole + (u_next < u_frac)) & 0xFF;
        u_frac = u_next;
    }
}

void fatmap_lut_loop(const void* raw) {
    const auto& a = *static_cast<const FatmapLutArgs*>(raw);
    for (int32_t n = 0; n < a.count; ++n) a.dst[n] = a.source[a.table[n]];
}

// The loop's random cases (core/selftest.h).
LoopCheck check_fatmap(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    return check_cases<FatmapArgs>(m, other, seed, cases, buf, [&](Random& r, FatmapArgs& a) {
        a.count = random_count(r, 0, 3, 320);
        a.texture = check_aligned_texture(buf);
        random_uv(r, a);
        return place_span(buf, a, 1);
    });
}

LoopCheck check_fatmap_lut(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buf) {
    int32_t table[321];  // count entries and the one the NASM loop reads past the last
    return check_cases<FatmapLutArgs>(m, other, seed, cases, buf, [&](Random& r, FatmapLutArgs& a) {
        a.count = random_count(r, 0, 3, 320);
        a.source = buf.texels + CHECK_TEXEL_MID + r.range(-1000, 1000);
        int32_t du = r.range(-512, 512), dv = r.range(-512, 512), u = 0, v = 0;
        for (int32_t k = 0; k <= a.count; ++k) {  // as fatmap builds it (24:8 steps, pitch 256)
            table[k] = (u >> 8) + int32_t(uint32_t(v) & 0xFFFFFF00u);
            u += du;
            v += dv;
        }
        a.table = table;
        return place_span(buf, a, 1);
    });
}

#if defined(MODEXLAB_OFFSETS)
// The block layouts asm/fatmap.asm reads (core/asm_offsets.h).
void fatmap_offsets() {
    ASM_FIELDS(FATMAP, FatmapArgs, dst, count, texture, u_16_16, v_16_16, du_16_16, dv_16_16)
    ASM_FIELDS(LUT, FatmapLutArgs, dst, count, source, table)
}
#endif

}  // namespace raster
