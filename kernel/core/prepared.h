// Auto's prepared polygon: set up once, with its spread and its spans kept for the several
// mappers' bounds asked of it in turn.
#pragma once

#include <stdint.h>

#include "kernel/core/setup.h"
#include "kernel/core/spread.h"
#include "kernel/core/walk.h"

namespace raster {

// A polygon set up (every plane) once, for asking several mappers' bounds in turn (auto): the
// bounds take its spread, and its spans along either walker (walked when a bound first needs them)
// rather than setting up and walking again, from `first` on (the span that settled the last bound
// above its budget: the likeliest to settle the next one).
struct PreparedSpans {
    static constexpr int32_t MAX_SPANS = 512;  // a screen's rows or columns, and more
    static constexpr int32_t NOT_WALKED = -2;
    // spans; NOT_WALKED: not yet; -1: more than MAX_SPANS, the bounds walk the polygon themselves
    int32_t count = NOT_WALKED;
    int32_t pixels = 0;
    int32_t first = 0;
    Span spans[MAX_SPANS];
};
struct PreparedPolygon {
    SetupStatus status = SetupStatus::Degenerate;
    PolygonSetup setup;
    bool spread_known = false;
    PolygonSpread spread;
    PreparedSpans walked[2];  // [Axis]
};
// Sets the polygon up, not walked (`input`: as setup_polygon takes it).
void prepare_setup(const Vertex* vertices, int count, PreparedPolygon* out, Input input = Input::Any);
// Walks it along the axis.
void walk_polygon(PreparedPolygon* p, Axis axis, const ClipRect& clip);
// Both.
void prepare_polygon(const Vertex* vertices, int count, Axis axis, const ClipRect& clip, PreparedPolygon* out);
// Its spread inside the clip, computed once (the clip is the same for every bound asked of it).
PolygonSpread& prepared_spread(PreparedPolygon* p, const ClipRect& clip);

}  // namespace raster
