// Drawing polygons: setup, the walker for the axis, the mapper per span, into a target.
#pragma once

#include <stdint.h>

#include "kernel/core/budget.h"
#include "kernel/core/envelope.h"
#include "kernel/core/mapper.h"
#include "kernel/core/prepared.h"
#include "kernel/scene/scene.h"
#include "kernel/core/setup.h"
#include "kernel/core/surface.h"

namespace raster {

// Draws one convex polygon. Returns the setup status; nothing is drawn (and the polygon counts as
// rejected) unless it is Ok, the mapper walks `axis`, accepts the texture and can draw into the
// target (mapper_targets). A mapper that chooses (Mapper::chooses: auto) draws it with the mapper it
// picks for the budget.
// `input`: InRange where the caller answers for the vertices' range (setup.h).
SetupStatus draw_polygon(const Vertex* vertices, int count, const Texture& tex, const Mapper& mapper, Axis axis,
                         Target& target, RenderStats* stats, Variant variant = Variant::Twin, const Budget& budget = DEFAULT_BUDGET,
                         Input input = Input::Any);
// A mapper set to draw with one texture along one axis into one target: what draw_polygon settles
// before each polygon (whether the mapper takes them at all, and its loop), settled once, for a
// mapper that does not choose (a frame's drivers keep them an object: the frame's mapper, or auto's
// envelope-proven and certain ones). No default member initialisers: a frame driver keeps several
// an object a frame, and only those Drawer::of makes, which sets every field, are read.
struct Drawer {
    const Mapper* mapper;
    const Texture* tex;
    Target* target;
    RenderStats* stats;
    LoopFn loop;
    int32_t row;   // the mapper's registry row (RenderStats::mapper_polygons)
    Axis axis;
    bool usable;   // it walks the axis, takes the texture and draws into the target
    // auto's envelope (draw_enveloped): the largest doubled area it draws a triangle of and the
    // largest extents of its box, across its lines (the other unlimited: an uncut triangle's box,
    // within ENVELOPE_REACH pixels, fits in 32 bits); else INT64_MAX and INT32_MAX
    EnvelopeLimits limits;
    // `checked`: known usable (plan_auto checked it)
    static Drawer of(const Mapper& mapper, const Texture& tex, Axis axis, Target& target, RenderStats* stats, Variant variant,
                     bool checked = false);
    bool own;      // usable, and the mapper has its own driver (draw_own)
    // draw_polygon with this mapper, texture, axis and target
    SetupStatus draw(const Vertex* vertices, int count, Input input = Input::Any) const;
    // The same with the polygon set up already with every plane (nullptr: not), and its spans along
    // the drawer's axis where walked (PreparedSpans::count below 0: not): a chooser's choice.
    SetupStatus draw_set_up(const Vertex* vertices, int count, const PolygonSetup* setup, const PreparedSpans* walked) const;
    // The same where `own`, inline: straight to the mapper's driver (a frame's loop).
    SetupStatus draw_own(const Vertex* vertices, int count, Input input) const;
    // draw_own's work with `driver` (the mapper's draw, or its enveloped one given auto's
    // `envelope`): the probe's laps about it, and the polygon counted unless Unproven.
    SetupStatus drive(DrawFn driver, const Vertex* vertices, int count, Input input, const EnvelopeLimits* envelope) const;
};

// Counts a polygon drawn (or not) with `row`'s mapper: its pixels those the statistics gained from
// `pixels_before`. Every drawing of a polygon ends here.
inline void count_polygon(RenderStats* stats, int32_t row, SetupStatus status, uint32_t pixels_before) {
    if (status == SetupStatus::Ok) {
        ++stats->polygons;
        ++stats->mapper_polygons[row];
        stats->mapper_pixels[row] += stats->pixels - pixels_before;
    } else if (status == SetupStatus::Degenerate) ++stats->skipped;
    else if (status != SetupStatus::Unproven) ++stats->rejected;  // (Unproven: auto chooses, and counts that)
}

inline SetupStatus Drawer::drive(DrawFn driver, const Vertex* vertices, int count, Input input, const EnvelopeLimits* envelope) const {
    Probe* probe = stats->probe;
    probe_lap(probe, Phase::Walk);  // what came before the polygon: the caller's loop
    const uint32_t pixels_before = stats->pixels;
    const SetupStatus status = driver(DrawContext{*tex, axis, *target, stats, loop, nullptr, input, envelope}, vertices, count);
    probe_lap(probe, Phase::Walk);
    count_polygon(stats, row, status, pixels_before);
    return status;
}
inline SetupStatus Drawer::draw_own(const Vertex* vertices, int count, Input input) const {
    return drive(mapper->draw, vertices, count, input, nullptr);
}

// The polygon being drawn, for a fault's report (the kernel's page-fault handler names them): the
// mapper asked for and the polygon's index in the scene, frame or run; mapper null between drawings.
struct DrawingNow {
    const char* mapper = nullptr;
    uint32_t polygon = 0;
};

// A long drawing watched (the kernel: progress events, and a line on COM1 stops it): before every
// WATCH_EVERY-th polygon, keep_going(ctx, polygons handled, polygons in all); false stops the
// drawing there, and RenderStats::interrupted says so.
// With `now`, the drawing loops also say there which polygon they draw (the caller's memory).
struct Watch {
    static constexpr uint32_t WATCH_EVERY = 16;
    bool (*keep_going)(void* ctx, uint32_t done, uint32_t total) = nullptr;
    void* ctx = nullptr;
    DrawingNow* now = nullptr;
    void drawing(const Mapper& mapper, uint32_t polygon) const {
        if (now) *now = DrawingNow{mapper.name, polygon};
    }
    void drawn() const {
        if (now) *now = DrawingNow{};
    }
    bool stops(uint32_t done, uint32_t total, RenderStats* stats) const {
        if (done == 0 || done % WATCH_EVERY || !keep_going || keep_going(ctx, done, total)) return false;
        stats->interrupted = true;
        return true;
    }
};

// Draws every polygon of the scene in order; with a probe, times the phases (probe.h). Screen-space
// scenes have no budget line: auto takes the default (`budget`: with the caller's lists, Budget::lists).
RenderStats render_scene(const Scene& scene, const Texture& tex, const Mapper& mapper, Axis axis, Target& target,
                         Variant variant = Variant::Twin, Probe* probe = nullptr, const Watch* watch = nullptr,
                         const Budget& budget = DEFAULT_BUDGET);

}  // namespace raster
