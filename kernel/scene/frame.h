// A frame of a 3D scene: objects and camera at the frame's time, culled, clipped in homogeneous
// space, projected and ordered far to near, then drawn (docs/scene-format.md, "From 3D to the screen").
#pragma once

#include <stdint.h>

#include "kernel/core/envelope.h"
#include "kernel/core/policy.h"
#include "kernel/core/render.h"
#include "kernel/scene/world.h"

namespace raster {

constexpr int32_t MAX_FRAME_POLYGONS = 32768;
constexpr int32_t MAX_FRAME_VERTICES = 131072;
constexpr int32_t MAX_FRAME_POSITIONS = 65536;  // object positions transformed in one frame
// Clip space keeps |x|, |y| <= GUARD_BAND * w: on screen within 160 +- 5120 and 120 +- 3840
// pixels, inside the setup's limits and the classics' +-8192.
constexpr double GUARD_BAND = 32;
constexpr double SCREEN_ASPECT = 4.0 / 3.0;  // 320 x 240, square pixels
// (what Frame::polygon_whole's range rests on)
static_assert(MAX_TEXCOORD * MAX_TEXTURE_SIZE <= MAX_UV && 160 * GUARD_BAND + 160 < MAX_COORD_PIXELS && 120 * GUARD_BAND + 120 < MAX_COORD_PIXELS);

struct FrameStats {
    uint32_t faces = 0;         // faces of all objects
    uint32_t culled = 0;        // facing away (objects with cull back)
    uint32_t outside = 0;       // entirely outside the view volume, or clipped to nothing
    uint32_t clipped = 0;       // cut by a plane and kept
    uint32_t polygons = 0;      // out: on their way to the mappers
    uint32_t overflow = 0;      // dropped for lack of room (beyond the limits above)
};

// The room of a frame and of its scratch: polygons (each face of each object gives at most one)
// and their corners (a face's corners and six more, one for each clip plane), and the positions of
// all objects. The kernel sizes it to the world at hand (frame_room); the host's frames have the
// limits above (HostFrame, HostFrameScratch).
struct FrameRoom {
    int32_t polygons = 0, vertices = 0, positions = 0;
    static FrameRoom limits() { return FrameRoom{MAX_FRAME_POLYGONS, MAX_FRAME_VERTICES, MAX_FRAME_POSITIONS}; }
};
FrameRoom frame_room(const World& world);

struct Frame {
    int32_t number = 0;
    int32_t polygon_count = 0, vertex_count = 0;
    int32_t object_count = 0;
    FrameStats stats;
    Budget budget;  // the world's: what auto draws to
    // per object: what its envelope proves on its uncut triangles (object_envelope), which auto
    // takes as their proof (footprint NO_BOUND: none)
    EnvelopeBound envelope[MAX_WORLD_OBJECTS];
    // per object: the largest |u| and |v| (texels) at any corner of its polygons, from above (its
    // mesh's texture coordinates times its texture's sides; a corner cut from two others lies
    // between them): what auto's oriented path asks of an object (fast_oriented_guard_takes)
    double texel_most[MAX_WORLD_OBJECTS];
    // The polygons, room.polygons of them and room.vertices corners, where the owner puts them:
    FrameRoom room;
    uint8_t* polygon_size = nullptr;
    uint8_t* polygon_object = nullptr;  // whose texture (and wrap) it takes
    // 1: a face inside every clip plane, as it is (not cut). Its corners are within setup's limits
    // (setup.h), so the drawing does not check them again (Input::InRange): w within [near, far]
    // (its outcode), which the parser keeps within [MIN_W, MAX_W]; |x| and |y| at most 32 w (the
    // guard band's planes; 32 w is exact), so on screen within 160 +- 5120 and 120 +- 3840 pixels;
    // u and v are vt times the texture's side, at most MAX_TEXCOORD x MAX_TEXTURE_SIZE = MAX_UV;
    // all finite (the parser's numbers are). A cut face's corners are interpolated: checked.
    uint8_t* polygon_whole = nullptr;
    Vertex* vertices = nullptr;

    Frame() = default;
    Frame(const Frame&) = delete;  // (a copy would share the polygons)
    Frame& operator=(const Frame&) = delete;
};

// A point in clip space with its texture coordinates in texels. No default member initialisers:
// build_frame keeps arrays of them on the stack for every face, and zeroing those would take a large
// share of the geometry's time for values never read.
struct ClipVertex {
    double x, y, w;  // w: the depth along the view direction
    double u, v;
};
// A position in clip space (what the frame's positions need: their texture coordinates come with
// the faces' corners).
struct ClipPoint {
    double x, y, w;
};

// Working memory for build_frame (large: kept apart so that it can be static in the kernel).
struct FrameScratch {
    struct Entry {
        double depth;  // mean w of the face's corners (finite)
        int32_t object, face;  // face: its index in World::faces
        bool cut;      // some corner outside some plane: to be clipped
    };
    static constexpr int32_t DIGIT_COUNTS = 3 << 11;
    int32_t digit_count[DIGIT_COUNTS];  // the bucket sizes of its radix digits (three of 11 bits at most)
    // room.positions positions and room.polygons entries, where the owner puts them:
    FrameRoom room;
    ClipPoint* positions = nullptr;
    uint8_t* outcodes = nullptr;  // bit k: outside clip plane k
    Fixed24_8 *screen_x = nullptr, *screen_y = nullptr;  // projected, where the outcode is 0
    Entry* entries = nullptr;
    // painter_order's two buffers: each entry's key (its depth's bits, in halves) and index
    uint32_t *key_lo[2] = {}, *key_hi[2] = {};
    int32_t* order[2] = {};

    FrameScratch() = default;
    FrameScratch(const FrameScratch&) = delete;
    FrameScratch& operator=(const FrameScratch&) = delete;
};

#if __STDC_HOSTED__
// A frame and a scratch with room up to the limits.
struct HostFrame : Frame {
    uint8_t size_pool[MAX_FRAME_POLYGONS], object_pool[MAX_FRAME_POLYGONS], whole_pool[MAX_FRAME_POLYGONS];
    Vertex vertex_pool[MAX_FRAME_VERTICES];
    HostFrame() {
        room = FrameRoom::limits();
        polygon_size = size_pool, polygon_object = object_pool, polygon_whole = whole_pool, vertices = vertex_pool;
    }
};
struct HostFrameScratch : FrameScratch {
    ClipPoint position_pool[MAX_FRAME_POSITIONS];
    uint8_t outcode_pool[MAX_FRAME_POSITIONS];
    Fixed24_8 x_pool[MAX_FRAME_POSITIONS], y_pool[MAX_FRAME_POSITIONS];
    Entry entry_pool[MAX_FRAME_POLYGONS];
    uint32_t key_pool[4][MAX_FRAME_POLYGONS];
    int32_t order_pool[2][MAX_FRAME_POLYGONS];
    HostFrameScratch() {
        room = FrameRoom::limits();
        positions = position_pool, outcodes = outcode_pool, screen_x = x_pool, screen_y = y_pool, entries = entry_pool;
        key_lo[0] = key_pool[0], key_lo[1] = key_pool[1], key_hi[0] = key_pool[2], key_hi[1] = key_pool[3];
        order[0] = order_pool[0], order[1] = order_pool[1];
    }
};
#endif

// The painter's order of scratch->entries[0..n): far before near (the larger depth first), equal
// depths in the order they come in (build_frame makes them by object, then face: the same total
// order everywhere). A stable sort of the depth's bits: by the high word, then by the low word
// within runs that share one; each by insertion up to 16 places, else by radix, 11 or 8 bits a pass
// (a pass where every key has the same digit skipped: a frame's depths share their exponent). Returns
// the indices in order (scratch->order[0]).
const int32_t* painter_order(FrameScratch* scratch, int32_t n);

// The camera and projection of a frame: clip-space coordinates of world points.
struct View {
    Vec3 eye, side, up, forward;  // right-handed: forward = toward the target; side = forward x up
    double focal_x = 1, focal_y = 1;  // clip x = focal_x * (side . p), y = focal_y * (up . p)
    static View of(const Camera& camera, double time);
    ClipPoint clip(Vec3 world_point) const;
};

// An object's placement at a time: world = rotation(scale * model) + position.
struct Placement {
    Rotation rotation;
    double scale = 1;
    Vec3 position;
    static Placement of(const Object& object, double time);
    Vec3 apply(Vec3 p) const { return rotation.apply(scale * p) + position; }
    // A world point in the mesh's coordinates: apply's inverse (the rotation's transpose as its
    // inverse, within roundings).
    Vec3 unapply(Vec3 p) const {
        const Vec3 d = p - position;
        const double(&m)[3][3] = rotation.m;
        return (1 / scale) * Vec3{(m[0][0] * d.x + m[1][0] * d.y) + m[2][0] * d.z, (m[0][1] * d.x + m[1][1] * d.y) + m[2][1] * d.z,
                                  (m[0][2] * d.x + m[1][2] * d.y) + m[2][2] * d.z};
    }
};

void build_frame(const World& world, int32_t frame, Frame* out, FrameScratch* scratch);

// The object's envelope in a frame (TriangleEnvelope, docs/auto.md, "The object's envelope"):
// its mesh's measures at its placement, `nearest` at most the least w of the positions inside every
// clip plane that are corners of its faces drawn (build_frame: those of the faces not culled).
TriangleEnvelope object_envelope(const World& world, int32_t object, const Placement& place, const View& view, double nearest);
// Frame::texel_most's value for an object.
double object_texel_most(const World& world, int32_t object);

// Clips a convex polygon (in clip space) against the view volume: w >= near, w <= far,
// |x| <= GUARD_BAND w, |y| <= GUARD_BAND w, one plane after the other (Sutherland-Hodgman,
// attributes linear in clip space). Returns the corners written to `out` (room for count + 6).
int clip_polygon(const ClipVertex* in, int count, double near, double far, ClipVertex* out);

// The textures as the mappers take them, one per object (its wrap), with the copies the classic
// loops read (bordered; 64 KiB-aligned for 256 x 256 textures; doubled, for powers of two). Where
// the copies are is the owner's: the host's set keeps them at its limits (HostTextureSet), the
// kernel puts each texture's in buffers of their own (kernel/present/current_world.cpp).
struct TextureSet {
    Texture objects[MAX_WORLD_OBJECTS];
};
#if __STDC_HOSTED__
// The host's texture set, with room for every copy of textures up to the world's limits: the
// bordered copies, the aligned ones and the doubled ones (four times the texels and their borders,
// (2 W + 16)(2 H + 16) - 4 W H = 32 (W + H) + 256, at most 65792 bytes a texture).
struct HostTextureSet : TextureSet {
    static constexpr size_t BORDERED_BYTES = size_t(MAX_TEXEL_POOL) + 2 * MAX_WORLD_TEXTURES * 2 * (MAX_TEXTURE_SIZE + 2);
    static constexpr size_t DOUBLED_BYTES = 4 * size_t(MAX_TEXEL_POOL) + MAX_WORLD_TEXTURES * size_t(doubled_bytes(MAX_TEXTURE_SIZE, MAX_TEXTURE_SIZE) - 4 * MAX_TEXTURE_SIZE * MAX_TEXTURE_SIZE);
    uint8_t bordered[BORDERED_BYTES];
    uint8_t aligned[MAX_WORLD_TEXTURES][ALIGNED256_BYTES];
    uint8_t doubled[DOUBLED_BYTES];
};
// Every texture of the world with its copies (`doubled` false: without the doubled ones, as the
// kernel leaves them out where memory is short), and each object's (its wrap).
inline void build_texture_set(const World& world, HostTextureSet* out, bool doubled_copies = true) {
    size_t bordered = 0, doubled = 0;
    Texture prepared[MAX_WORLD_TEXTURES];
    for (int32_t i = 0; i < world.texture_count; ++i) {
        const WorldTexture& t = world.textures[i];
        prepared[i] = Texture{world.texels + t.offset, t.width, t.height, Wrap::Repeat};
        prepare_texture(&prepared[i], out->bordered + bordered, out->aligned[i], doubled_copies ? out->doubled + doubled : nullptr);
        bordered += size_t(bordered_bytes(t.width, t.height));
        if (prepared[i].doubled) doubled += size_t(doubled_bytes(t.width, t.height));
    }
    for (int32_t o = 0; o < world.object_count; ++o) {
        const Texture& copies = prepared[world.objects[o].texture];
        out->objects[o] = world.texture_of(o);
        out->objects[o].bordered = copies.bordered;
        out->objects[o].aligned256 = copies.aligned256;
        out->objects[o].doubled = copies.doubled;
    }
}
#endif

// Draws the frame's polygons in order into `target`; with a probe, times the phases (probe.h);
// with a watch, it may stop early (core/render.h). A mapper with a frame driver of its own
// (Mapper::draw_frame: auto) draws it.
RenderStats render_frame(const Frame& frame, const TextureSet& textures, const Mapper& mapper, Axis axis, Target& target,
                         Variant variant = Variant::Twin, Probe* probe = nullptr, const Watch* watch = nullptr);

// Each polygon of the frame in turn, the watch asked before it: draw(vertices, count, object,
// input), `input` InRange for an uncut face (its corners within setup's limits:
// Frame::polygon_whole). (A frame driver's loop: inline in it.)
template <typename Draw>
[[gnu::always_inline]] inline void each_frame_polygon(const Frame& frame, const Mapper& mapper, const Watch* watch, RenderStats* stats,
                                                      Draw&& draw) {
    const Vertex* v = frame.vertices;
    const uint8_t *const sizes = frame.polygon_size, *const objects = frame.polygon_object, *const whole = frame.polygon_whole;
    const int32_t count = frame.polygon_count;
    for (int32_t i = 0; i < count; ++i) {
        if (watch && watch->stops(uint32_t(i), uint32_t(count), stats)) break;
        if (watch) watch->drawing(mapper, uint32_t(i));
        const int n = sizes[i];
        draw(v, n, int(objects[i]), whole[i] ? Input::InRange : Input::Any);
        v += n;
    }
}

}  // namespace raster
