// From a 3D scene to a frame of screen-space polygons, and drawing them.
#include "kernel/scene/frame.h"

#include "kernel/core/footprint.h"
#include "kernel/core/policy.h"

namespace raster {

namespace {

// The path's point at `time`: keys loop over the last key's time; linear between keys.
PathKey on_path(const PathKey* keys, int32_t count, double time) {
    if (count == 1) return keys[0];
    const double period = keys[count - 1].time;
    if (period > 0) time -= period * double(floor_i64(time / period));
    if (time <= keys[0].time) return keys[0];
    for (int32_t i = 1; i < count; ++i)
        if (time <= keys[i].time) {
            double t = (time - keys[i - 1].time) / (keys[i].time - keys[i - 1].time);
            return PathKey{time, lerp(keys[i - 1].position, keys[i].position, t), lerp(keys[i - 1].target, keys[i].target, t)};
        }
    return keys[count - 1];
}

// A clip-space point on the 320 x 240 screen, snapped to the subpixel grid.
template <typename P>  // ClipVertex or ClipPoint
void project(const P& p, Fixed24_8* x, Fixed24_8* y) {
    *x = snap(160.0 + 160.0 * (p.x / p.w));
    *y = snap(120.0 - 120.0 * (p.y / p.w));
}

// Signed distance to clip plane `plane` (inside: >= 0).
double distance(const ClipVertex& p, int plane, double near, double far) {
    switch (plane) {
    case 0: return p.w - near;
    case 1: return far - p.w;
    case 2: return GUARD_BAND * p.w + p.x;
    case 3: return GUARD_BAND * p.w - p.x;
    case 4: return GUARD_BAND * p.w + p.y;
    default: return GUARD_BAND * p.w - p.y;
    }
}

// The outcode of a point: bit k set where it lies outside clip plane k (distance() below 0), all six
// at once (the same expressions, the guard band's product taken once).
uint8_t outcode(const ClipPoint& p, double near, double far) {
    const double band = GUARD_BAND * p.w;
    return uint8_t(int(p.w - near < 0) | int(far - p.w < 0) << 1 | int(band + p.x < 0) << 2 | int(band - p.x < 0) << 3 |
                   int(band + p.y < 0) << 4 | int(band - p.y < 0) << 5);
}

ClipVertex between(const ClipVertex& a, const ClipVertex& b, double t) {
    return ClipVertex{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.w + t * (b.w - a.w), a.u + t * (b.u - a.u), a.v + t * (b.v - a.v)};
}

}  // namespace

View View::of(const Camera& camera, double time) {
    View v;
    Vec3 target = camera.target;
    v.eye = camera.position;
    if (camera.key_count > 0) {
        PathKey k = on_path(camera.keys, camera.key_count, time);
        v.eye = k.position, target = k.target;
    }
    v.forward = normalize(target - v.eye);
    v.side = normalize(cross(v.forward, camera.up));
    v.up = cross(v.side, v.forward);
    double s, c;
    sin_cos_degrees(camera.fov_degrees / 2, &s, &c);
    v.focal_y = c / s;  // 1 / tan(fov / 2)
    v.focal_x = v.focal_y / SCREEN_ASPECT;
    return v;
}

ClipPoint View::clip(Vec3 p) const {
    Vec3 d = p - eye;
    return ClipPoint{focal_x * dot(side, d), focal_y * dot(up, d), dot(forward, d)};
}

Placement Placement::of(const Object& o, double time) {
    Placement p;
    Rotation fixed = Rotation::about(o.rotate_axis, o.rotate_degrees);
    p.rotation = o.spin_degrees_per_second != 0 ? Rotation::about(o.spin_axis, o.spin_degrees_per_second * time).after(fixed) : fixed;
    p.scale = o.scale;
    p.position = o.key_count > 0 ? on_path(o.keys, o.key_count, time).position : o.position;
    return p;
}

int clip_polygon(const ClipVertex* in, int count, double near, double far, ClipVertex* out) {
    ClipVertex a[MAX_POLYGON_VERTICES + 6], b[MAX_POLYGON_VERTICES + 6];
    const ClipVertex* from = in;
    ClipVertex* to = a;
    int n = count;
    for (int plane = 0; plane < 6 && n > 0; ++plane) {
        int m = 0;
        for (int i = 0; i < n; ++i) {
            const ClipVertex &p = from[i], &q = from[i + 1 < n ? i + 1 : 0];
            double dp = distance(p, plane, near, far), dq = distance(q, plane, near, far);
            if (dp >= 0) to[m++] = p;
            if ((dp >= 0) != (dq >= 0)) to[m++] = between(p, q, dp / (dp - dq));
        }
        n = m;
        from = to;
        to = to == a ? b : a;
    }
    for (int i = 0; i < n; ++i) {
        out[i] = from[i];
        // interpolation may land a hair outside [near, far]: the setup's w limits must hold
        if (out[i].w < near) out[i].w = near;
        if (out[i].w > far) out[i].w = far;
    }
    return n;
}

namespace {

// Three arrays a sort moves together, twice: [0] holds them, [1] is room to move them into.
struct SortBuffers {
    uint32_t* key[2];    // what they are sorted by
    uint32_t* other[2];  // the rest of the key, carried along
    int32_t* at[2];      // the entries' indices, carried along
    int32_t* count;      // room for the digits' bucket sizes (FrameScratch::DIGIT_COUNTS)
};

// One stable counting pass over places [b, e) by the BITS-bit digit of the keys at `shift`, whose
// bucket sizes are in `count` (made starts here), from buffer `from` into the same places of the
// other.
template <int BITS>
void digit_pass(const SortBuffers& s, int from, int32_t b, int32_t e, int shift, int32_t* count) {
    constexpr uint32_t BUCKETS = 1u << BITS;
    for (uint32_t k = 0, sum = uint32_t(b); k < BUCKETS; ++k) {
        const int32_t c = count[k];
        count[k] = int32_t(sum), sum += uint32_t(c);
    }
    const uint32_t* key = s.key[from];
    const int to = 1 - from;
    for (int32_t i = b; i < e; ++i) {
        const int32_t k = count[(key[i] >> shift) & (BUCKETS - 1)]++;
        s.key[to][k] = key[i], s.other[to][k] = s.other[from][i], s.at[to][k] = s.at[from][i];
    }
}

// Places [b, e) of buffer 0 by the key's BITS-bit digits, the least significant first: every
// digit's bucket sizes counted in one pass, and a pass skipped where every key has the same digit
// (a frame's depths share their sign and exponent, so most of the top digit). The result in buffer
// 0.
template <int BITS>
void radix_sort(const SortBuffers& s, int32_t b, int32_t e) {
    constexpr int DIGITS = (32 + BITS - 1) / BITS;
    constexpr uint32_t BUCKETS = 1u << BITS;
    static_assert(DIGITS * BUCKETS <= FrameScratch::DIGIT_COUNTS);
    uint32_t *key = s.key[0], *other = s.other[0];
    int32_t* at = s.at[0];
    int32_t* count = s.count;
    __builtin_memset(count, 0, sizeof(int32_t) * DIGITS * BUCKETS);
    for (int32_t i = b; i < e; ++i) {
        const uint32_t k = key[i];
#pragma GCC unroll 4
        for (int d = 0; d < DIGITS; ++d) ++count[d * BUCKETS + ((k >> (d * BITS)) & (BUCKETS - 1))];
    }
    int in = 0;
    for (int d = 0; d < DIGITS; ++d) {
        int32_t* c = count + d * BUCKETS;
        const int shift = d * BITS;
        if (c[(key[b] >> shift) & (BUCKETS - 1)] == e - b) continue;  // (key: buffer 0's; any key has the digit then)
        digit_pass<BITS>(s, in, b, e, shift, c);
        in = 1 - in;
    }
    if (in == 1)
        for (int32_t i = b; i < e; ++i) key[i] = s.key[1][i], other[i] = s.other[1][i], at[i] = s.at[1][i];
}

// A stable sort of places [b, e) of buffer 0 by key, the result in buffer 0: by insertion up to 16
// places (moved only past larger keys), else by radix: 11-bit digits from 1024 places (three
// passes at most, 6144 buckets to clear), bytes below (four, 1024).
void sort_by_key(const SortBuffers& s, int32_t b, int32_t e) {
    if (e - b > 16) {
        if (e - b >= 1024) radix_sort<11>(s, b, e);
        else radix_sort<8>(s, b, e);
        return;
    }
    uint32_t *key = s.key[0], *other = s.other[0];
    int32_t* at = s.at[0];
    for (int32_t i = b + 1; i < e; ++i) {
        const uint32_t k = key[i], o = other[i];
        const int32_t index = at[i];
        int32_t j = i;
        for (; j > b && key[j - 1] > k; --j) key[j] = key[j - 1], other[j] = other[j - 1], at[j] = at[j - 1];
        key[j] = k, other[j] = o, at[j] = index;
    }
}

}  // namespace

const int32_t* painter_order(FrameScratch* scratch, int32_t n) {
    uint32_t *lo = scratch->key_lo[0], *hi = scratch->key_hi[0];
    int32_t* at = scratch->order[0];
    for (int32_t i = 0; i < n; ++i) {
        // the depth's bits as an unsigned key that grows with it (-0 first made +0: equal depths,
        // equal keys), then inverted: the far ones first
        const double depth = scratch->entries[i].depth + 0.0;
        uint64_t bits;
        __builtin_memcpy(&bits, &depth, sizeof bits);
        bits = ~(bits >> 63 ? ~bits : bits | (uint64_t(1) << 63));
        lo[i] = uint32_t(bits), hi[i] = uint32_t(bits >> 32), at[i] = i;
    }
    // By the high word (sign, exponent, the top 20 bits of the mantissa), then the low word within
    // each run of one high word (a frame's depths rarely share one)
    sort_by_key(SortBuffers{{hi, scratch->key_hi[1]}, {lo, scratch->key_lo[1]}, {at, scratch->order[1]}, scratch->digit_count}, 0, n);
    const SortBuffers by_low{{lo, scratch->key_lo[1]}, {hi, scratch->key_hi[1]}, {at, scratch->order[1]}, scratch->digit_count};
    for (int32_t b = 0, e; b < n; b = e) {
        for (e = b + 1; e < n && hi[e] == hi[b]; ++e) {
        }
        if (e - b > 1) sort_by_key(by_low, b, e);
    }
    return at;
}

void build_frame(const World& world, int32_t frame_number, Frame* out, FrameScratch* scratch) {
    Frame& f = *out;
    f.number = frame_number;
    f.polygon_count = f.vertex_count = 0;
    // The parts, each through a pointer of its own (a byte stored through one may alias any other
    // memory, the structs' pointers too: kept in locals, they are not read again after it)
    const Vec3* const world_positions = world.positions;
    const TexCoord* const uvs = world.uvs;
    const Face* const faces = world.faces;
    const Corner* const world_corners = world.corners;
    ClipPoint* const positions = scratch->positions;  // (by `at` below: base + the world's index)
    uint8_t* const codes = scratch->outcodes;
    Fixed24_8* const screen_x = scratch->screen_x;
    Fixed24_8* const screen_y = scratch->screen_y;
    FrameScratch::Entry* const entry_list = scratch->entries;
    uint8_t* const polygon_size = f.polygon_size;
    uint8_t* const polygon_object = f.polygon_object;
    uint8_t* const polygon_whole = f.polygon_whole;
    Vertex* const vertices = f.vertices;
    const int32_t position_room = scratch->room.positions, polygon_room = scratch->room.polygons < f.room.polygons ? scratch->room.polygons : f.room.polygons;
    const int32_t vertex_room = f.room.vertices;
    int32_t polygon_count = 0, vertex_count = 0;
    f.stats = FrameStats{};
    f.budget = world.budget;
    f.object_count = world.object_count;
    const double time = frame_time(frame_number);
    const View view = View::of(world.camera, time);
    const double near = world.camera.near, far = world.camera.far;

    // Every face that might show, with its depth: culled first, by its plane and the eye in its
    // mesh's coordinates (the sign of the eye's distance from the plane: a scale is positive, so the
    // placement keeps the front), and only then its corners in clip space, each position
    // transformed and projected at its first use in the frame (a face culled needs none of them).
    // Each object's base (a world position's index plus it: that position's index in the scratch
    // arrays; an index, not a pointer moved by it: it may be below 0) and its texture's size, for
    // the corners written below.
    int32_t bases[MAX_WORLD_OBJECTS];
    double sizes[MAX_WORLD_OBJECTS][2];
    constexpr uint8_t UNSEEN = 0xFF;  // an outcode no position has: not yet transformed (codes are 6 bits)
    int32_t used = 0, entries = 0;
    for (int32_t o = 0; o < world.object_count; ++o) {
        const Object& object = world.objects[o];
        const Mesh& mesh = world.meshes[object.mesh];
        f.stats.faces += uint32_t(mesh.face_count);
        if (used + mesh.position_count > position_room) {
            f.stats.overflow += uint32_t(mesh.face_count);
            f.envelope[o] = EnvelopeBound{}, f.texel_most[o] = NO_BOUND;
            continue;
        }
        const Placement place = Placement::of(object, time);
        const Vec3 eye = place.unapply(view.eye);
        const bool cull = object.cull == Cull::Back;
        const int32_t base = used - mesh.first_position;
        const WorldTexture& texture = world.textures[object.texture];
        bases[o] = base, sizes[o][0] = texture.width, sizes[o][1] = texture.height;
        __builtin_memset(codes + used, UNSEEN, size_t(mesh.position_count));
        used += mesh.position_count;
        double nearest = far;  // the least w of a position inside every plane (the corners of uncut faces)
        for (int32_t k = 0; k < mesh.face_count; ++k) {
            const Face& face = faces[mesh.first_face + k];
            if (cull && !(dot(face.normal, eye) > face.offset)) {
                ++f.stats.culled;
                continue;
            }
            uint8_t all = 0x3F, any = 0;  // planes every corner is outside; planes some corner is
            double depth = 0;
            for (int32_t i = 0; i < face.count; ++i) {
                const int32_t position = world_corners[face.first_corner + i].position, at = base + position;
                if (codes[at] == UNSEEN) {
                    const ClipPoint p = view.clip(place.apply(world_positions[position]));
                    positions[at] = p;
                    codes[at] = outcode(p, near, far);
                    // projected once here rather than at every corner that shares it (faces inside
                    // every plane take their corners from here; a clipped face's corners are
                    // projected below)
                    if (codes[at] == 0) {
                        project(p, &screen_x[at], &screen_y[at]);
                        nearest = p.w < nearest ? p.w : nearest;
                    }
                }
                depth += positions[at].w;
                all &= codes[at];
                any |= codes[at];
            }
            if (all) {
                ++f.stats.outside;
                continue;
            }
            if (entries == polygon_room) {
                ++f.stats.overflow;
                continue;
            }
            entry_list[entries++] = FrameScratch::Entry{depth / face.count, o, mesh.first_face + k, any != 0};
        }
        f.envelope[o] = envelope_bound(object_envelope(world, o, place, view, nearest));
        f.texel_most[o] = object_texel_most(world, o);
    }
    const int32_t* order = painter_order(scratch, entries);

    for (int32_t e = 0; e < entries; ++e) {
        const FrameScratch::Entry& entry = entry_list[order[e]];
        const Face& face = faces[entry.face];
        const int32_t base = bases[entry.object];
        const double width = sizes[entry.object][0], height = sizes[entry.object][1];
        int n = face.count;
        ClipVertex clipped[MAX_FACE_CORNERS + 6];
        if (entry.cut) {  // (a face inside every plane is its own clipped polygon)
            ClipVertex c[MAX_FACE_CORNERS];
            for (int32_t i = 0; i < n; ++i) {
                const Corner& corner = world_corners[face.first_corner + i];
                const ClipPoint& p = positions[base + corner.position];
                c[i] = ClipVertex{p.x, p.y, p.w, uvs[corner.uv].u * width, uvs[corner.uv].v * height};
            }
            n = clip_polygon(c, face.count, near, far, clipped);
            if (n < 3) {
                ++f.stats.outside;
                continue;
            }
            ++f.stats.clipped;
        }
        if (vertex_count + n > vertex_room) {
            ++f.stats.overflow;
            continue;
        }
        Vertex* corners = vertices + vertex_count;
        if (entry.cut) {
            for (int i = 0; i < n; ++i) {
                const ClipVertex& p = clipped[i];
                corners[i] = Vertex{{}, {}, p.w, p.u, p.v};
                project(p, &corners[i].x, &corners[i].y);
            }
        } else {  // its corners as projected above
            const Corner* corner = world_corners + face.first_corner;
            for (int i = 0; i < n; ++i) {
                const int32_t at = base + corner[i].position;
                const TexCoord& uv = uvs[corner[i].uv];
                Vertex& v = corners[i];
                v.x = screen_x[at], v.y = screen_y[at];
                v.w = positions[at].w;
                v.u = uv.u * width, v.v = uv.v * height;
            }
        }
        polygon_size[polygon_count] = uint8_t(n);
        polygon_object[polygon_count] = uint8_t(entry.object);
        polygon_whole[polygon_count] = uint8_t(entry.cut ? 0 : 1);
        ++polygon_count;
        vertex_count += n;
        ++f.stats.polygons;
    }
    f.polygon_count = polygon_count, f.vertex_count = vertex_count;
}

TriangleEnvelope object_envelope(const World& world, int32_t o, const Placement& place, const View& view, double nearest) {
    const Object& object = world.objects[o];
    const Mesh& mesh = world.meshes[object.mesh];
    const WorldTexture& texture = world.textures[object.texture];
    // u = vt * size in double: each within a rounding of its product, so a range within two of its
    // magnitude's; w within 2^-40 of the distances it is computed from (a dot product of a
    // difference of sums: some ten roundings of 2^-53); edges no longer than the mesh's scaled, a
    // rotation's length error of a few roundings aside
    constexpr double R = 0x1p-40;
    TriangleEnvelope e;
    const double size[2] = {double(texture.width), double(texture.height)};
    for (int t = 0; t < 2; ++t) {
        e.texel_abs[t] = mesh.triangle_uv_abs[t] * size[t] * (1 + R);
        e.texel_range[t] = (mesh.triangle_uv_range[t] + R * mesh.triangle_uv_abs[t]) * size[t] * (1 + R);
    }
    const double scale = magnitude(place.scale), w_error = R * (scale * mesh.radius + length(place.position) + length(view.eye));
    e.depth_ratio = nearest > 0 && mesh.measured ? (scale * mesh.triangle_edge * (1 + 0x1p-30) + 2 * w_error) / nearest : NO_BOUND;
    return e;
}

double object_texel_most(const World& world, int32_t o) {
    const Object& object = world.objects[o];
    const Mesh& mesh = world.meshes[object.mesh];
    const WorldTexture& texture = world.textures[object.texture];
    // (each product within a rounding, and a cut corner within a few of its ends' largest)
    return larger(mesh.uv_abs[0] * double(texture.width), mesh.uv_abs[1] * double(texture.height)) * (1 + 0x1p-40);
}

FrameRoom frame_room(const World& world) {
    int64_t polygons = 0, vertices = 0, positions = 0;
    for (int32_t o = 0; o < world.object_count; ++o) {
        const Mesh& mesh = world.meshes[world.objects[o].mesh];
        polygons += mesh.face_count, positions += mesh.position_count;
        for (int32_t k = 0; k < mesh.face_count; ++k) vertices += world.faces[mesh.first_face + k].count + 6;
    }
    const FrameRoom most = FrameRoom::limits();
    auto at_most = [](int64_t n, int32_t limit) { return int32_t(n < limit ? n : limit); };
    return FrameRoom{at_most(polygons, most.polygons), at_most(vertices, most.vertices), at_most(positions, most.positions)};
}

RenderStats render_frame(const Frame& frame, const TextureSet& textures, const Mapper& mapper, Axis axis, Target& target, Variant variant,
                         Probe* probe, const Watch* watch) {
    if (mapper.draw_frame) return mapper.draw_frame(frame, textures, mapper, axis, target, variant, probe, watch);
    RenderStats stats;
    stats.probe = probe;
    // what the mapper settles once for a texture (render.h, Drawer)
    Drawer drawers[MAX_WORLD_OBJECTS];
    for (int32_t o = 0; o < MAX_WORLD_OBJECTS && o < frame.object_count; ++o)
        drawers[o] = Drawer::of(mapper, textures.objects[o], axis, target, &stats, variant);
    each_frame_polygon(frame, mapper, watch, &stats, [&](const Vertex* v, int n, int object, Input input) {
        const Drawer& d = drawers[object];
        if (d.own) d.draw_own(v, n, input);
        else d.draw(v, n, input);
    });
    if (watch) watch->drawn();
    return stats;
}

}  // namespace raster
