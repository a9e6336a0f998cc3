// 3D scenes (scene format version 2, docs/scene-format.md): textures (procedural or BMP/PCX files),
// one palette, meshes, objects with transforms and animation, a camera, an accuracy budget. Parsed
// by the same code in the kernel and on the host; files the scene names come from a resolver
// (the host's file system, the kernel's modules, uploads and built-ins).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/lib/words.h"
#include "kernel/scene/math3d.h"
#include "kernel/scene/palette.h"
#include "kernel/scene/scene.h"
#include "kernel/core/budget.h"
#include "kernel/core/texture.h"

namespace raster {

// Limits (docs/scene-format.md); the parser refuses a scene beyond any of them with a message.
constexpr int32_t MAX_WORLD_TEXTURES = 16;
constexpr int32_t MAX_TEXEL_POOL = 4 << 20;  // bytes of texels, all textures together
constexpr int32_t MAX_WORLD_MESHES = 16;
constexpr int32_t MAX_WORLD_POSITIONS = 32768;
constexpr int32_t MAX_WORLD_UVS = 32768;
constexpr int32_t MAX_WORLD_FACES = 32768;
constexpr int32_t MAX_WORLD_CORNERS = 131072;
constexpr int32_t MAX_FACE_CORNERS = 10;  // clipping against six planes adds at most six: setup takes 16
constexpr int32_t MAX_WORLD_OBJECTS = 64;
constexpr int32_t MAX_PATH_KEYS = 32;
constexpr int32_t MAX_WORLD_NAME = 32;  // names of textures, meshes, objects (with the NUL)
constexpr int32_t MAX_FILE_NAME = 64;   // file names (with the NUL)
constexpr double MAX_WORLD_COORD = 1e6;  // positions, path points, scales
constexpr double MAX_TEXCOORD = 16384;   // vt, in texture sizes
constexpr int32_t FRAMES_PER_SECOND = 30;  // frame n shows time n / 30 s: kernel and host agree on frames
constexpr int32_t MAX_FRAMES = 1 << 20;

enum class TextureSource : uint8_t { Procedural, File };

struct WorldTexture {
    char name[MAX_WORLD_NAME] = {};
    TextureSource source = TextureSource::Procedural;
    TextureKind kind = TextureKind::Checker;  // procedural
    char file[MAX_FILE_NAME] = {};            // file
    int32_t width = 0, height = 0;
    uint32_t offset = 0;  // first texel in World::texels
};

struct Mesh {
    char name[MAX_WORLD_NAME] = {};
    int32_t first_position = 0, position_count = 0;
    int32_t first_uv = 0, uv_count = 0;
    int32_t first_face = 0, face_count = 0;
    // Measured once it is read, over its triangles (the envelope, frame.h): the longest edge, the
    // largest range and magnitude of u and v at their corners (texture sizes); and the largest
    // |position| of the mesh.
    bool measured = false;  // (a mesh not measured has no envelope)
    double triangle_edge = 0;
    double triangle_uv_range[2] = {0, 0}, triangle_uv_abs[2] = {0, 0};
    double radius = 0;
    double uv_abs[2] = {0, 0};  // the largest |u| and |v| of all its texture coordinates (auto's oriented path)
};

// A convex planar face: `count` corners from `first_corner` on, counter-clockwise seen from its
// front (right-handed, the OBJ convention). Its plane in its mesh's coordinates, measured once the
// mesh is read (measure_mesh): `normal` (Newell's, toward the front; not unit) and `offset`, the
// normal's product with the first corner: a point p lies in front where dot(normal, p) > offset.
struct Face {
    int32_t first_corner = 0;
    int32_t count = 0;
    Vec3 normal;
    double offset = 0;
};

struct Corner {
    int32_t position = 0, uv = 0;  // indices into World::positions and World::uvs
};

struct TexCoord {
    double u = 0, v = 0;  // in texture sizes: (1, 1) is the far corner; v grows downward (rows)
};

// A path key: at `time` seconds, the position (objects), or the camera's position and target.
struct PathKey {
    double time = 0;
    Vec3 position, target;
};

enum class Cull : uint8_t { Back, None };

struct Object {
    char name[MAX_WORLD_NAME] = {};
    int32_t mesh = -1, texture = -1;
    Wrap wrap = Wrap::Repeat;
    Cull cull = Cull::Back;
    Vec3 position;                 // where the path is not given
    Vec3 rotate_axis{0, 1, 0};     // a fixed rotation
    double rotate_degrees = 0;
    double scale = 1;
    Vec3 spin_axis{0, 1, 0};       // and a rotation growing with time, applied after it
    double spin_degrees_per_second = 0;
    int32_t key_count = 0;         // a looping path of positions, linear between keys
    PathKey keys[MAX_PATH_KEYS];
};

struct Camera {
    Vec3 position{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};
    double fov_degrees = 60;  // vertical
    double near = 0.1, far = 1000;
    int32_t key_count = 0;    // a looping path of positions and targets
    PathKey keys[MAX_PATH_KEYS];
};

// The room for a world's variable parts: the texels of all its textures, its positions, texture
// coordinates, faces and their corners. The kernel sizes it to the scene at hand (world_room); the
// host's worlds have the limits above (HostWorld).
struct WorldRoom {
    uint32_t texels = 0;
    int32_t positions = 0, uvs = 0, faces = 0, corners = 0;
    static WorldRoom limits() { return WorldRoom{uint32_t(MAX_TEXEL_POOL), MAX_WORLD_POSITIONS, MAX_WORLD_UVS, MAX_WORLD_FACES, MAX_WORLD_CORNERS}; }
};

struct World {
    int32_t texture_count = 0;
    WorldTexture textures[MAX_WORLD_TEXTURES];
    uint32_t texel_count = 0;  // used in `texels`
    int32_t palette_texture = -1;  // the palette: the default one, or that image texture's
    Palette palette;               // remapped textures index it

    int32_t mesh_count = 0;
    Mesh meshes[MAX_WORLD_MESHES];
    int32_t position_count = 0, uv_count = 0, face_count = 0, corner_count = 0;

    int32_t object_count = 0;
    Object objects[MAX_WORLD_OBJECTS];
    Camera camera;
    Budget budget;  // its budget line, or the default
    int32_t frames = 150;  // the animation's length: the demo plays frames 0..frames-1 and loops

    // The variable parts, `room` of each, where the owner puts them (the parser fills them).
    WorldRoom room;
    uint8_t* texels = nullptr;
    Vec3* positions = nullptr;
    TexCoord* uvs = nullptr;
    Face* faces = nullptr;
    Corner* corners = nullptr;

    World() = default;
    World(const World&) = delete;  // (a copy would share the parts)
    World& operator=(const World&) = delete;

    // texture i as the mappers see it for object `o` (its wrap), without the derived copies
    Texture texture_of(int32_t object) const {
        const WorldTexture& t = textures[objects[object].texture];
        return Texture{texels + t.offset, t.width, t.height, objects[object].wrap};
    }
};

#if __STDC_HOSTED__
// A world with room up to the limits.
struct HostWorld : World {
    uint8_t texel_pool[MAX_TEXEL_POOL];
    Vec3 position_pool[MAX_WORLD_POSITIONS];
    TexCoord uv_pool[MAX_WORLD_UVS];
    Face face_pool[MAX_WORLD_FACES];
    Corner corner_pool[MAX_WORLD_CORNERS];
    HostWorld() {
        room = WorldRoom::limits();
        texels = texel_pool, positions = position_pool, uvs = uv_pool, faces = face_pool, corners = corner_pool;
    }
};
#endif

// Where the files a scene names come from. `find` returns false when there is no such file.
struct FileResolver {
    const void* context = nullptr;
    bool (*find)(const void* context, lib::StrView name, const uint8_t** data, size_t* size) = nullptr;
};

// The names of textures, meshes and objects.
constexpr const char* WORLD_NAME_RULE = "1 to 31 letters, digits, '-', '_', '.'";
bool world_name_ok(lib::StrView name);

// Parses a version 2 scene into `world` (which it overwrites; on failure it holds nothing usable),
// reading the texture files it names through `files`, remapping every texture to the scene's
// palette. False with the first error (its line; 0 when it is about the whole file).
bool parse_world(const char* text, size_t length, const FileResolver& files, World* world, ParseError* error);

// The room parse_world needs for this text (each part at most its limit): its v, vt and f lines,
// the corners on its f lines, and the texels of its texture lines (a file's size from its header,
// through `files`). Exact for a scene that parses; a text that does not may get less than its
// lines ask for, and fails to parse all the same.
WorldRoom world_room(const char* text, size_t length, const FileResolver& files);

// The scene's time at frame n, in seconds.
inline double frame_time(int32_t frame) { return double(frame) / FRAMES_PER_SECOND; }

}  // namespace raster
