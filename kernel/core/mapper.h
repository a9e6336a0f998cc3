// The texture-mapper registry: every mapper in one table with what it needs and what it promises,
// so the tests, the bench and the selection policy iterate one list. A mapper here draws the spans
// (rows or columns) the edge walker yields; its inner loop may have a NASM twin (loops.h).
#pragma once

#include <stdint.h>

#include "kernel/lib/words.h"
#include "kernel/mappers/loops.h"
#include "kernel/core/probe.h"
#include "kernel/core/setup.h"
#include "kernel/core/surface.h"
#include "kernel/core/texture.h"
#include "kernel/core/walk.h"

namespace raster {

// What a mapper needs from the texture; the caller must not give it anything else.
enum Need : uint32_t {
    NEED_NOTHING = 0,
    NEED_POW2 = 1 << 0,           // width and height powers of two
    NEED_WIDTH_256 = 1 << 1,      // width exactly 256
    NEED_BORDERED = 1 << 2,       // the texture's bordered copy (Texture::bordered)
    NEED_INSIDE = 1 << 3,         // cannot wrap: a polygon's texture coordinates must fit in the texture
    NEED_PLANAR_TARGET = 1 << 4,  // writes Mode X planes itself (rows on a planar target)
    NEED_VGA_FOR_ASM = 1 << 5,    // the NASM loop programs the VGA: it runs on VGA pages only
    NEED_ALIGNED256 = 1 << 6,     // 256 x 256, repeat, with the 64 KiB-aligned copy (Texture::aligned256)
};

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

struct RenderStats {
    uint32_t polygons = 0;   // set up and walked
    uint32_t skipped = 0;    // degenerate (zero area): nothing to draw
    uint32_t rejected = 0;   // not convex, too many vertices, out of range, or not for this mapper
    uint32_t spans = 0;
    uint32_t pixels = 0;
    Probe* probe = nullptr;  // the bench's lap timer, when it times the phases
};

// A mapper with its own setup and edge walking (the classics) draws whole polygons.
struct DrawContext {
    const Texture& tex;
    Axis axis;
    Target& target;
    RenderStats* stats;  // the driver adds spans and pixels
    LoopFn loop;
};
using DrawFn = SetupStatus (*)(const DrawContext& c, const Vertex* vertices, int count);

// For the bench's probe (probe.h): a polygon driver marks the end of its setup, and runs its
// per-span (per-column) code through these, so that its time counts as the inner loop's.
inline void setup_done(const DrawContext& c) { probe_lap(c.stats->probe, Phase::Setup); }
inline void inner_begins(const DrawContext& c) { probe_lap(c.stats->probe, Phase::Walk); }
inline void inner_ends(const DrawContext& c) { probe_lap(c.stats->probe, Phase::Inner); }
inline void run_loop(const DrawContext& c, const void* args) {
    inner_begins(c);
    c.loop(args);
    inner_ends(c);
}

// What a mapper promises about accuracy, in checkable form (tests/unit/promise_test.cpp checks it
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

struct Mapper {
    const char* name;
    const char* family;   // "ours" or "classic"
    const char* origin;   // where it comes from
    const char* promise;  // what it promises about accuracy
    Guarantee guarantee;  // the same, checkable
    uint32_t needs;       // Need flags
    uint8_t axes;         // AxisSet
    SpanFn span;          // for the generic walker (nullptr when draw is set)
    LoopFn twin;          // the C++ inner loop (nullptr: span does all the work itself)
    LoopFn asm_loop;      // its NASM twin, or nullptr
    DrawFn draw = nullptr;  // its own polygon driver, or nullptr for the generic walker
};

extern const Mapper MAPPERS[];
extern const int MAPPER_COUNT;
const Mapper* find_mapper(lib::StrView name);
inline const Mapper* find_mapper(const char* name) { return find_mapper(lib::StrView{name, lib::c_length(name)}); }

inline bool mapper_accepts(const Mapper& m, const Texture& t) {
    bool pow2 = (t.width & (t.width - 1)) == 0 && (t.height & (t.height - 1)) == 0;
    if ((m.needs & NEED_POW2) && !pow2) return false;
    if ((m.needs & NEED_WIDTH_256) && t.width != 256) return false;
    if ((m.needs & NEED_BORDERED) && !t.bordered) return false;
    if ((m.needs & NEED_ALIGNED256) && (t.width != 256 || t.height != 256 || t.wrap != Wrap::Repeat || !t.aligned256)) return false;
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
