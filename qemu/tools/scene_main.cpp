// modexlab-scene: checks scene files, makes the demo scenes, converts Wavefront OBJ meshes.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "kernel/scene/world.h"
#include "qemu/tools/demo_scenes.h"
#include "qemu/lib/error.h"
#include "qemu/accuracy/measure.h"

namespace {

using namespace harness;

const char* USAGE =
    "usage: modexlab-scene check FILE...        parse scene files (version 1 or 2), print what each holds\n"
    "       modexlab-scene make NAME|all [DIR]   print a demo scene, or write DIR/NAME.scene (all: every one)\n"
    "       modexlab-scene list                  the demo scenes and what each exercises\n"
    "       modexlab-scene obj FILE.obj NAME     a mesh block (v, vt, f) from a Wavefront OBJ file\n";

[[noreturn]] void usage_error(const std::string& why) {
    std::fprintf(stderr, "modexlab-scene: %s\n%s", why.c_str(), USAGE);
    std::exit(2);
}

int check(const std::vector<std::string>& paths) {
    int failed = 0;
    for (const std::string& path : paths) {
        try {
            std::string text = read_whole_file(path);
            raster::ParseError e;
            int version = raster::scene_version(text.data(), text.size(), &e);
            if (version == 1) {
                LoadedScene s = parse_scene_text(text, path);
                std::printf("%s: version 1, %d polygons, texture %s %dx%d\n", path.c_str(), s.scene->polygon_count,
                            raster::texture_kind_name(s.scene->texture_kind), s.texture.width, s.texture.height);
            } else if (version == 2) {
                LoadedWorld w = parse_world_text(text, path, world_search_path(path));
                const raster::World& d = *w.world;
                std::printf("%s: version 2, %d textures, %d meshes, %d faces, %d objects, %d frames, palette %s\n", path.c_str(),
                            d.texture_count, d.mesh_count, d.face_count, d.object_count, d.frames,
                            d.palette_texture >= 0 ? d.textures[d.palette_texture].name : "default");
            } else {
                throw HarnessError(path + (e.line ? ":" + std::to_string(e.line) : std::string()) + ": " + e.message);
            }
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s\n", e.what());
            ++failed;
        }
    }
    return failed ? 1 : 0;
}

int make(const std::string& name, const std::string& dir) {
    bool found = false;
    for (const DemoScene& d : demo_scenes()) {
        if (name != "all" && name != d.name) continue;
        found = true;
        std::string text = d.make();
        if (dir.empty()) {
            std::fputs(text.c_str(), stdout);
            continue;
        }
        std::string path = dir + "/" + d.name + ".scene";
        std::ofstream out(path, std::ios::binary);
        out << text;
        if (!out) throw HarnessError("cannot write " + path);
        std::printf("%s (%zu bytes)\n", path.c_str(), text.size());
    }
    if (!found) usage_error("no demo scene '" + name + "' (see 'modexlab-scene list')");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) usage_error("no command");
    try {
        const std::string& verb = args[0];
        if (verb == "check") {
            if (args.size() < 2) usage_error("check needs files");
            return check(std::vector<std::string>(args.begin() + 1, args.end()));
        }
        if (verb == "make") {
            if (args.size() < 2 || args.size() > 3) usage_error("make NAME|all [DIR]");
            return make(args[1], args.size() == 3 ? args[2] : "");
        }
        if (verb == "list") {
            for (const DemoScene& d : demo_scenes()) std::printf("%-10s %s\n", d.name, d.exercises);
            return 0;
        }
        if (verb == "obj") {
            if (args.size() != 3) usage_error("obj FILE.obj NAME");
            std::fputs(obj_to_mesh(read_whole_file(args[1]), args[2], args[1]).c_str(), stdout);
            return 0;
        }
        usage_error("unknown command '" + verb + "'");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "modexlab-scene: %s\n", e.what());
        return 1;
    }
}
