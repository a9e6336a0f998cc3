// The version 2 scene parser: top-level lines and mesh, object and camera blocks; then the checks
// that need the whole file, and the palette remap.
#include "kernel/scene/world.h"

#include "kernel/lib/fmt.h"
#include "kernel/scene/image.h"
#include "kernel/scene/scene_text.h"

namespace raster {

namespace {

using lib::Fmt;
using lib::StrView;
using scene_text::parse_decimal;
using scene_text::parse_int;

constexpr int MAX_LINE_WORDS = 2 + MAX_FACE_CORNERS + 1;  // a face line and one word too many
constexpr size_t MAX_WORLD_BYTES = 4 << 20;

enum class Block : uint8_t { None, Mesh, Object, Camera };

struct Parser {
    World* world;
    const FileResolver* files;
    ParseError* error;
    int32_t line = 0;
    Block block = Block::None;
    int32_t block_line = 0;
    bool have_camera = false, have_palette = false, have_frames = false;
    Palette sources[MAX_WORLD_TEXTURES];  // each texture's own palette, before the remap

    bool fail(const Fmt& m) { return scene_text::fail(error, line, m.c_str()); }
};

void copy_name(char* out, size_t capacity, StrView w) {
    size_t i = 0;
    for (; i < w.size && i + 1 < capacity; ++i) out[i] = w.data[i];
    out[i] = 0;
}

bool name_is(const char* name, StrView w) { return w.equals(name); }

bool check_name(Parser& p, StrView w, const char* what) {
    if (!world_name_ok(w)) return p.fail(Fmt().s("bad ").s(what).s(" name '").s(w).s("' (").s(WORLD_NAME_RULE).s(")"));
    return true;
}

// A file name: a relative path of 1..63 such characters and '/', without '..' components.
bool check_file_name(Parser& p, StrView w) {
    bool ok = w.size >= 1 && w.size < size_t(MAX_FILE_NAME) && w.data[0] != '/';
    for (size_t i = 0; ok && i < w.size; ++i) {
        char c = w.data[i];
        ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.' || c == '/';
        if (c == '.' && i + 1 < w.size && w.data[i + 1] == '.' && (i == 0 || w.data[i - 1] == '/')) ok = false;
    }
    if (!ok) return p.fail(Fmt().s("bad file name '").s(w).s("' (a relative path of at most 63 letters, digits, '-', '_', '.', '/'; no '..')"));
    return true;
}

// v to at most 6 decimals, trailing zeros dropped (-16384, 0.000001, 170): a range's ends.
Fmt& put_limit(Fmt& m, double v) {
    if (v < 0) m.s("-"), v = -v;
    const uint64_t micro = uint64_t(v * 1e6 + 0.5);
    m.u(uint32_t(micro / 1000000));
    uint32_t fraction = uint32_t(micro % 1000000);
    if (!fraction) return m;
    char digits[7] = {};
    for (int i = 5; i >= 0; --i) digits[i] = char('0' + fraction % 10), fraction /= 10;
    for (int i = 5; i > 0 && digits[i] == '0'; --i) digits[i] = 0;
    return m.s(".").s(digits);
}

bool number(Parser& p, StrView w, const char* what, double lo, double hi, double* out) {
    if (!parse_decimal(w, out)) return p.fail(Fmt().s("bad number '").s(w).s("' for ").s(what).s(" (a decimal with at most 6 digits after the point)"));
    if (!(*out >= lo && *out <= hi)) {
        Fmt m;
        m.s(what).s(" '").s(w).s("' out of range (");
        put_limit(m, lo).s(" to ");
        return p.fail(put_limit(m, hi).s(")"));
    }
    return true;
}

bool vec3(Parser& p, const StrView* w, const char* what, Vec3* out) {
    return number(p, w[0], what, -MAX_WORLD_COORD, MAX_WORLD_COORD, &out->x) && number(p, w[1], what, -MAX_WORLD_COORD, MAX_WORLD_COORD, &out->y) &&
           number(p, w[2], what, -MAX_WORLD_COORD, MAX_WORLD_COORD, &out->z);
}

bool usage(Parser& p, size_t n, size_t want, const char* text) {
    if (n == want) return true;
    return p.fail(Fmt().s("usage: ").s(text));
}

int32_t find_texture(const World& w, StrView name) {
    for (int32_t i = 0; i < w.texture_count; ++i)
        if (name_is(w.textures[i].name, name)) return i;
    return -1;
}

int32_t find_mesh(const World& w, StrView name) {
    for (int32_t i = 0; i < w.mesh_count; ++i)
        if (name_is(w.meshes[i].name, name)) return i;
    return -1;
}

// Repeats the image of w x h texels at `texels` across `width` x `height` (whole multiples of w and
// h), in place: row y of the result is row y mod h of the image. From the last texel back, so that
// no image texel is overwritten before it is read: result row y starts at or after image row y
// (past its end unless y = 0 or width = w, where it copies the row onto itself), and the result
// rows still to come, those above y, read only image rows above y.
void tile_in_place(uint8_t* texels, int32_t w, int32_t h, int32_t width, int32_t height) {
    for (int32_t y = height - 1; y >= 0; --y) {
        const uint8_t* row = texels + size_t(y % h) * size_t(w);
        uint8_t* out = texels + size_t(y) * size_t(width);
        for (int32_t x = width - 1; x >= 0; --x) out[x] = row[x % w];
    }
}

bool too_many_texels(Parser& p) { return p.fail(Fmt().s("textures too large together (at most ").u(p.world->room.texels).s(" texels)")); }

// texture NAME KIND W H | texture NAME file PATH [tile W H]
bool texture_line(Parser& p, const StrView* w, size_t n) {
    World& world = *p.world;
    const bool file = n >= 3 && w[2].equals("file"), tiled = file && n == 7 && w[4].equals("tile");
    if (n < 3 || (file ? n != 4 && !tiled : n != 5))
        return p.fail(Fmt().s("usage: texture NAME checker|grid|numbered|xor|gradient WIDTH HEIGHT, or texture NAME file PATH [tile WIDTH HEIGHT]"));
    if (!check_name(p, w[1], "texture")) return false;
    if (find_texture(world, w[1]) >= 0) return p.fail(Fmt().s("a second texture named '").s(w[1]).s("'"));
    if (world.texture_count == MAX_WORLD_TEXTURES) return p.fail(Fmt().s("too many textures (at most 16)"));
    WorldTexture& t = world.textures[world.texture_count];
    t = WorldTexture{};
    copy_name(t.name, sizeof t.name, w[1]);
    t.offset = world.texel_count;
    const size_t room = size_t(world.room.texels) - world.texel_count;
    Palette& source = p.sources[world.texture_count];
    if (w[2].equals("file")) {
        if (!check_file_name(p, w[3])) return false;
        t.source = TextureSource::File;
        copy_name(t.file, sizeof t.file, w[3]);
        const uint8_t* data = nullptr;
        size_t size = 0;
        if (!p.files->find || !p.files->find(p.files->context, w[3], &data, &size))
            return p.fail(Fmt().s("texture '").s(w[1]).s("': no file '").s(w[3]).s("'"));
        IndexedImage image;
        Fmt why;
        if (!decode_indexed_image(data, size, &image, world.texels + t.offset, room, &why))
            return p.fail(Fmt().s("texture '").s(w[1]).s("' (").s(w[3]).s("): ").s(why.c_str()));
        t.width = image.width, t.height = image.height;
        if (tiled) {
            int32_t width, height;
            if (!parse_int(w[5], 1, MAX_TEXTURE_SIZE, &width) || !parse_int(w[6], 1, MAX_TEXTURE_SIZE, &height))
                return p.fail(Fmt().s("tile size '").s(w[5]).s(" ").s(w[6]).s("' out of range: width and height 1..1024"));
            if (width % t.width != 0 || height % t.height != 0)
                return p.fail(Fmt().s("texture '").s(w[1]).s("': tile ").u(uint32_t(width)).s(" x ").u(uint32_t(height))
                                  .s(" is not whole copies of its ").u(uint32_t(t.width)).s(" x ").u(uint32_t(t.height)).s(" image"));
            if (size_t(width) * size_t(height) > room) return too_many_texels(p);
            tile_in_place(world.texels + t.offset, t.width, t.height, width, height);
            t.width = width, t.height = height;
        }
        for (int i = 0; i < 256; ++i)
            source.entry[i] = Rgb6{uint8_t(image.palette[i][0] >> 2), uint8_t(image.palette[i][1] >> 2), uint8_t(image.palette[i][2] >> 2)};
    } else {
        if (!texture_kind_from_name(w[2], &t.kind))
            return p.fail(Fmt().s("unknown texture kind '").s(w[2]).s("' (checker, grid, numbered, xor, gradient, or file)"));
        if (!parse_int(w[3], 1, MAX_TEXTURE_SIZE, &t.width) || !parse_int(w[4], 1, MAX_TEXTURE_SIZE, &t.height))
            return p.fail(Fmt().s("texture size '").s(w[3]).s(" ").s(w[4]).s("' out of range: width and height 1..1024"));
        if (size_t(t.width) * size_t(t.height) > room) return too_many_texels(p);
        generate_texture(t.kind, t.width, t.height, world.texels + t.offset);
        source = raster::palette(PaletteId::Default);
    }
    world.texel_count += uint32_t(t.width) * uint32_t(t.height);
    ++world.texture_count;
    return true;
}

// f A/a B/b ...: 1-based indices into the mesh's v and vt lists so far
bool face_line(Parser& p, const StrView* w, size_t n) {
    World& world = *p.world;
    Mesh& m = world.meshes[world.mesh_count];
    size_t corners = n - 1;
    if (corners < 3 || corners > size_t(MAX_FACE_CORNERS)) return p.fail(Fmt().s("a face has 3 to 10 corners, each POSITION/TEXCOORD"));
    if (world.face_count == world.room.faces) return p.fail(Fmt().s("too many faces (at most ").u(uint32_t(world.room.faces)).s(")"));
    if (world.corner_count + int32_t(corners) > world.room.corners)
        return p.fail(Fmt().s("too many face corners (at most ").u(uint32_t(world.room.corners)).s(")"));
    for (size_t k = 0; k < corners; ++k) {
        StrView c = w[1 + k];
        size_t slash = 0;
        while (slash < c.size && c.data[slash] != '/') ++slash;
        int32_t v = 0, t = 0;
        if (slash == c.size || !parse_int(StrView{c.data, slash}, 1, m.position_count, &v) ||
            !parse_int(c.drop(slash + 1), 1, m.uv_count, &t))
            return p.fail(Fmt().s("bad corner '").s(c).s("': POSITION/TEXCOORD, 1-based indices of this mesh's v (1..")
                              .u(uint32_t(m.position_count)).s(") and vt (1..").u(uint32_t(m.uv_count)).s(") lines so far"));
        world.corners[world.corner_count + int32_t(k)] = Corner{m.first_position + v - 1, m.first_uv + t - 1};
    }
    world.faces[world.face_count++] = Face{world.corner_count, int32_t(corners), Vec3{}, 0};  // (its plane: measure_mesh)
    world.corner_count += int32_t(corners);
    ++m.face_count;
    return true;
}

bool mesh_line(Parser& p, const StrView* w, size_t n) {
    World& world = *p.world;
    Mesh& m = world.meshes[world.mesh_count];
    if (w[0].equals("v")) {
        if (!usage(p, n, 4, "v X Y Z")) return false;
        if (world.position_count == world.room.positions) return p.fail(Fmt().s("too many positions (at most ").u(uint32_t(world.room.positions)).s(")"));
        if (!vec3(p, w + 1, "a position", &world.positions[world.position_count])) return false;
        ++world.position_count, ++m.position_count;
        return true;
    }
    if (w[0].equals("vt")) {
        if (!usage(p, n, 3, "vt U V (in texture sizes, v down)")) return false;
        if (world.uv_count == world.room.uvs) return p.fail(Fmt().s("too many texture coordinates (at most ").u(uint32_t(world.room.uvs)).s(")"));
        TexCoord& t = world.uvs[world.uv_count];
        if (!number(p, w[1], "u", -MAX_TEXCOORD, MAX_TEXCOORD, &t.u) || !number(p, w[2], "v", -MAX_TEXCOORD, MAX_TEXCOORD, &t.v)) return false;
        ++world.uv_count, ++m.uv_count;
        return true;
    }
    if (w[0].equals("f")) return face_line(p, w, n);
    return p.fail(Fmt().s("unknown line '").s(w[0]).s("' in a mesh (v, vt, f, end)"));
}

bool axis_angle(Parser& p, const StrView* w, const char* what, double limit, Vec3* axis, double* angle) {
    if (!vec3(p, w, "an axis", axis)) return false;
    if (axis->x == 0 && axis->y == 0 && axis->z == 0) return p.fail(Fmt().s("the axis must not be 0 0 0"));
    return number(p, w[3], what, -limit, limit, angle);
}

// Between two keys of the camera's path the eye and the target move linearly (frame.cpp, on_path),
// and so does the side vector cross(target - eye, up), which is zero where the camera looks nowhere
// (eye on target, or view along up). False where it comes within a billionth of its larger end's
// length of zero on the way.
bool aimed_between(const PathKey& k0, const PathKey& k1, Vec3 up) {
    const Vec3 a = cross(k0.target - k0.position, up), b = cross(k1.target - k1.position, up) - a;
    const double bb = dot(b, b);
    if (bb == 0) return true;  // the same side vector all the way: the keys' own check
    double s = -dot(a, b) / bb;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    const Vec3 nearest = a + s * b, end = a + b;
    const double larger = dot(a, a) > dot(end, end) ? dot(a, a) : dot(end, end);
    return dot(nearest, nearest) > 1e-18 * larger;
}

bool path_key(Parser& p, int32_t* count, PathKey* keys, double time) {
    if (*count == MAX_PATH_KEYS) return p.fail(Fmt().s("too many path keys (at most 32)"));
    if (*count > 0 && !(time > keys[*count - 1].time)) return p.fail(Fmt().s("path key times must increase"));
    keys[*count].time = time;
    return true;
}

bool object_line(Parser& p, const StrView* w, size_t n) {
    World& world = *p.world;
    Object& o = world.objects[world.object_count];
    if (w[0].equals("mesh")) {
        if (!usage(p, n, 2, "mesh NAME")) return false;
        o.mesh = find_mesh(world, w[1]);
        if (o.mesh < 0) return p.fail(Fmt().s("no mesh named '").s(w[1]).s("' (meshes come before the objects using them)"));
        return true;
    }
    if (w[0].equals("texture")) {
        if (!usage(p, n, 2, "texture NAME")) return false;
        o.texture = find_texture(world, w[1]);
        if (o.texture < 0) return p.fail(Fmt().s("no texture named '").s(w[1]).s("'"));
        return true;
    }
    if (w[0].equals("wrap")) {
        if (n != 2 || !wrap_from_name(w[1], &o.wrap)) return p.fail(Fmt().s("usage: wrap repeat|clamp"));
        return true;
    }
    if (w[0].equals("cull")) {
        if (n != 2 || !(w[1].equals("back") || w[1].equals("none"))) return p.fail(Fmt().s("usage: cull back|none"));
        o.cull = w[1].equals("back") ? Cull::Back : Cull::None;
        return true;
    }
    if (w[0].equals("position")) return usage(p, n, 4, "position X Y Z") && vec3(p, w + 1, "a position", &o.position);
    if (w[0].equals("rotate")) return usage(p, n, 5, "rotate AXIS_X AXIS_Y AXIS_Z DEGREES") && axis_angle(p, w + 1, "degrees", 1e6, &o.rotate_axis, &o.rotate_degrees);
    if (w[0].equals("scale")) return usage(p, n, 2, "scale S") && number(p, w[1], "scale", 1e-6, MAX_WORLD_COORD, &o.scale);
    if (w[0].equals("spin"))
        return usage(p, n, 5, "spin AXIS_X AXIS_Y AXIS_Z DEGREES_PER_SECOND") && axis_angle(p, w + 1, "degrees per second", 1e6, &o.spin_axis, &o.spin_degrees_per_second);
    if (w[0].equals("key")) {
        double t;
        if (!usage(p, n, 5, "key TIME X Y Z") || !number(p, w[1], "time", 0, 1e6, &t) || !path_key(p, &o.key_count, o.keys, t)) return false;
        return vec3(p, w + 2, "a position", &o.keys[o.key_count++].position);
    }
    return p.fail(Fmt().s("unknown line '").s(w[0]).s("' in an object (mesh, texture, wrap, cull, position, rotate, scale, spin, key, end)"));
}

bool camera_line(Parser& p, const StrView* w, size_t n) {
    Camera& c = p.world->camera;
    if (w[0].equals("position")) return usage(p, n, 4, "position X Y Z") && vec3(p, w + 1, "a position", &c.position);
    if (w[0].equals("target")) return usage(p, n, 4, "target X Y Z") && vec3(p, w + 1, "a target", &c.target);
    if (w[0].equals("up")) return usage(p, n, 4, "up X Y Z") && vec3(p, w + 1, "an up vector", &c.up);
    if (w[0].equals("fov")) return usage(p, n, 2, "fov DEGREES (vertical, 1..170)") && number(p, w[1], "fov", 1, 170, &c.fov_degrees);
    if (w[0].equals("near")) return usage(p, n, 2, "near DISTANCE") && number(p, w[1], "near", MIN_W, MAX_W, &c.near);
    if (w[0].equals("far")) return usage(p, n, 2, "far DISTANCE") && number(p, w[1], "far", MIN_W, MAX_W, &c.far);
    if (w[0].equals("key")) {
        double t;
        if (!usage(p, n, 8, "key TIME X Y Z TARGET_X TARGET_Y TARGET_Z") || !number(p, w[1], "time", 0, 1e6, &t) || !path_key(p, &c.key_count, c.keys, t))
            return false;
        PathKey& k = c.keys[c.key_count];
        if (!vec3(p, w + 2, "a position", &k.position) || !vec3(p, w + 5, "a target", &k.target)) return false;
        ++c.key_count;
        return true;
    }
    return p.fail(Fmt().s("unknown line '").s(w[0]).s("' in the camera (position, target, up, fov, near, far, key, end)"));
}

// The mesh's measures for the envelope (Mesh): over its triangles, and its positions; and each
// face's plane (Face).
void measure_mesh(World& world, Mesh* m) {
    m->measured = true;
    for (int32_t k = 0; k < m->face_count; ++k) {
        Face& face = world.faces[m->first_face + k];
        const Corner* c = world.corners + face.first_corner;
        Vec3 n;
        for (int32_t i = 0; i < face.count; ++i) {
            const Vec3 a = world.positions[c[i].position], b = world.positions[c[i + 1 < face.count ? i + 1 : 0].position];
            n.x += (a.y - b.y) * (a.z + b.z), n.y += (a.z - b.z) * (a.x + b.x), n.z += (a.x - b.x) * (a.y + b.y);
        }
        face.normal = n;
        face.offset = dot(n, world.positions[c[0].position]);
    }
    for (int32_t i = 0; i < m->position_count; ++i) m->radius = larger(m->radius, length(world.positions[m->first_position + i]));
    for (int32_t i = 0; i < m->uv_count; ++i) {
        const TexCoord t = world.uvs[m->first_uv + i];
        m->uv_abs[0] = larger(m->uv_abs[0], magnitude(t.u)), m->uv_abs[1] = larger(m->uv_abs[1], magnitude(t.v));
    }
    for (int32_t k = 0; k < m->face_count; ++k) {
        const Face& face = world.faces[m->first_face + k];
        if (face.count != 3) continue;
        const Corner* c = world.corners + face.first_corner;
        for (int i = 0; i < 3; ++i) {
            const Corner &a = c[i], &b = c[i == 2 ? 0 : i + 1];
            m->triangle_edge = larger(m->triangle_edge, length(world.positions[a.position] - world.positions[b.position]));
            const TexCoord ta = world.uvs[a.uv], tb = world.uvs[b.uv];
            m->triangle_uv_range[0] = larger(m->triangle_uv_range[0], magnitude(ta.u - tb.u));
            m->triangle_uv_range[1] = larger(m->triangle_uv_range[1], magnitude(ta.v - tb.v));
            m->triangle_uv_abs[0] = larger(m->triangle_uv_abs[0], magnitude(ta.u));
            m->triangle_uv_abs[1] = larger(m->triangle_uv_abs[1], magnitude(ta.v));
        }
    }
}

// Checks a block once its 'end' is read.
bool end_block(Parser& p) {
    World& world = *p.world;
    if (p.block == Block::Mesh) {
        if (world.meshes[world.mesh_count].face_count == 0) return p.fail(Fmt().s("mesh '").s(world.meshes[world.mesh_count].name).s("' has no faces"));
        measure_mesh(world, &world.meshes[world.mesh_count]);
        ++world.mesh_count;
    } else if (p.block == Block::Object) {
        const Object& o = world.objects[world.object_count];
        if (o.mesh < 0) return p.fail(Fmt().s("object '").s(o.name).s("' has no mesh"));
        if (o.texture < 0) return p.fail(Fmt().s("object '").s(o.name).s("' has no texture"));
        ++world.object_count;
    } else {
        const Camera& c = world.camera;
        if (!(c.near < c.far)) return p.fail(Fmt().s("the camera's near distance must be below its far distance"));
        auto aimed = [&](Vec3 eye, Vec3 target) {
            Vec3 f = target - eye;
            Vec3 side = cross(f, c.up);
            return (f.x != 0 || f.y != 0 || f.z != 0) && (side.x != 0 || side.y != 0 || side.z != 0);
        };
        bool ok = c.key_count > 0 || aimed(c.position, c.target);
        for (int32_t i = 0; i < c.key_count; ++i) ok = ok && aimed(c.keys[i].position, c.keys[i].target);
        if (!ok) return p.fail(Fmt().s("the camera must look somewhere: target apart from its position, up not along the view"));
        for (int32_t i = 1; i < c.key_count; ++i)
            if (!aimed_between(c.keys[i - 1], c.keys[i], c.up))
                return p.fail(Fmt().s("the camera must look somewhere between its keys too: from ").decimal(c.keys[i - 1].time).s(" s to ")
                                  .decimal(c.keys[i].time).s(" s its target meets its position, or the view turns along up"));
        p.have_camera = true;
    }
    p.block = Block::None;
    return true;
}

bool begin_block(Parser& p, const StrView* w, size_t n) {
    World& world = *p.world;
    if (w[0].equals("mesh")) {
        if (!usage(p, n, 2, "mesh NAME, then v, vt and f lines, then end") || !check_name(p, w[1], "mesh")) return false;
        if (find_mesh(world, w[1]) >= 0) return p.fail(Fmt().s("a second mesh named '").s(w[1]).s("'"));
        if (world.mesh_count == MAX_WORLD_MESHES) return p.fail(Fmt().s("too many meshes (at most 16)"));
        Mesh& m = world.meshes[world.mesh_count];
        m = Mesh{};
        copy_name(m.name, sizeof m.name, w[1]);
        m.first_position = world.position_count, m.first_uv = world.uv_count, m.first_face = world.face_count;
        p.block = Block::Mesh;
    } else if (w[0].equals("object")) {
        if (!usage(p, n, 2, "object NAME, then its lines, then end") || !check_name(p, w[1], "object")) return false;
        for (int32_t i = 0; i < world.object_count; ++i)
            if (name_is(world.objects[i].name, w[1])) return p.fail(Fmt().s("a second object named '").s(w[1]).s("'"));
        if (world.object_count == MAX_WORLD_OBJECTS) return p.fail(Fmt().s("too many objects (at most 64)"));
        Object& o = world.objects[world.object_count];
        o = Object{};
        copy_name(o.name, sizeof o.name, w[1]);
        p.block = Block::Object;
    } else {
        if (!usage(p, n, 1, "camera, then its lines, then end")) return false;
        if (p.have_camera) return p.fail(Fmt().s("a second camera"));
        p.block = Block::Camera;
    }
    p.block_line = p.line;
    return true;
}

bool top_line(Parser& p, const StrView* w, size_t n) {
    World& world = *p.world;
    if (w[0].equals("texture")) return texture_line(p, w, n);
    if (w[0].equals("mesh") || w[0].equals("object") || w[0].equals("camera")) return begin_block(p, w, n);
    if (w[0].equals("palette")) {
        if (!usage(p, n, 2, "palette default|TEXTURE")) return false;
        if (p.have_palette) return p.fail(Fmt().s("a second palette line"));
        p.have_palette = true;
        if (w[1].equals("default")) return true;
        world.palette_texture = find_texture(world, w[1]);
        if (world.palette_texture < 0) return p.fail(Fmt().s("no texture named '").s(w[1]).s("' (textures come before the palette line)"));
        if (world.textures[world.palette_texture].source != TextureSource::File)
            return p.fail(Fmt().s("texture '").s(w[1]).s("' is procedural: the palette comes from an image file"));
        return true;
    }
    if (w[0].equals("budget")) {
        // budget max-error N|any coverage exact|any [target icount|486|pentium]
        if ((n != 5 && n != 7) || !w[1].equals("max-error") || !w[3].equals("coverage") || !(w[4].equals("exact") || w[4].equals("any")) ||
            (n == 7 && !w[5].equals("target")))
            return p.fail(Fmt().s("usage: budget max-error N|any coverage exact|any [target icount|486|pentium]"));
        Budget& b = world.budget;
        if (b.given) return p.fail(Fmt().s("a second budget line"));
        if (n == 7 && !cost_target_named(w[6].data, w[6].size, &b.target))
            return p.fail(Fmt().s("bad target '").s(w[6]).s("' (icount, 486 or pentium: the machine auto is to be cheapest on)"));
        b.given = true;
        b.exact_coverage = w[4].equals("exact");
        if (w[2].equals("any")) b.max_error = ANY_ERROR;
        else if (!parse_decimal(w[2], &b.max_error) || !(b.max_error >= 0 && b.max_error <= 1e6))
            return p.fail(Fmt().s("bad max-error '").s(w[2]).s("' (a footprint error 0..1000000, or any)"));
        return true;
    }
    if (w[0].equals("frames")) {
        if (p.have_frames) return p.fail(Fmt().s("a second frames line"));
        if (n != 2 || !parse_int(w[1], 1, MAX_FRAMES, &world.frames)) return p.fail(Fmt().s("usage: frames N (1..1048576: the animation's length)"));
        p.have_frames = true;
        return true;
    }
    return p.fail(Fmt().s("unknown keyword '").s(w[0]).s("'"));
}

}  // namespace

bool world_name_ok(StrView w) {
    bool ok = w.size >= 1 && w.size < size_t(MAX_WORLD_NAME);
    for (size_t i = 0; ok && i < w.size; ++i) {
        char c = w.data[i];
        ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
    }
    return ok;
}

bool parse_world(const char* text, size_t length, const FileResolver& files, World* world, ParseError* error) {
    world->texture_count = world->mesh_count = world->object_count = 0;
    world->texel_count = 0;
    world->position_count = world->uv_count = world->face_count = world->corner_count = 0;
    world->palette_texture = -1;
    world->camera = Camera{};
    world->budget = Budget{};
    world->frames = 150;
    Parser p;  // 12 KiB of source palettes: on the stack (256 KiB in the kernel), so no state outlives the call
    p.world = world, p.files = &files, p.error = error;
    *error = ParseError{};
    if (length > MAX_WORLD_BYTES) return scene_text::fail(error, 0, "file too large (at most 4194304 bytes)");
    scene_text::Lines lines(text, length);
    char buf[scene_text::MAX_LINE + 1];
    int version = scene_text::read_header(lines, buf, error);
    if (version == 0) return false;
    if (version != 2) return scene_text::fail(error, lines.line, "a version 1 (screen-space) scene, not a 3D one");
    bool ok = scene_text::each_line(lines, buf, error, [&](char* line) {
        p.line = lines.line;
        StrView w[MAX_LINE_WORDS];
        size_t n = lib::split_words(line, w, MAX_LINE_WORDS);
        if (n > size_t(MAX_LINE_WORDS)) return p.fail(Fmt().s("too many words on one line"));
        if (p.block != Block::None && w[0].equals("end")) return usage(p, n, 1, "end") && end_block(p);
        if (p.block == Block::Mesh) return mesh_line(p, w, n);
        if (p.block == Block::Object) return object_line(p, w, n);
        if (p.block == Block::Camera) return camera_line(p, w, n);
        return top_line(p, w, n);
    });
    if (!ok) return false;
    if (p.block != Block::None) {
        p.line = p.block_line;
        return p.fail(Fmt().s("this block has no 'end'"));
    }
    if (world->object_count == 0) return scene_text::fail(error, 0, "no objects: nothing to draw");
    if (!p.have_camera) return scene_text::fail(error, 0, "no camera block");

    // every texture in the scene's palette
    world->palette = world->palette_texture >= 0 ? p.sources[world->palette_texture] : palette(PaletteId::Default);
    for (int32_t i = 0; i < world->texture_count; ++i) {
        uint8_t map[256];
        for (int32_t k = 0; k < 256; ++k) map[k] = nearest_entry(world->palette, p.sources[i].entry[k]);
        const WorldTexture& t = world->textures[i];
        uint8_t* texel = world->texels + t.offset;
        for (uint32_t k = 0; k < uint32_t(t.width) * uint32_t(t.height); ++k) texel[k] = map[texel[k]];
    }
    return true;
}

WorldRoom world_room(const char* text, size_t length, const FileResolver& files) {
    WorldRoom need;
    uint64_t texels = 0;
    int64_t positions = 0, uvs = 0, faces = 0, corners = 0;
    if (length <= MAX_WORLD_BYTES) {
        scene_text::Lines lines(text, length);
        char buf[scene_text::MAX_LINE + 1];
        const char* bad = nullptr;
        while (lines.next(buf, &bad)) {
            StrView w[MAX_LINE_WORDS];
            const size_t n = lib::split_words(buf, w, MAX_LINE_WORDS);
            if (n == 0) continue;
            if (w[0].equals("v")) ++positions;
            else if (w[0].equals("vt")) ++uvs;
            else if (w[0].equals("f")) ++faces, corners += int64_t(n > size_t(MAX_LINE_WORDS) ? MAX_LINE_WORDS : n) - 1;
            else if (w[0].equals("texture") && n >= 5) {
                int32_t width = 0, height = 0;  // as the parser reads them: a size out of range is refused there
                const bool file = w[2].equals("file"), tiled = file && n == 7;
                const StrView* size = tiled ? w + 5 : file ? nullptr : w + 3;
                if (size) {
                    if (!parse_int(size[0], 1, MAX_TEXTURE_SIZE, &width) || !parse_int(size[1], 1, MAX_TEXTURE_SIZE, &height)) width = height = 0;
                }
                texels += uint64_t(width) * uint64_t(height);
            } else if (w[0].equals("texture") && n == 4 && w[2].equals("file")) {
                const uint8_t* data = nullptr;
                size_t bytes = 0;
                int32_t width = 0, height = 0;
                if (files.find && files.find(files.context, w[3], &data, &bytes) && indexed_image_size(data, bytes, &width, &height))
                    texels += uint64_t(width) * uint64_t(height);
            }
        }
    }
    const WorldRoom most = WorldRoom::limits();
    auto at_most = [](int64_t n, int32_t limit) { return int32_t(n < limit ? n : limit); };
    need.texels = uint32_t(texels < most.texels ? texels : most.texels);
    need.positions = at_most(positions, most.positions), need.uvs = at_most(uvs, most.uvs);
    need.faces = at_most(faces, most.faces), need.corners = at_most(corners, most.corners);
    return need;
}

}  // namespace raster
