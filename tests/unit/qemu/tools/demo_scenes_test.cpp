// Under test: qemu/tools/demo_scenes.h.
// The demo scenes: the committed files are what their generator makes, each parses and animates,
// every mapper draws their frames (the sanitizer build runs this too); the OBJ converter.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "qemu/tools/demo_scenes.h"
#include "qemu/lib/error.h"
#include "qemu/accuracy/measure.h"

namespace {

using namespace harness;

TEST(DemoScenes, TheCommittedFilesAreTheGeneratorsOutput) {
    ASSERT_EQ(demo_scenes().size(), 11u);
    for (const DemoScene& d : demo_scenes())
        EXPECT_EQ(read_whole_file(std::string("scenes/") + d.name + ".scene"), d.make())
            << d.name << ": regenerate with build/host/modexlab-scene make all scenes";
}

// The variants every mapper draws whole, so that all are benched on the same work: corridor-cut
// (the corridor's faces cut along their textures' period lines), ball-256 and cube-256 (their
// textures at 256 x 256), freedoom-256 (its pictures tiled to 256 x 256, its faces cut at their
// periods). At 8 frames spread over each, no mapper refuses a polygon, the classics that cannot
// wrap or take only 256 x 256 included, while on the original some mappers refuse some or all.
TEST(DemoScenes, EveryMapperDrawsTheVariantsWhole) {
    const std::pair<const char*, const char*> variants[] = {{"corridor-cut", "corridor"}, {"ball-256", "ball"}, {"cube-256", "cube"},
                                                                 {"freedoom-256", "freedoom"}};
    for (const auto& [variant, original] : variants) {
        SCOPED_TRACE(variant);
        LoadedWorld cut = load_world_file(std::string("scenes/") + variant + ".scene");
        LoadedWorld whole = load_world_file(std::string("scenes/") + original + ".scene");
        std::set<std::string> refusing;  // on the original
        for (int32_t n = 0; n < cut.world->frames; n += cut.world->frames / 8) {
            auto frame = world_frame(cut, n), plain = world_frame(whole, n);
            for (int m = 0; m < raster::MAPPER_COUNT; ++m) {
                const raster::Mapper& mapper = raster::MAPPERS[m];
                raster::RenderStats stats, plain_stats;
                render_world_frame(cut, *frame, mapper, home_axis(mapper), &stats);
                EXPECT_EQ(stats.rejected, 0u) << mapper.name << ", frame " << n;
                EXPECT_EQ(stats.polygons + stats.skipped, uint32_t(frame->polygon_count)) << mapper.name << ", frame " << n;
                render_world_frame(whole, *plain, mapper, home_axis(mapper), &plain_stats);
                if (plain_stats.rejected) refusing.insert(mapper.name);
            }
        }
        EXPECT_GE(refusing.size(), 3u) << "the original should be refused, some or all of it, by the classics the variant is for";
    }
}

// cube-1024, its textures above 256 a side: every fast mapper of ours draws all of it through the
// doubled copies, at 8 frames spread over it; fatmap's loops, which take only 256 x 256 textures,
// refuse its faces.
TEST(DemoScenes, OurFastMappersDrawTheCubeAbove256Whole) {
    LoadedWorld w = load_world_file("scenes/cube-1024.scene");
    uint32_t drawn = 0, refused = 0;
    const char* ours[] = {"fast-table", "fast-table-columns", "fast-affine", "fast-columns", "fast-subdiv-8", "fast-subdiv-16", "fast-subdiv-32",
                          "fast-constant-depth", "fast-adaptive-1", "fast-adaptive-2", "fast-oriented-1"};
    for (int32_t n = 0; n < w.world->frames; n += w.world->frames / 8) {
        auto frame = world_frame(w, n);
        for (const char* name : ours) {
            const raster::Mapper& mapper = *raster::find_mapper(name);
            raster::RenderStats stats;
            render_world_frame(w, *frame, mapper, home_axis(mapper), &stats);
            EXPECT_EQ(stats.rejected, 0u) << name << ", frame " << n;
            EXPECT_EQ(stats.polygons + stats.skipped, uint32_t(frame->polygon_count)) << name << ", frame " << n;
            drawn += stats.polygons;
        }
        raster::RenderStats stats;
        render_world_frame(w, *frame, *raster::find_mapper("fatmap-256"), raster::Axis::Rows, &stats);
        refused += stats.rejected;
    }
    EXPECT_GT(drawn, 100u);
    EXPECT_GT(refused, 10u) << "fatmap-256 takes no texture above 256 a side";
}

TEST(DemoScenes, EveryMapperDrawsTheirFrames) {
    for (const DemoScene& d : demo_scenes()) {
        SCOPED_TRACE(d.name);
        LoadedWorld w = load_world_file(std::string("scenes/") + d.name + ".scene");
        ASSERT_GT(w.world->frames, 60);
        for (int32_t n : {0, w.world->frames / 3}) {
            auto frame = world_frame(w, n);
            EXPECT_GT(frame->polygon_count, 0) << "frame " << n;
            EXPECT_EQ(frame->stats.overflow, 0u);
            for (int m = 0; m < raster::MAPPER_COUNT; ++m) {
                const raster::Mapper& mapper = raster::MAPPERS[m];
                raster::RenderStats stats;
                IndexImage img = render_world_frame(w, *frame, mapper, home_axis(mapper), &stats);
                EXPECT_EQ(stats.polygons + stats.skipped + stats.rejected, uint32_t(frame->polygon_count)) << mapper.name;
                // ours take every texture they accept (the fast ones: every demo texture but
                // cube-1024's tiles 256 x 256; fast-table takes those too)
                bool accepts_all = true;
                for (int32_t o = 0; o < w.world->object_count; ++o) accepts_all = accepts_all && raster::mapper_accepts(mapper, w.textures->objects[o]);
                if (std::string(mapper.family) == "ours" && accepts_all) {
                    EXPECT_EQ(stats.rejected, 0u) << mapper.name << " takes every texture";
                }
                EXPECT_TRUE(accepts_all || std::string(mapper.family) != "ours" || std::string(d.name) == "cube-1024") << mapper.name;
            }
        }
    }
}

// Back-face culling against an independent computation: in world space, a face is kept when the
// eye lies on the side its (Newell) normal points to.
TEST(DemoScenes, CullingKeepsTheFacesTurnedToTheEye) {
    for (const char* name : {"ball", "mesh", "cube"}) {
        LoadedWorld w = load_world_file(std::string("scenes/") + name + ".scene");
        const raster::World& world = *w.world;
        int frames = 0;
        for (int32_t n = 0; n < world.frames; n += 17, ++frames) {
            auto frame = world_frame(w, n);
            const double t = raster::frame_time(n);
            const raster::Vec3 eye = raster::View::of(world.camera, t).eye;
            uint32_t facing = 0;
            for (int32_t o = 0; o < world.object_count; ++o) {
                const raster::Mesh& mesh = world.meshes[world.objects[o].mesh];
                const raster::Placement place = raster::Placement::of(world.objects[o], t);
                for (int32_t k = 0; k < mesh.face_count; ++k) {
                    const raster::Face& face = world.faces[mesh.first_face + k];
                    raster::Vec3 normal, first = place.apply(world.positions[world.corners[face.first_corner].position]);
                    for (int32_t i = 0; i < face.count; ++i) {
                        raster::Vec3 a = place.apply(world.positions[world.corners[face.first_corner + i].position]);
                        raster::Vec3 b = place.apply(world.positions[world.corners[face.first_corner + (i + 1) % face.count].position]);
                        normal.x += (a.y - b.y) * (a.z + b.z), normal.y += (a.z - b.z) * (a.x + b.x), normal.z += (a.x - b.x) * (a.y + b.y);
                    }
                    facing += raster::dot(normal, eye - first) > 0;
                }
            }
            EXPECT_EQ(frame->stats.faces - frame->stats.culled, facing) << name << " frame " << n;
        }
        EXPECT_GT(frames, 5);
    }
}

TEST(Obj, ConvertsTheSubsetAndFlipsV) {
    std::string obj =
        "# a unit quad, as a modeller writes it\n"
        "o quad\nmtllib q.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0.5\nvn 0 0 1\n"
        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 0.25\ns off\nusemtl stone\n"
        "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
        "f -4/-4 -2/-2 -1/-1\n";
    std::string mesh = obj_to_mesh(obj, "quad", "q.obj");
    EXPECT_EQ(mesh,
              "mesh quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0.5\nvt 0 1\nvt 1 1\nvt 1 0\nvt 0 0.75\n"
              "f 1/1 2/2 3/3 4/4\nf 1/1 3/3 4/4\nend\n");
    // it makes a scene the parser takes
    std::string scene = "modexlab-scene 2\ntexture t checker 8 8\n" + mesh + "object o\nmesh quad\ntexture t\nend\ncamera\nend\n";
    EXPECT_NO_THROW(parse_world_text(scene, "obj.scene", {"."}));
}

TEST(Obj, RefusesWhatItCannotTake) {
    const std::pair<std::string, std::string> cases[] = {
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "q.obj:4: corner '1' has no texture coordinate"},
        {"v 0 0 0\nvt 0 0\nf 1/1 2/1 1/1\n", "q.obj:3: corner '2/1' points past the list"},
        {"v 0 0 x\n", "q.obj:1: bad number 'x'"},
        {"v 0 0\n", "q.obj:1: v needs x y z"},
        {"v 0 0 0\nvt 0 0\nf 1/0 1/1 1/1\n", "q.obj:3: bad index in corner '1/0'"},
        {"v 0 0 0\nvt 0 0\nf 1/1 1/1 1/1 1/1 1/1 1/1 1/1 1/1 1/1 1/1 1/1\n", "q.obj:3: a face needs 3 to 10 corners"},
        {"v 0 0 0\n", "q.obj: no faces"},
        {"", "q.obj: no faces"},
        // what the scene parser would refuse: refused here, at the OBJ's line, with the limit
        {"v 0 0 1e38\n", "q.obj:1: coordinate 1e38 is beyond the scene format's limit of 1000000"},
        {"v 0 1e300 0\n", "q.obj:1: coordinate 1e300 is beyond"},
        {"v 0 0 0\nvt 0 20000\n", "q.obj:2: texture coordinate 20000 is beyond"},
    };
    std::string many;
    for (int i = 0; i < 40000; ++i) many += "v 0 0 " + std::to_string(i) + "\n";
    const std::pair<std::string, std::string> more[] = {{many, "q.obj:32769: more than 32768 positions (v)"}};
    for (const auto& [obj, want] : more) {
        try {
            obj_to_mesh(obj, "m", "q.obj");
            ADD_FAILURE() << "took " << obj.substr(0, 80);
        } catch (const HarnessError& e) {
            EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
        }
    }
    try {
        obj_to_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n", "two words", "q.obj");
        ADD_FAILURE() << "took a mesh name with a space";
    } catch (const HarnessError& e) {
        EXPECT_NE(std::string(e.what()).find("bad mesh name 'two words'"), std::string::npos) << e.what();
    }
    for (const auto& [obj, want] : cases) {
        try {
            obj_to_mesh(obj, "m", "q.obj");
            ADD_FAILURE() << "took " << obj;
        } catch (const HarnessError& e) {
            EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
        }
    }
}

}  // namespace
