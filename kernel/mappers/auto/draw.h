// auto's drivers (docs/auto.md): a polygon drawn with the mapper choose_mapper picks for the
// budget, and a frame drawn with what auto settles per object (AutoPlan, AutoObject) before its
// polygons. Its registry row's Mapper::chooses and Mapper::draw_frame.
#pragma once

#include "kernel/core/render.h"
#include "kernel/scene/frame.h"

namespace raster {

// auto's choice for the polygon, and the drawing with it, counted under the chosen mapper's row
// (its setup counts as setup, the rest of the choice as Phase::Choose); where no mapper draws the
// polygon, the fallback's setup says why. DrawContext::budget (nullptr: DEFAULT_BUDGET).
SetupStatus auto_draw(const DrawContext& c, const Vertex* vertices, int count);
RenderStats auto_draw_frame(const Frame& frame, const TextureSet& textures, const Mapper& mapper, Axis axis, Target& target,
                            Variant variant, Probe* probe, const Watch* watch);

// auto on an uncut triangle of an object whose envelope proves the mapper of `enveloped` (plan_auto,
// choice.h; the drawer made once an object, checked): the mapper's Mapper::enveloped driver sets
// it up and checks it (DrawContext::envelope: the envelope's guards, its doubled area and its extent
// across its lines within the drawer's limits; fast-affine's rows in the same NASM call as its
// setup and walk, fast_triangle_enveloped_asm) and draws it; where it is not within them, nothing
// drawn, auto's choice as in auto_draw, with the drawer's texture, axis and target
// (draw_unproven). Inline: once a triangle of the mesh, in the frame's loop.
SetupStatus draw_unproven(const Drawer& enveloped, const Vertex* vertices, Variant variant, const Budget& budget);
inline SetupStatus draw_enveloped(const Drawer& enveloped, const Vertex* vertices, Variant variant, const Budget& budget) {
    // (an uncut triangle: in range, as build_frame makes it)
    const SetupStatus status = enveloped.drive(enveloped.mapper->enveloped, vertices, 3, Input::InRange, &enveloped.limits);
    if (status == SetupStatus::Unproven) return draw_unproven(enveloped, vertices, variant, budget);
    enveloped.stats->enveloped += status == SetupStatus::Ok;
    return status;
}

}  // namespace raster
