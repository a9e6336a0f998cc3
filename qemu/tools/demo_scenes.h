// The demo scenes (scenes/*.scene), made by code so that their meshes are exact and can be made
// again: `modexlab-scene make NAME` prints one; a test checks the committed files are its output.
#pragma once

#include <string>
#include <vector>

namespace raster {
struct Mapper;
}

namespace harness {

class Session;
struct LoadedWorld;

struct DemoScene {
    const char* name;      // the file is scenes/NAME.scene
    const char* exercises; // what it is for (docs/scene-format.md lists them)
    std::string (*make)();
};

const std::vector<DemoScene>& demo_scenes();

// A scene as the tools' --scenes name it: a demo scene (its file scenes/NAME.scene, from the
// repository's top, where the tools run) or a scene file (named after its stem; a word with a '/'
// or ending in .scene is one, read later). Throws HarnessError "no demo scene or scene file 'X'
// (the demo scenes, the nearest first: ...)" for neither.
struct SceneChoice {
    std::string name, path;
    const DemoScene* demo;  // nullptr: a file
};
SceneChoice choose_scene(const std::string& spec);

// The scene into the kernel: a demo scene by its built-in name; a file with the files `host` (its
// parse on the host) read, each under the name the scene gives it, then itself under its own file
// name, loaded by that name (the kernel's errors name it so). Throws HarnessError with the
// kernel's error where it refuses one.
void load_scene_in_kernel(Session& s, const SceneChoice& scene, const LoadedWorld& host);

// The demo scenes whose first frame the mapper draws whole on the host (it refuses no polygon):
// where to send a user whose scene it refuses.
std::vector<std::string> demo_scenes_drawn_whole(const raster::Mapper& m);

// A mesh block from a Wavefront OBJ subset (v, vt, f; f corners v/vt or v/vt/vn, negative indices
// relative; other lines ignored): `v` flipped so that rows run down (OBJ's v runs up). What the
// scene parser would refuse is refused here, naming the OBJ's file and line and the limit
// (coordinates, counts, corners a face; a mesh name by the parser's own rule). Throws HarnessError
// "FILE:LINE: message", or "FILE: message" for the file as a whole.
std::string obj_to_mesh(const std::string& obj_text, const std::string& mesh_name, const std::string& file_name);

}  // namespace harness
