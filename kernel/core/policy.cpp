// Surfaces by name and kind, RAM targets, and texture preparation.
#include "kernel/core/policy.h"

namespace raster {

namespace {

constexpr const char* SURFACE_NAMES[SURFACE_COUNT] = {"linear", "planar", "vga"};  // in Surface's order

}  // namespace

bool surface_from_name(lib::StrView name, Surface* out) {
    int i = lib::find_name(name, SURFACE_NAMES, SURFACE_COUNT);
    if (i >= 0) *out = Surface(i);
    return i >= 0;
}

const char* surface_name(Surface s) { return SURFACE_NAMES[int(s)]; }

Target surface_kind(Surface s) {
    Target t;
    t.planar = s != Surface::Linear;
    t.vga = s == Surface::Vga;
    return t;
}

bool draws_through(const Mapper& m, Surface s) {
    Axis axis = surface_axis(m, s);
    return mapper_walks(m, axis) && mapper_targets(m, surface_kind(s), axis);
}

Target ram_target(uint8_t* pixels, bool planar) {
    return planar ? planar_target(pixels) : linear_target(pixels, SCREEN_WIDTH, SCREEN_HEIGHT, SCREEN_WIDTH);
}

void prepare_texture(Texture* t, uint8_t* bordered, uint8_t* aligned, uint8_t* doubled) {
    make_bordered(*t, bordered);
    t->bordered = bordered;
    t->aligned256 = wants_aligned256(*t) ? make_aligned256(*t, aligned) : nullptr;
    t->doubled = doubled && wants_doubled(*t) ? make_doubled(*t, doubled) : nullptr;
}

}  // namespace raster
