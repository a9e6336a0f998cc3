// Fuzz target `scene`: scene files of either version, as a client uploads them (`scene`, `file`,
// `load`) and the host tools read them. Promises: an error has a message and names a line of the
// text (or 0, the whole file); a version 2 scene that parses is drawn (frame and mapper picked by
// the input's last bytes) into a surface with guard bytes around it, none of which changes.
// Texture files the scene names are served from memory: a small BMP for names ending in .bmp,
// a PCX for .pcx, nothing for others.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "kernel/core/policy.h"
#include "kernel/scene/frame.h"
#include "kernel/scene/scene.h"
#include "kernel/scene/world.h"
#include "tests/fuzz/fuzz.h"
#include "tests/unit/kernel/scene/texture_files.h"

namespace {

using namespace raster;

struct Files {
    std::vector<uint8_t> bmp, pcx;
    Files() {
        const texfiles::Picture p = texfiles::random_picture(16, 8, 7);
        bmp = texfiles::encode_bmp(p, texfiles::BmpKind::Rle8);
        pcx = texfiles::encode_pcx(texfiles::random_picture(8, 8, 9));
    }
};

bool find_file(const void* context, lib::StrView name, const uint8_t** data, size_t* size) {
    const Files& f = *static_cast<const Files*>(context);
    const std::vector<uint8_t>* file = name.size >= 4 && std::string(name.data + name.size - 4, 4) == ".bmp" ? &f.bmp
                                       : name.size >= 4 && std::string(name.data + name.size - 4, 4) == ".pcx" ? &f.pcx
                                                                                                               : nullptr;
    if (!file) return false;
    *data = file->data();
    *size = file->size();
    return true;
}

int32_t line_count(const uint8_t* data, size_t size) { return int32_t(std::count(data, data + size, uint8_t('\n'))) + 1; }

void check_error(const ParseError& e, const uint8_t* data, size_t size, const char* what) {
    if (!e.message[0]) fuzz::fail(std::string(what) + ": refused without a message");
    if (e.line < 0 || e.line > line_count(data, size))
        fuzz::fail(std::string(what) + ": error names line " + std::to_string(e.line) + " of " + std::to_string(line_count(data, size)) + ": " + e.message);
}

constexpr uint8_t GUARD = 0x5A;
constexpr size_t GUARD_BYTES = 4096;

// Frame `frame` of the world with the mapper, into a RAM surface between guard bytes.
void draw(const World& world, int32_t frame, const Mapper& mapper) {
    static auto scratch = std::make_unique<HostFrameScratch>();
    static auto textures = std::make_unique<HostTextureSet>();
    static auto out = std::make_unique<HostFrame>();
    build_frame(world, frame, out.get(), scratch.get());
    build_texture_set(world, textures.get());
    const Axis axis = home_axis(mapper);
    std::vector<uint8_t> bytes(SCREEN_PIXELS + 2 * GUARD_BYTES, GUARD);
    Target target = ram_target(bytes.data() + GUARD_BYTES, ram_planar(mapper, axis));
    render_frame(*out, *textures, mapper, axis, target);
    for (size_t i = 0; i < GUARD_BYTES; ++i)
        if (bytes[i] != GUARD || bytes[bytes.size() - 1 - i] != GUARD)
            fuzz::fail(std::string(mapper.name) + " wrote outside the surface on frame " + std::to_string(frame));
}

}  // namespace

MODEXLAB_FUZZ_TARGET(scene) {
    static const Files files;
    static auto scene = std::make_unique<Scene>();
    static auto world = std::make_unique<HostWorld>();
    const char* text = reinterpret_cast<const char*>(data);
    ParseError e;
    const int version = scene_version(text, size, &e);
    if (version == 0) {
        check_error(e, data, size, "scene_version");
        return 0;
    }
    if (version == 1) {
        if (!parse_scene(text, size, scene.get(), &e)) check_error(e, data, size, "parse_scene");
        else if (scene->polygon_count < 0 || scene->polygon_count > MAX_SCENE_POLYGONS) fuzz::fail("parse_scene: polygon count out of range");
        return 0;
    }
    const FileResolver resolver{&files, find_file};
    if (!parse_world(text, size, resolver, world.get(), &e)) {
        check_error(e, data, size, "parse_world");
        return 0;
    }
    const uint8_t pick = size ? data[size - 1] : 0;
    draw(*world, int32_t(pick % 16) * 9, MAPPERS[pick % MAPPER_COUNT]);
    return 0;
}
