// Where a mapper draws and what it reads: the surface and walker it takes, and the copies of a
// texture the mappers need. The one place these are decided, for the kernel, the host tools and
// the tests alike.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/core/mapper.h"

namespace raster {

// Where a drawing goes on its way to a Mode X page.
enum class Surface : uint8_t {
    Linear,  // rows into a linear RAM surface, then a blit
    Planar,  // columns into a planar RAM surface (the page's four planes), then a blit
    Vga,     // columns straight into the page
};
constexpr int SURFACE_COUNT = 3;
bool surface_from_name(lib::StrView name, Surface* out);
const char* surface_name(Surface s);

// The surface a mapper is drawn and measured through when none is named: straight into the page
// for the mappers that write Mode X planes themselves, else rows into the linear surface.
inline Surface home_surface(const Mapper& m) { return (m.needs & NEED_PLANAR_TARGET) ? Surface::Vga : Surface::Linear; }

// The walker a mapper uses through a surface: its only one, or for those that walk both, rows into
// the linear surface and columns into the planar ones.
inline Axis surface_axis(const Mapper& m, Surface s) {
    if (m.axes == AXIS_ROWS) return Axis::Rows;
    if (m.axes == AXIS_COLUMNS) return Axis::Columns;
    return s == Surface::Linear ? Axis::Rows : Axis::Columns;
}
// The walker through the home surface: the mapper's own, rows for those that walk both.
inline Axis home_axis(const Mapper& m) { return surface_axis(m, home_surface(m)); }

// A target of the kind `s` is (no pixels): for asking what a mapper can draw into.
Target surface_kind(Surface s);
// Whether the mapper can draw through the surface (its walker there, and the target).
bool draws_through(const Mapper& m, Surface s);

// The RAM layout that stands for the target a mapper draws into where there is no VGA (the host):
// planar for the mappers that write Mode X planes themselves and for columns, else linear.
inline bool ram_planar(const Mapper& m, Axis axis) { return (m.needs & NEED_PLANAR_TARGET) || axis == Axis::Columns; }
// A 320x240 RAM target over SCREEN_PIXELS bytes, linear or the four planes one after the other.
Target ram_target(uint8_t* pixels, bool planar);

// The copies of a texture the mappers read besides its texels: the bordered copy (every texture:
// the classics, which cannot wrap, read it), for textures with power-of-two sides up to 256 the
// tiled copy aligned to 64 KiB (fatmap's loops, 256 x 256 only, and ours), and for those with
// power-of-two sides up to 1024 the doubled copy (fast-table's; and fast-affine's and the other
// fast loops' where a side is above 256). prepare_texture builds them into the buffers given
// (bordered_bytes(width, height), ALIGNED256_BYTES and doubled_bytes(width, height); `doubled`
// null: none built, fast-table refuses the texture, and our other fast loops one above 256) and
// points the texture at them.
inline bool wants_aligned256(const Texture& t) { return tiles256(t.width, t.height); }
inline bool wants_doubled(const Texture& t) { return gets_doubled(t.width, t.height); }
void prepare_texture(Texture* t, uint8_t* bordered, uint8_t* aligned, uint8_t* doubled = nullptr);

}  // namespace raster
