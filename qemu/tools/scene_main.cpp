// modexlab-scene: checks scene files, makes the demo scenes, converts Wavefront OBJ meshes.
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "kernel/scene/world.h"
#include "qemu/tools/demo_scenes.h"
#include "qemu/lib/command_line.h"
#include "qemu/lib/error.h"
#include "qemu/accuracy/measure.h"

namespace {

using namespace harness;

const char* USAGE =
    "usage: modexlab-scene check FILE...        parse scene files (version 1 or 2), print what each holds\n"
    "       modexlab-scene make NAME|all [DIR]   print a demo scene, or write DIR/NAME.scene (all: every one)\n"
    "       modexlab-scene list                  the demo scenes and what each exercises\n"
    "       modexlab-scene obj FILE.obj NAME     a mesh block (v, vt, f) from a Wavefront OBJ file\n";

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
    if (!found) throw UsageError("no demo scene '" + name + "' (see 'modexlab-scene list')");
    return 0;
}

// A command word, then positionals only: none of the commands has options.
int scene_tool(const std::vector<std::string>& words) {
    if (words.empty()) throw UsageError("no command");
    const std::string& verb = words[0];
    if (verb == "-h" || verb == "--help") return show_usage(USAGE);
    if (verb != "check" && verb != "make" && verb != "list" && verb != "obj") throw UsageError("unknown command '" + verb + "'");
    const CommandLine args = parse_command_line(std::vector<std::string>(words.begin() + 1, words.end()), {}, {});
    if (args.help()) return show_usage(USAGE);
    const std::vector<std::string>& p = args.positionals();
    if (verb == "check") {
        if (p.empty()) throw UsageError("check needs files");
        return check(p);
    }
    if (verb == "make") {
        if (p.empty() || p.size() > 2) throw UsageError("make NAME|all [DIR]");
        return make(p[0], p.size() == 2 ? p[1] : "");
    }
    if (verb == "list") {
        if (!p.empty()) throw UsageError("list takes no arguments");
        for (const DemoScene& d : demo_scenes()) std::printf("%-10s %s\n", d.name, d.exercises);
        return 0;
    }
    if (p.size() != 2) throw UsageError("obj FILE.obj NAME");
    std::fputs(obj_to_mesh(read_whole_file(p[0]), p[1], p[0]).c_str(), stdout);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return run_cli("modexlab-scene", USAGE, argc, argv, scene_tool);
}
