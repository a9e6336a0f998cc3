// From a 3D scene to a frame of screen-space polygons, and drawing them.
#include "kernel/scene/frame.h"

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
void project(const ClipVertex& p, Fixed24_8* x, Fixed24_8* y) {
    *x = snap(160.0 + 160.0 * (p.x / p.w));
    *y = snap(120.0 - 120.0 * (p.y / p.w));
}

// Twice the signed area of a face in clip space, as seen from the eye: the sum over its fan of
// det[A, B, C] with rows (x, y, w). Positive: the face's front (counter-clockwise in a right-handed
// world) is toward the eye, for any w, so faces reaching behind the eye are culled correctly too.
double facing(const ClipVertex* c, int n) {
    double sum = 0;
    for (int k = 1; k + 1 < n; ++k) {
        const ClipVertex &a = c[0], &b = c[k], &d = c[k + 1];
        sum += (a.x * (b.y * d.w - b.w * d.y) - a.y * (b.x * d.w - b.w * d.x)) + a.w * (b.x * d.y - b.y * d.x);
    }
    return sum;
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

ClipVertex between(const ClipVertex& a, const ClipVertex& b, double t) {
    return ClipVertex{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.w + t * (b.w - a.w), a.u + t * (b.u - a.u), a.v + t * (b.v - a.v)};
}

// Far before near; equal depths by object, then face: a total order, the same everywhere.
bool before(const FrameScratch::Entry& a, const FrameScratch::Entry& b) {
    if (a.depth != b.depth) return a.depth > b.depth;
    if (a.object != b.object) return a.object < b.object;
    return a.face < b.face;
}

// Bottom-up merge sort of entries[0..n) (through `sorted`); the result in entries.
void sort_entries(FrameScratch::Entry* entries, FrameScratch::Entry* tmp, int32_t n) {
    FrameScratch::Entry *from = entries, *to = tmp;
    for (int32_t width = 1; width < n; width *= 2) {
        for (int32_t lo = 0; lo < n; lo += 2 * width) {
            int32_t mid = lo + width < n ? lo + width : n, hi = lo + 2 * width < n ? lo + 2 * width : n;
            int32_t i = lo, j = mid, k = lo;
            while (i < mid && j < hi) to[k++] = before(from[j], from[i]) ? from[j++] : from[i++];
            while (i < mid) to[k++] = from[i++];
            while (j < hi) to[k++] = from[j++];
        }
        FrameScratch::Entry* t = from;
        from = to, to = t;
    }
    if (from != entries)
        for (int32_t i = 0; i < n; ++i) entries[i] = from[i];
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

ClipVertex View::clip(Vec3 p) const {
    Vec3 d = p - eye;
    return ClipVertex{focal_x * dot(side, d), focal_y * dot(up, d), dot(forward, d), 0, 0};
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

void build_frame(const World& world, int32_t frame_number, Frame* out, FrameScratch* scratch) {
    Frame& f = *out;
    f.number = frame_number;
    f.polygon_count = f.vertex_count = 0;
    f.stats = FrameStats{};
    f.budget = world.budget;
    f.object_count = world.object_count;
    const double time = frame_time(frame_number);
    const View view = View::of(world.camera, time);
    const double near = world.camera.near, far = world.camera.far;

    // every object's positions in clip space; every face that might show, with its depth
    int32_t first_position[MAX_WORLD_OBJECTS];
    int32_t used = 0, entries = 0;
    for (int32_t o = 0; o < world.object_count; ++o) {
        const Object& object = world.objects[o];
        const Mesh& mesh = world.meshes[object.mesh];
        f.stats.faces += uint32_t(mesh.face_count);
        if (used + mesh.position_count > MAX_FRAME_POSITIONS) {
            f.stats.overflow += uint32_t(mesh.face_count);
            first_position[o] = -1;
            f.envelope[o] = EnvelopeBound{};
            continue;
        }
        first_position[o] = used;
        const Placement place = Placement::of(object, time);
        double nearest = far;  // the least w of a position inside every plane (the corners of uncut faces)
        for (int32_t i = 0; i < mesh.position_count; ++i) {
            const ClipVertex p = view.clip(place.apply(world.positions[mesh.first_position + i]));
            uint8_t code = 0;
            for (int plane = 0; plane < 6; ++plane) code |= uint8_t((distance(p, plane, near, far) < 0) << plane);
            scratch->positions[used + i] = p;
            scratch->outcodes[used + i] = code;
            // projected once here rather than at every corner that shares it (faces inside every
            // plane take their corners from here; a clipped face's corners are projected below)
            if (code == 0) {
                project(p, &scratch->screen_x[used + i], &scratch->screen_y[used + i]);
                nearest = p.w < nearest ? p.w : nearest;
            }
        }
        f.envelope[o] = envelope_bound(object_envelope(world, o, place, view, nearest));
        used += mesh.position_count;
        for (int32_t k = 0; k < mesh.face_count; ++k) {
            const Face& face = world.faces[mesh.first_face + k];
            ClipVertex c[MAX_FACE_CORNERS];
            uint8_t all = 0x3F, any = 0;  // planes every corner is outside; planes some corner is
            double depth = 0;
            for (int32_t i = 0; i < face.count; ++i) {
                int32_t at = first_position[o] + world.corners[face.first_corner + i].position - mesh.first_position;
                c[i] = scratch->positions[at];
                depth += c[i].w;
                all &= scratch->outcodes[at];
                any |= scratch->outcodes[at];
            }
            if (object.cull == Cull::Back && !(facing(c, face.count) > 0)) {
                ++f.stats.culled;
                continue;
            }
            if (all) {
                ++f.stats.outside;
                continue;
            }
            if (entries == MAX_FRAME_POLYGONS) {
                ++f.stats.overflow;
                continue;
            }
            scratch->entries[entries++] = FrameScratch::Entry{depth / face.count, o, k, any != 0};
        }
    }
    sort_entries(scratch->entries, scratch->sorted, entries);

    for (int32_t e = 0; e < entries; ++e) {
        const FrameScratch::Entry& entry = scratch->entries[e];
        const Object& object = world.objects[entry.object];
        const Mesh& mesh = world.meshes[object.mesh];
        const WorldTexture& texture = world.textures[object.texture];
        const Face& face = world.faces[mesh.first_face + entry.face];
        const int32_t base = first_position[entry.object] - mesh.first_position;
        int n = face.count;
        ClipVertex clipped[MAX_FACE_CORNERS + 6];
        if (entry.cut) {  // (a face inside every plane is its own clipped polygon)
            ClipVertex c[MAX_FACE_CORNERS];
            for (int32_t i = 0; i < n; ++i) {
                const Corner& corner = world.corners[face.first_corner + i];
                c[i] = scratch->positions[base + corner.position];
                c[i].u = world.uvs[corner.uv].u * texture.width;
                c[i].v = world.uvs[corner.uv].v * texture.height;
            }
            n = clip_polygon(c, face.count, near, far, clipped);
            if (n < 3) {
                ++f.stats.outside;
                continue;
            }
            ++f.stats.clipped;
        }
        if (f.vertex_count + n > MAX_FRAME_VERTICES) {
            ++f.stats.overflow;
            continue;
        }
        Vertex* corners = f.vertices + f.vertex_count;
        for (int i = 0; i < n; ++i) {
            if (entry.cut) {
                const ClipVertex& p = clipped[i];
                corners[i] = Vertex{{}, {}, p.w, p.u, p.v};
                project(p, &corners[i].x, &corners[i].y);
            } else {  // its corners as projected above
                const Corner& corner = world.corners[face.first_corner + i];
                const int32_t at = base + corner.position;
                corners[i] = Vertex{scratch->screen_x[at], scratch->screen_y[at], scratch->positions[at].w,
                                    world.uvs[corner.uv].u * texture.width, world.uvs[corner.uv].v * texture.height};
            }
        }
        f.polygon_size[f.polygon_count] = uint8_t(n);
        f.polygon_object[f.polygon_count] = uint8_t(entry.object);
        f.polygon_whole[f.polygon_count] = uint8_t(entry.cut ? 0 : 1);
        ++f.polygon_count;
        f.vertex_count += n;
        ++f.stats.polygons;
    }
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

void build_texture_set(const World& world, TextureSet* out) {
    size_t bordered = 0;
    Texture prepared[MAX_WORLD_TEXTURES];
    for (int32_t i = 0; i < world.texture_count; ++i) {
        const WorldTexture& t = world.textures[i];
        prepared[i] = Texture{world.texels + t.offset, t.width, t.height, Wrap::Repeat};
        prepare_texture(&prepared[i], out->bordered + bordered, out->aligned[i]);
        bordered += size_t(bordered_bytes(t.width, t.height));
    }
    for (int32_t o = 0; o < world.object_count; ++o) {
        out->objects[o] = world.texture_of(o);
        out->objects[o].bordered = prepared[world.objects[o].texture].bordered;
        out->objects[o].aligned256 = prepared[world.objects[o].texture].aligned256;
    }
}

RenderStats render_frame(const Frame& frame, const TextureSet& textures, const Mapper& mapper, Axis axis, Target& target, Variant variant,
                         Probe* probe, const Watch* watch) {
    RenderStats stats;
    stats.probe = probe;
    // auto: what it settles once a frame per object (choice.h, AutoPlan)
    AutoPlan plans[MAX_WORLD_OBJECTS];
    if (mapper.chooses)
        for (int32_t o = 0; o < MAX_WORLD_OBJECTS && o < frame.object_count; ++o)
            plans[o] = plan_auto(frame.budget, textures.objects[o], target, frame.envelope[o].footprint);
    const Vertex* v = frame.vertices;
    for (int32_t i = 0; i < frame.polygon_count; ++i) {
        if (watch && watch->stops(uint32_t(i), uint32_t(frame.polygon_count), &stats)) break;
        if (watch) watch->drawing(mapper, uint32_t(i));
        const int object = frame.polygon_object[i], n = frame.polygon_size[i];
        const Texture& tex = textures.objects[object];
        const AutoPlan& plan = plans[object];
        Axis unchosen_axis;
        const Mapper* unchosen = nullptr;
        if (!mapper.chooses)
            draw_polygon(v, n, tex, mapper, axis, target, &stats, variant);
        else if (plan.enveloped && frame.polygon_whole[i] && n == 3)
            draw_enveloped(v, tex, *plan.enveloped, plan.enveloped_axis, target, &stats, variant, frame.budget);
        else if ((unchosen = unchosen_mapper(plan, v, n, target.clip, &unchosen_axis)))
            draw_polygon(v, n, tex, *unchosen, unchosen_axis, target, &stats, variant);
        else
            draw_polygon(v, n, tex, mapper, axis, target, &stats, variant, frame.budget);
        v += n;
    }
    if (watch) watch->drawn();
    return stats;
}

}  // namespace raster
