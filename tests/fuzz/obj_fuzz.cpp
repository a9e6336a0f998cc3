// Fuzz target `obj`: Wavefront OBJ files as `modexlab-scene obj` converts them to a mesh block.
// Promises: every refusal is a HarnessError naming the file (and, but for the file as a whole, its
// line); a mesh it makes is one the scene parser takes.
#include <memory>
#include <string>

#include "kernel/scene/world.h"
#include "qemu/lib/error.h"
#include "qemu/tools/demo_scenes.h"
#include "tests/fuzz/fuzz.h"

MODEXLAB_FUZZ_TARGET(obj) {
    const std::string obj(reinterpret_cast<const char*>(data), size);
    std::string mesh;
    try {
        mesh = harness::obj_to_mesh(obj, "m", "fuzz.obj");
    } catch (const harness::HarnessError& e) {
        if (std::string(e.what()).rfind("fuzz.obj:", 0) != 0) fuzz::fail(std::string("an error that does not name the file: ") + e.what());
        return 0;
    }
    // the mesh in a scene of its own, with a procedural texture
    const std::string scene = "modexlab-scene 2\ntexture t checker 8 8\n" + mesh +
                              "object o\nmesh m\ntexture t\nend\ncamera\nposition 0 0 5\ntarget 0 0 0\nend\n";
    static auto world = std::make_unique<raster::HostWorld>();
    raster::ParseError e;
    if (!raster::parse_world(scene.data(), scene.size(), raster::FileResolver{}, world.get(), &e))
        fuzz::fail("the converted mesh is refused: line " + std::to_string(e.line) + ": " + e.message);
    return 0;
}
