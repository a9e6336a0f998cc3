// What a texture mapper is: its registry row (needs, promises, loops), the contexts its span or
// polygon driver gets, and the one path by which a driver hands pixels to its inner loop.
#pragma once

#include <stdint.h>

#include "kernel/core/probe.h"
#include "kernel/core/setup.h"
#include "kernel/core/surface.h"
#include "kernel/core/texture.h"
#include "kernel/core/walk.h"
#include "kernel/lib/fmt.h"
#include "kernel/lib/words.h"

namespace raster {

// An inner loop: one pointer to its argument block. The C++ twin is the specification; the NASM
// loop (asm/NAME.asm) must match it bit for bit. Naming rule: the twin is NAME_loop (or
// NAME_KIND_loop) in namespace raster, its NASM loop the same name with _asm, extern "C".
// An inner loop's type: a mapper's header declares its twin and NASM loop as `Loop NAME_loop;` and
// `extern "C" Loop NAME_loop_asm;`.
using Loop = void(const void* args);
using LoopFn = Loop*;

#if defined(MODEXLAB_ASM_LOOPS)
#define MODEXLAB_ASM(symbol) (&symbol)
#else
#define MODEXLAB_ASM(symbol) nullptr
#endif
// A registry row's twin and NASM loop (designated), named by the rule above.
#define TWIN_AND_ASM(loop) .twin = loop, .asm_loop = MODEXLAB_ASM(loop##_asm)

// What a mapper needs from the texture and the target; the caller must not give it anything else.
enum Need : uint32_t {
    NEED_NOTHING = 0,
    NEED_BORDERED = 1 << 0,       // the texture's bordered copy (Texture::bordered)
    NEED_INSIDE = 1 << 1,         // cannot wrap: a polygon's texture coordinates must fit in the texture
    NEED_PLANAR_TARGET = 1 << 2,  // writes Mode X planes itself (rows on a planar target)
    NEED_VGA_FOR_ASM = 1 << 3,    // the NASM loop programs the VGA: it runs on VGA pages only
    NEED_ALIGNED256 = 1 << 4,     // 256 x 256, repeat, with the 64 KiB-aligned copy (Texture::aligned256)
    // sides powers of two up to 1024, repeat, with the tiled 64 KiB-aligned copy (sides up to 256)
    // or the doubled one (Texture::doubled: a side above 256)
    NEED_POW2_REPEAT = 1 << 5,
    // sides powers of two up to 256 with the tiled copy, repeating, or clamped where the polygon's
    // texture coordinates lie inside the texture (the mapper refuses the others: texture_inside)
    NEED_TILED256_OR_INSIDE = 1 << 6,
    // the same with sides powers of two up to 1024, those above 256 read from the doubled copy
    // (Texture::doubled)
    NEED_POW2_OR_INSIDE = 1 << 7,
    NEED_DOUBLED = 1 << 8,  // the texture's doubled copy (Texture::doubled: fast-table's offsets)
};
// Each need's name (the `mappers` reply) and its words (error messages), in one table.
struct NeedName {
    Need need;
    const char* name;
    const char* words;
};
extern const NeedName NEED_NAMES[];
extern const int NEED_NAME_COUNT;
// The needs a scene can fail to meet (its textures, its coordinates); the texture copies are always
// prepared (policy.h) and the target is the caller's choice.
constexpr uint32_t SCENE_NEEDS = NEED_INSIDE | NEED_ALIGNED256 | NEED_POW2_REPEAT | NEED_TILED256_OR_INSIDE | NEED_POW2_OR_INSIDE;
// The words of the needs in `needs`, comma-separated.
void describe_needs(lib::Fmt& out, uint32_t needs);

// Which walkers a mapper works with.
enum AxisSet : uint8_t { AXIS_ROWS = 1, AXIS_COLUMNS = 2, AXIS_BOTH = 3 };

// Which implementation of the inner loop to run: the C++ twin, or the NASM loop where one exists
// (builds without NASM, and mappers without a NASM loop, run the twin).
enum class Variant : uint8_t { Twin, Asm };

struct SpanContext {
    const PolygonSetup& setup;
    const Texture& tex;
    Axis axis;
    LoopFn loop;
};

// Draws span s starting at dst, `stride` bytes between pixels, with the context's loop.
using SpanFn = void (*)(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride);

// At most this many registry rows (registry.cpp checks): arrays indexed by row.
constexpr int MAPPER_LIMIT = 33;

struct RenderStats {
    uint32_t polygons = 0;   // set up and walked
    uint32_t skipped = 0;    // degenerate (zero area): nothing to draw
    uint32_t rejected = 0;   // not convex, too many vertices, out of range, or not for this mapper
    uint32_t spans = 0;
    uint32_t pixels = 0;
    Probe* probe = nullptr;  // the bench's lap timer, when it times the phases
    bool interrupted = false;  // a Watch stopped the drawing before its last polygon (render.h)
    // by registry row: the polygons each mapper drew and their pixels (auto draws with several)
    uint32_t mapper_polygons[MAPPER_LIMIT] = {};
    uint32_t mapper_pixels[MAPPER_LIMIT] = {};
    // auto, by the level of the proof of each polygon it drew (counted above too): by its object's
    // envelope, by the whole polygon's bound or certificate, span by span; the rest it drew unasked
    // (the reference's definition, where choosing cannot pay: docs/auto.md)
    uint32_t enveloped = 0, proven_whole = 0, proven_spans = 0;
};

// A mapper with its own setup and edge walking (the classics, our fast loops) draws whole polygons.
struct EnvelopeLimits;  // (envelope.h)
struct Budget;          // (budget.h)
struct Mapper;
struct DrawContext {
    const Texture& tex;
    Axis axis;
    Target& target;
    RenderStats* stats;  // the driver adds spans and pixels through emit() and tally()
    LoopFn loop;
    // the polygon set up already (auto: every plane), or nullptr; given, `axis` is the walker auto
    // picked (a driver that picks its own, fast-oriented's, takes it: auto picks it the same way)
    const PolygonSetup* setup = nullptr;
    Input input = Input::Any;             // for the driver's own setup_polygon
    // auto's envelope (draw_enveloped, mappers/auto/draw.h), for a mapper's Mapper::enveloped driver: right
    // after its setup it checks within_envelope (envelope.h) and returns Unproven, nothing drawn,
    // where the triangle fails it
    const EnvelopeLimits* envelope = nullptr;
    // for a driver that chooses a mapper (Mapper::chooses): the budget to meet, and the variant of
    // the loops it draws with (nullptr: DEFAULT_BUDGET)
    const Budget* budget = nullptr;
    Variant variant = Variant::Twin;
};
using DrawFn = SetupStatus (*)(const DrawContext& c, const Vertex* vertices, int count);
// A frame drawn by a mapper's own frame driver (Mapper::draw_frame; render_frame, kernel/scene/frame.h).
struct Frame;
struct TextureSet;
struct Watch;
using FrameFn = RenderStats (*)(const Frame& frame, const TextureSet& textures, const Mapper& mapper, Axis axis, Target& target,
                                Variant variant, Probe* probe, const Watch* watch);

// A polygon driver marks the end of its setup (for the bench's probe, probe.h).
inline void setup_done(const DrawContext& c) { probe_lap(c.stats->probe, Phase::Setup); }

// Counts what a loop drew: every driver's statistics go through here.
inline void tally(RenderStats* stats, uint32_t spans, uint32_t pixels) {
    stats->spans += spans;
    stats->pixels += pixels;
}

// The one path from a driver to its inner loop: the probe's laps around `draw` (its time counts as
// the inner loop's; what came before it, as walking), then the tally. `draw` is the loop call, or
// a whole span routine where the original's span code is the inner loop (X-Sharp's, Hecker's).
// (The probe comes apart from the statistics so that a caller can keep it in a register.)
template <typename Draw>
inline void emit(Probe* probe, RenderStats* stats, uint32_t spans, uint32_t pixels, Draw&& draw) {
    probe_lap(probe, Phase::Walk);
    draw();
    probe_lap(probe, Phase::Inner);
    tally(stats, spans, pixels);
}
// The common case: the context's loop on one argument block. (Written out rather than through the
// lambda form, which changes the drivers' register allocation, and so their cost.)
inline void emit(const DrawContext& c, const void* args, uint32_t spans, uint32_t pixels) {
    probe_lap(c.stats->probe, Phase::Walk);
    c.loop(args);
    probe_lap(c.stats->probe, Phase::Inner);
    tally(c.stats, spans, pixels);
}

// What a mapper promises about accuracy, in checkable form (tests/unit/kernel/mappers/promise_test.cpp checks it
// on every screen-space scene; the prose is in `promise`).
struct Guarantee {
    bool exact_coverage;     // draws exactly the pixels the reference covers: no gaps, no overdraw
    int8_t max_error;        // max texel error against the reference on any scene; -1: none promised
    int8_t max_error_flat;   // the same where every vertex has the same w (no perspective); -1: none
};
constexpr Guarantee EQUALS_REFERENCE{true, 0, 0};
constexpr Guarantee EXACT_COVERAGE_FLAT_ONE{true, -1, 1};  // exact coverage; within a texel without perspective
constexpr Guarantee EXACT_COVERAGE{true, -1, -1};
constexpr Guarantee NO_GUARANTEE{false, -1, -1};           // the classics: what they are

struct LoopCheck;
struct CheckBuffers;
struct ErrorBound;
struct BoundContext;
// What the mapper promises for a polygon before drawing it (core/bound.h).
using BoundFn = ErrorBound (*)(const BoundContext& c, const Vertex* vertices, int count);
// The differential check of a mapper's NASM loop against its twin (core/selftest.h).
using Check = LoopCheck(const Mapper& m, LoopFn other, uint32_t seed, uint32_t cases, const CheckBuffers& buffers);
using CheckFn = Check*;

// Whether auto, where a mapper's bound of the whole polygon at once is above the budget, asks its
// bound span by span (BOUND_SPAN_COST a span, mappers/auto/choice.h): only where the spans' bounds
// can be much tighter than the whole polygon's, as they are where the error depends on each line's
// own direction or place (docs/auto.md).
enum SpanProof : uint8_t { SPANS_NOT_ASKED, SPANS_ASKED };

// What auto takes a registry row for beyond its bound and its cost (mappers/auto/choice.h): the oriented
// candidate (its own driver picks the walker), the adaptive ones it is weighed against along each
// walker, the constant-depth one whose one chord a line the oriented certificate proves too, and
// the fallback that draws what no candidate may (the reference's definition).
enum class AutoRole : uint8_t { None, Adaptive1, Adaptive2, Oriented, ConstantDepth, Fallback };

struct Mapper {
    const char* name;
    const char* family;   // "ours" or "classic"
    const char* origin;   // where it comes from
    const char* promise;  // what it promises about accuracy
    Guarantee guarantee;  // the same, checkable
    uint32_t needs;       // Need flags
    uint8_t axes;         // AxisSet
    SpanFn span = nullptr;      // for the generic walker (nullptr when draw is set)
    LoopFn twin = nullptr;      // the C++ inner loop (nullptr: span does all the work itself)
    LoopFn asm_loop = nullptr;  // its NASM twin, or nullptr
    DrawFn draw = nullptr;    // its own polygon driver, or nullptr for the generic walker
    CheckFn check = nullptr;  // random cases for its loop: NASM against twin (nullptr: no NASM loop,
                              // or one the kernel checks on the VGA itself, NEED_VGA_FOR_ASM)
    BoundFn bound = nullptr;  // its error bound on a polygon (unbounded: none derived)
    bool is_auto = false;     // auto: draws each polygon with a mapper it chooses (mappers/auto/choice.h)
    // A driver that draws the polygon with a mapper it chooses for DrawContext::budget, counting it
    // under that mapper's row (auto); and a driver of a whole frame, which settles what it can once
    // an object (auto: its plans and envelopes). nullptr: the polygon's and frame's usual drawing.
    DrawFn chooses = nullptr;
    FrameFn draw_frame = nullptr;
    SpanProof span_proof = SPANS_NOT_ASKED;  // whether auto asks its bound span by span (mappers/auto/choice.h)
    // Its bound is the 16.16 planes' (spread_planes_bound, planes_fit_16_16): an object's envelope
    // proves it on the object's uncut triangles (plan_auto, mappers/auto/choice.h), which auto draws with
    // this driver (draw's, given DrawContext::envelope: draw_enveloped, mappers/auto/draw.h); nullptr: no
    // envelope proves it. (A driver of its own, so that the mapper's own path checks nothing.)
    DrawFn enveloped = nullptr;
    // The planes its span routine reads, all draw_with sets up for it (the perspective ones, but
    // for affine's): setting up a plane the routine does not read would cost every polygon.
    SetupPlanes span_planes = PLANES_PERSPECTIVE;
    // Where the target takes rows, the walker it draws a polygon along, which it picks itself
    // polygon by polygon (fast-oriented), from the polygon's setup (any planes) and the clip: asked
    // for rows it draws along this one (its bound too); asked for columns, columns. nullptr: the
    // walker it is asked for. auto does not take such a mapper as a candidate (choosable).
    Axis (*own_walker)(const PolygonSetup& s, const ClipRect& clip) = nullptr;
    AutoRole auto_role = AutoRole::None;
};

extern const Mapper MAPPERS[];
extern const int MAPPER_COUNT;
const Mapper* find_mapper(lib::StrView name);
inline const Mapper* find_mapper(const char* name) { return find_mapper(lib::StrView{name, lib::c_length(name)}); }

// Whether the texture is tiled over the 64 KiB block, and meets NEED_ALIGNED256 (its one tile 256 x 256).
inline bool texture_tiled256(const Texture& t) { return tiles256(t.width, t.height) && t.wrap == Wrap::Repeat && t.aligned256; }
inline bool texture_aligned256(const Texture& t) { return texture_tiled256(t) && t.width == 256 && t.height == 256; }
// Whether the texture meets NEED_TILED256_OR_INSIDE (a clamped one: its polygons checked one by one).
inline bool texture_tiled256_any_wrap(const Texture& t) { return tiles256(t.width, t.height) && t.aligned256; }
// Whether the texture meets NEED_POW2_OR_INSIDE (its table block built).
inline bool texture_pow2_any_wrap(const Texture& t) { return texture_tiled256_any_wrap(t) || (beyond_tile(t.width, t.height) && t.doubled); }

inline bool mapper_accepts(const Mapper& m, const Texture& t) {
    if ((m.needs & NEED_BORDERED) && !t.bordered) return false;
    if ((m.needs & NEED_DOUBLED) && !t.doubled) return false;
    if ((m.needs & NEED_ALIGNED256) && !texture_aligned256(t)) return false;
    if ((m.needs & NEED_POW2_REPEAT) && !(t.wrap == Wrap::Repeat && texture_pow2_any_wrap(t))) return false;
    if ((m.needs & NEED_TILED256_OR_INSIDE) && !texture_tiled256_any_wrap(t)) return false;
    if ((m.needs & NEED_POW2_OR_INSIDE) && !texture_pow2_any_wrap(t)) return false;
    return true;
}

inline bool mapper_walks(const Mapper& m, Axis axis) { return m.axes & (axis == Axis::Rows ? AXIS_ROWS : AXIS_COLUMNS); }

// Whether the mapper can draw into this target along this axis.
inline bool mapper_targets(const Mapper& m, const Target& t, Axis axis) {
    if (m.needs & NEED_PLANAR_TARGET) return t.planar;
    return target_supports(t, axis);
}

inline LoopFn mapper_loop(const Mapper& m, Variant v, const Target& t) {
    bool asm_ok = m.asm_loop && (!(m.needs & NEED_VGA_FOR_ASM) || t.vga);
    return v == Variant::Asm && asm_ok ? m.asm_loop : m.twin;
}

}  // namespace raster
