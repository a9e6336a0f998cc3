// fast-subdiv-N: our subdividing perspective mapper on the fast 8:16 core (docs/mappers.md): the
// span function, its loop's argument block, the twin and the NASM loop (asm/fastsubdiv.asm).
#pragma once

#include <stdint.h>

#include "kernel/core/bound.h"
#include "kernel/core/mapper.h"
#include "kernel/core/spread.h"

namespace raster {

// One span, segment by segment: the exact point (u, v) = (pu/q, pv/q) at pixel 0, at every
// N = 2^shift pixels after it and at the last pixel, each plane evaluated along the span as the
// reference does (a row: (a0 + gy y) + gx x, c below being a0 + gy y; a column: (a0 + gx x) + gy y),
// scaled to 16.16, rounded to nearest in 64 bits and kept modulo 2^32 (whole 65536-texel periods:
// the tiled block repeats every 256). Between two points the 8:16 core steps by their 32-bit
// difference over the pixels between: by a shift over N, by a division over fewer (the last one).
// Each pixel reads texel (u whole mod W, v whole mod H), from the tiled block or, a side above 256,
// the doubled copy (docs/bounds.md, "The subdivided fast mappers on the doubled copy").
struct FastSubdivArgs {
    uint8_t* dst;            // pixel 0
    int32_t stride;          // bytes from a pixel to the next: 1 (a row, drawn in pairs), or a column's
    int32_t count;           // pixels, 0 or more
    const uint8_t* texture;  // tiled over 256 x 256, aligned to 64 KiB (Texture::aligned256); null: source's doubled copy
    const Texture* source;   // the texture (its doubled copy read where `texture` is null)
    int32_t shift;           // segments of 1 << shift pixels, shift 1 to 9
    double x;                // pixel 0's centre along the span (x, or y: a column), from the reference vertex, subpixels
    double c[3], g[3];       // q, pu, pv on the span's line: a0 + gy y and gx (a row), a0 + gx x and gy (a column)
};

Loop fast_subdiv_loop;

// Segments longer than any row or column (320 pixels at most): one a span, exact at its first and
// last pixels (fast-constant-depth: constant-depth on the fast core).
constexpr int FAST_SPAN_LONG = 512;

template <int N>
void fast_subdiv_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);
template <int N>
ErrorBound fast_subdiv_bound(const BoundContext& c, const Vertex* vertices, int count);

// fast-adaptive-B (B = QUARTERS / 4 footprints, 1 or more): the same loop, its segments as long as
// the relative chords bound allows, span by span: the longest power of two from 2 to 512 pixels
// whose chords keep every pixel within B footprints (docs/bounds.md, "Adaptive segments on the
// fast core"). Along a span Q is linear: a chord of h pixels deviates at each pixel by at most
// X = h^2 |Q'| / (4 Q_lo) times that pixel's own step (Q' a pixel along the span, Q_lo the least
// of Q at the span's ends), and relative_chords_bound(X, r) <= B where X <= fast_adaptive_room(B)
// and the rounding r (16.16 over up to 511 steps, and the reference's) is at most
// FAST_ADAPTIVE_ROUNDING texels.
constexpr double FAST_ADAPTIVE_ROUNDING = 1.0 / 32;
// relative_chords_bound(X, r) = max(n0, (n0 + 1) X / (n0 - r)), n0 = ceil(X + r): within B
// (n0 = floor(B) >= 1) up to X = B (n0 - r) / (n0 + 1), where X + r <= n0 holds too; 0 below 1.
constexpr double fast_adaptive_room(double budget) {
    const double n0 = double(int64_t(budget));
    return n0 >= 1 ? budget * (n0 - FAST_ADAPTIVE_ROUNDING) / (n0 + 1) * (1 - 1e-6) : 0;
}
// The segments' log2 for a span from Q at its first and last pixel and |Q'| a pixel: the largest s
// in 1..9 with 4^s |Q'| <= 4 Q_lo room; 1 where none is (2 pixels: the bound then says how far).
// (Inline: once a span, where a call and its arguments cost as much again.)
[[gnu::always_inline]] inline int32_t fast_adaptive_shift(double q_first, double q_last, double q_pixel, double room) {
    const double q_lo = q_first < q_last ? q_first : q_last;
    // h = 2^s within where h^2 <= ratio: s = floor(log2(ratio) / 2), from the exponent's bits,
    // clamped to 1..9 (512^2 = 2^18). A ratio not above 0 (its sign bit: Q_lo not above 0) or below
    // 4 takes 1; +inf (Q constant along the span, the gradient 0 or -0) takes 9.
    const double ratio = 4 * room * q_lo / __builtin_fabs(q_pixel);
    uint64_t bits;
    __builtin_memcpy(&bits, &ratio, sizeof bits);
    const uint32_t high = uint32_t(bits >> 32);
    if (int32_t(high) < 0) return 1;
    const int32_t s = (int32_t(high >> 20) - 1023) >> 1;
    return s < 1 ? 1 : s > 9 ? 9 : s;
}
template <int QUARTERS>
void fast_adaptive_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);
template <int QUARTERS>
ErrorBound fast_adaptive_bound(const BoundContext& c, const Vertex* vertices, int count);

// Whether fast-adaptive-B's bound along `axis` is within B on the polygon, from its setup alone
// (every plane), without the spread: true only where the polygon lies inside the clip (the spread's
// corners are then its vertices) with a repeating texture the mapper takes, and where what the
// whole-polygon bound above checks holds for every value the spread could take there (docs/bounds.md,
// "fast-adaptive's certificate": the checks, and what it costs beside the spread). Then
// fast_adaptive_bound<QUARTERS> is within B (tested), so auto may take the mapper unasked. The
// caller's to ensure fast-adaptive-B takes the texture (mapper_accepts, as choose_mapper's candidates).
template <int QUARTERS>
bool fast_adaptive_certain(const PolygonSetup& s, const ClipRect& clip, const Texture& tex, Axis axis);
// The certificate's part that every chord length shares (fast_certificate),
// and from it fast-adaptive-B's (above) and fast-subdiv-N's (fast_chords_bound): at least the
// relative chords bound that segments_bound's whole bound of N-pixel chords along `axis` returns
// where within a budget (fast-constant-depth: N = 512), at the least Q and the most rounding the
// spread could find; NO_BOUND where the certificate does not hold.
struct FastCertificate {
    bool holds = false;        // Q_min above 0, and 16.16 holds the range of t without steps (chords_fit's first test)
    bool terms_within = false; // and Q's terms within 2^26 of its least (fast-adaptive's whole bound asks it)
    double q_min = 0;          // at most the spread's Q_min
    double reference = 0;      // at least the spread's reference rounding, either coordinate
    double last[2] = {0, 0};   // the spread's lines less one, by rows and by columns
};
// From the setup alone, where the polygon lies inside the clip and the texture repeats (the
// caller's to ensure the mapper takes it); or from the polygon's spread (PolygonSpread: one the
// clip cuts, whose spread a bound has computed already), its own values.
FastCertificate fast_certificate(const PolygonSetup& s, const ClipRect& clip, const Texture& tex);
FastCertificate fast_certificate(const PolygonSpread& p);
template <int QUARTERS>
bool fast_adaptive_certain(const FastCertificate& f, const PolygonSetup& s, Axis axis);
double fast_chords_bound(const FastCertificate& f, const PolygonSetup& s, Axis axis, double n);

// fast-oriented-B: fast-adaptive-B, each polygon along the walker where 1/w changes least for
// the lines it costs (walls by columns, floors and ceilings by rows), its own polygon driver: asked
// for rows (a linear target) it takes the walker oriented_axis picks, asked for columns (a planar
// target) columns. Its bound is fast-adaptive-B's along the walker it draws with. oriented_axis
// counts a line as ORIENTED_LINE and a segment as ORIENTED_SEGMENT (fast-adaptive's cost a span and
// a segment, rounded), a line of L pixels along axis a as 1 + L / h_a segments (fast_adaptive_shift's
// h at Q at the reference vertex), and the lines and pixels as the cost model does: the fewer
// instructions, rows on a tie (docs/bounds.md, "Along its own walker").
constexpr double ORIENTED_LINE = 300, ORIENTED_SEGMENT = 60;
Axis oriented_axis(const PolygonSetup& s, const ClipRect& clip, double room);
// The same from the polygon's sizes as polygon_sizes gives them (choice.h), where the caller has them.
struct PolygonSize;
Axis oriented_axis(const PolygonSetup& s, const PolygonSize size[2], double room);
// fast-oriented-B's walker (Mapper::own_walker)
template <int QUARTERS>
Axis fast_oriented_walker(const PolygonSetup& s, const ClipRect& clip);
template <int QUARTERS>
SetupStatus fast_oriented_draw(const DrawContext& c, const Vertex* vertices, int count);
// fast-oriented-1's guard: from its setup with the perspective planes alone, along `axis`, a few
// compares against Q's least over the polygon's box inside the clip (else at its vertices) such
// that fast-adaptive-1's whole bound is within 1 (docs/bounds.md, "fast-oriented-1's guard";
// tested), on a repeating texture, for an object whose corners' |u| and |v| are at most
// `texel_most` where fast_oriented_guard_takes(texel_most, clip) (once an object: the affine
// planes' terms, which the guard does not set up, within what the certificate allows; a polygon
// the clip cuts is checked on its own). Returns that least (at most the certificate's or the
// spread's Q_min), 0 where the guard fails.
bool fast_oriented_guard_takes(double texel_most, const ClipRect& clip);
double fast_oriented_guard(const PolygonSetup& s, const ClipRect& clip, Axis axis, double texel_most);
// Where the guard holds with `q_min`: whether the certificate bounds fast-constant-depth's chords
// along `axis` within the budget whose fast_adaptive_room is `room` (fast_chords_bound for 512 pixels).
bool fast_constant_within(const PolygonSetup& s, const ClipRect& clip, Axis axis, double q_min, double room);
template <int QUARTERS>
ErrorBound fast_oriented_bound(const BoundContext& c, const Vertex* vertices, int count);

Check check_fast_subdiv;

}  // namespace raster

extern "C" {
raster::Loop fast_subdiv_loop_asm;
}
