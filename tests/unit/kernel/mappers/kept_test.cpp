// Under test: kernel/mappers/auto/draw.cpp (auto_draw_frame's objects kept from frame to frame,
// ChoiceLists::objects) and choice.h (AutoObjectKey).
// What auto keeps of an object from one frame to the next draws every frame as plans and drawers
// made afresh would, however the scene, the frame, the budget, its target and the walker change
// between them.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "kernel/mappers/auto/choice.h"
#include "qemu/accuracy/measure.h"
#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;
using harness::LoadedWorld;

TEST(Auto, ObjectsKeptFromFrameToFrameDrawAsObjectsMadeAfresh) {
    const Mapper& a = *find_mapper("auto");
    const char* const scenes[] = {"cube", "freedoom", "ball", "cube-256", "corridor-cut", "rotozoom"};
    std::vector<LoadedWorld> worlds;
    for (const char* s : scenes) worlds.push_back(harness::load_world_file(std::string("scenes/") + s + ".scene"));
    const Budget budgets[] = {{true, 1, true}, {true, 1, false}, {true, 0.5, true}, {true, 2, true}, {true, 4, false}, {true, 4, true}, {true, 0, true}, {true, ANY_ERROR, false}};
    auto kept = std::make_unique<ChoiceLists>();
    int steps = 0, drew = 0;
    for (int i = 0; i < 6 * 48; ++i) {
        // (the frame each step, the machine priced for every third, the budget every fourth, the
        // walker (and with it the target: planes for columns) every seventh, each at times alone,
        // the scene every 48th)
        LoadedWorld& w = worlds[size_t(i / 48)];
        auto frame = harness::world_frame(w, int32_t((i * 37) % w.world->frames));
        const Axis axis = (i / 7) % 2 ? Axis::Rows : Axis::Columns;
        frame->budget = budgets[(i / 4) % 8];
        frame->budget.target = CostTarget((i / 3) % int(CostTarget::Count)), frame->budget.lists = kept.get();
        RenderStats with_kept;
        const harness::IndexImage picture = harness::render_world_frame(w, *frame, a, axis, &with_kept);
        auto fresh = std::make_unique<ChoiceLists>();
        frame->budget.lists = fresh.get();
        RenderStats afresh;
        const harness::IndexImage want = harness::render_world_frame(w, *frame, a, axis, &afresh);
        const std::string what = std::string(scenes[i / 48]) + " step " + std::to_string(i);
        EXPECT_EQ(picture.index, want.index) << what;
        for (int m = 0; m < MAPPER_COUNT; ++m) EXPECT_EQ(with_kept.mapper_polygons[m], afresh.mapper_polygons[m]) << what << ", " << MAPPERS[m].name;
        EXPECT_EQ(with_kept.proven_whole, afresh.proven_whole) << what;
        EXPECT_EQ(with_kept.enveloped, afresh.enveloped) << what;
        ++steps, drew += with_kept.polygons != 0;
        if (HasFailure()) return;
    }
    EXPECT_EQ(drew, steps) << "every step drew";
}

}  // namespace
