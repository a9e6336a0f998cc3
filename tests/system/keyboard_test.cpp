// The show at the keyboard: keys pressed through QMP send-key on QEMU's PS/2 keyboard (the 8042,
// IRQ 1, scan code set 1 by translation) drive the boot show, each reported by a `key` event, and
// the screen shows what the key says: the paused frame, the next one, another mapper, surface,
// scene and budget, the HUD's text and the help, each equal to the host's drawing pixel for pixel.
#include "tests/system/system.h"

#include <unistd.h>

#include "kernel/core/budget.h"
#include "kernel/core/policy.h"
#include "kernel/lib/keys.h"
#include "kernel/scene/text.h"
#include "qemu/accuracy/measure.h"

namespace {

using namespace systest;

void expect_screen(Session& s, const json& e, const std::string& stem) {
    SCOPED_TRACE(stem + ": " + e.dump());
    LoadedWorld host = load_world_file("scenes/" + e["scene"].get<std::string>());
    expect_screendump(s, show_screen(e), host.world->palette, stem);
}

json press(Session& s, const std::string& qcode, const std::string& action) {
    s.send_key(qcode);
    json e = s.wait_event("key");
    EXPECT_EQ(e["action"], action) << qcode << ": " << e.dump();
    return e;
}

TEST(Keyboard, KeysDriveTheShowAndTheScreenShowsWhatTheySay) {
    SessionOptions o = options_for_this_test();
    o.append = "boot=demo scene=cube.scene mapper=exact";
    Session s(o);
    const json& k = s.boot_line()["keyboard"];
    EXPECT_TRUE(k["controller"].get<bool>() && k["port"].get<bool>() && k["keyboard"].get<bool>() && k["irq"].get<bool>()) << k.dump();

    // Space pauses: the frame in hand again, the HUD saying so; the screen then stays
    json e = press(s, "spc", "pause");
    EXPECT_EQ(e["key"], "space");
    EXPECT_TRUE(e["paused"].get<bool>());
    EXPECT_EQ(e["scene"], "cube.scene");
    EXPECT_EQ(e["mapper"], "exact");
    ASSERT_GE(e["hud"].size(), 4u);
    EXPECT_EQ(e["hud"][0], "cube.scene  frame " + std::to_string(e["frame"].get<int>()) + "/" +
                               std::to_string(load_world_file("scenes/cube.scene").world->frames));
    EXPECT_EQ(e["hud"][1], "exact");
    EXPECT_EQ(e["hud"][2], "paused, RAM + blit");
    EXPECT_EQ(e["hud"][3].get<std::string>().rfind("cycles/px ", 0), 0u) << "a TSC: cycles a pixel";
    expect_screen(s, e, "paused");
    usleep(300000);
    expect_screen(s, e, "still-paused");
    const int paused_at = e["frame"];

    // H: the HUD off, the bare frame
    e = press(s, "h", "hud");
    EXPECT_TRUE(e["hud"].empty());
    expect_screen(s, e, "hud-off");
    // S: one frame on, still paused
    e = press(s, "s", "step");
    EXPECT_EQ(e["frame"], (paused_at + 1) % load_world_file("scenes/cube.scene").world->frames);
    expect_screen(s, e, "step");
    // H again, then Down: the next mapper of the registry, and V: straight into VGA memory by columns
    press(s, "h", "hud");
    e = press(s, "down", "next-mapper");
    const int exact_row = int(raster::find_mapper("exact") - raster::MAPPERS);
    EXPECT_EQ(e["mapper"], raster::MAPPERS[exact_row + 1].name);
    EXPECT_EQ(e["hud"][1], raster::MAPPERS[exact_row + 1].name);
    expect_screen(s, e, "next-mapper");
    e = press(s, "v", "surface");
    EXPECT_EQ(e["surface"], "vga");
    EXPECT_EQ(e["hud"][2], "paused, VGA memory");
    expect_screen(s, e, "vga-surface");
    // Up three times: back past exact and affine to the registry's last, auto; + raises its budget a step
    press(s, "up", "previous-mapper");
    e = press(s, "up", "previous-mapper");
    e = press(s, "up", "previous-mapper");
    EXPECT_EQ(e["mapper"], "auto");
    const double before = e["budget"]["max_error"];
    e = press(s, "equal", "budget-up");
    EXPECT_GT(e["budget"]["max_error"].get<double>(), before);
    EXPECT_NE(e["hud"][1].get<std::string>().find("auto, budget "), std::string::npos);
    expect_screen(s, e, "auto-budget-up");
    e = press(s, "minus", "budget-down");
    EXPECT_EQ(e["budget"]["max_error"].get<double>(), before);
    // Right: the next scene from its first frame
    e = press(s, "right", "next-scene");
    EXPECT_NE(e["scene"], "cube.scene");
    EXPECT_EQ(e["frame"], 0);
    expect_screen(s, e, "next-scene");

    // F1: the help, drawn in the scene's palette; any key goes back
    e = press(s, "f1", "help");
    EXPECT_TRUE(e["help"].get<bool>());
    {
        LoadedWorld host = load_world_file("scenes/" + e["scene"].get<std::string>());
        IndexImage want{320, 240, std::vector<uint8_t>(320 * 240, 0)};
        raster::Target t = raster::linear_target(want.index.data(), 320, 240, 320);
        raster::draw_help(t, raster::text_colours(host.world->palette));
        expect_screendump(s, want, host.world->palette, "help");
    }
    e = press(s, "x", "help");
    EXPECT_FALSE(e["help"].get<bool>());
    expect_screen(s, e, "after-help");

    // a key the show does not bind is reported and changes nothing; Space goes on
    e = press(s, "q", "none");
    e = press(s, "spc", "pause");
    EXPECT_FALSE(e["paused"].get<bool>());
    // the first command still ends the show
    EXPECT_EQ(s.ok("hello")["mode"], "modex");
}

}  // namespace
