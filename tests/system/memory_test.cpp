// The kernel's memory: its image is small and loaded at 1 MiB, its buffers come from the largest
// stretch of RAM the loader reports (the pool), a scene's own buffers are taken at its load, sized
// to it: a scene that does not fit is refused saying what it needs and what is free, the show skips
// it saying so, and a machine with too little at all is told so, with what it needs and what it
// has, on COM1 (and the screen) before the kernel halts.
#include "tests/system/system.h"

#include <map>

#include "kernel/core/selftest.h"
#include "qemu/accuracy/measure.h"
#include "qemu/tools/demo_scenes.h"

namespace {

using namespace systest;

// What each demo scene's buffers take (the load reply's memory_kib), on a machine with room for all.
std::map<std::string, uint32_t> demo_scene_needs() {
    SessionOptions o = options_for_this_test();
    o.memory_mib = 64, o.name += ".needs";
    Session s(o);
    std::map<std::string, uint32_t> need;
    for (const DemoScene& d : demo_scenes()) need[d.name] = s.ok(std::string("load ") + d.name + ".scene")["memory_kib"].get<uint32_t>();
    return need;
}

// The room for a scene's buffers after the boot: the pool less what the boot took and its last guard.
uint32_t scene_room_kib(const json& boot) {
    const json& pool = boot["pool"];
    return pool["kib"].get<uint32_t>() - pool["taken_kib"].get<uint32_t>() - 4;
}

TEST(Memory, In16MiBEveryDemoScenePlaysAndBenchesAsOnTheHostSomeWithoutTheirDoubledCopies) {
    const std::map<std::string, uint32_t> need = demo_scene_needs();
    SessionOptions o = options_for_this_test();
    o.memory_mib = 16;
    Session s(o);
    const uint32_t room = scene_room_kib(s.boot_line());
    s.ok("mode modex");
    for (const DemoScene& d : demo_scenes()) {
        SCOPED_TRACE(d.name);
        const uint32_t kib = need.at(d.name);
        const json r = s.command(std::string("load ") + d.name + ".scene");
        ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
        // sized to the scene, the same on every machine; where it all does not fit, less: without
        // the doubled copies
        EXPECT_EQ(r["doubled_copies"].get<bool>(), kib <= room) << r.dump();
        if (kib <= room) EXPECT_EQ(r["memory_kib"], kib);
        else EXPECT_LE(r["memory_kib"].get<uint32_t>(), room);
        LoadedWorld host = load_world_file("scenes/" + std::string(d.name) + ".scene");
        match_kernel_copies(host, r);
        const json f = s.ok("frame 37 auto 1 linear");
        auto frame = world_frame(host, 37);
        const raster::Axis axis = f["walker"] == "rows" ? raster::Axis::Rows : raster::Axis::Columns;
        const IndexImage want = render_world_frame(host, *frame, *raster::find_mapper("auto"), axis);
        EXPECT_EQ(s.readback_crc(1), crc32_of(want));
        // and the bench's frames (as make bench draws them), every pixel the host draws
        std::vector<json> frames;
        const json bench = s.ok("bench 2 auto linear", [&](const json& e) { frames.push_back(e); });
        ASSERT_EQ(frames.size(), 2u) << bench.dump();
        for (const json& b : frames) {
            auto bf = world_frame(host, b["frame"].get<int32_t>());
            raster::RenderStats stats;
            render_world_frame(host, *bf, *raster::find_mapper("auto"), raster::Axis::Rows, &stats);
            EXPECT_EQ(b["pixels"], stats.pixels) << b.dump();
        }
    }
    std::printf("16 MiB: %u KiB for a scene's buffers\n", room);
}

TEST(Memory, In8MiBTheKernelServesAndItsShowSkipsTheScenesThatDoNotFitSayingWhy) {
    const std::map<std::string, uint32_t> need = demo_scene_needs();
    SessionOptions o = options_for_this_test();
    o.memory_mib = 8;
    o.append = "boot=demo";
    Session s(o);
    const uint32_t room = scene_room_kib(s.boot_line());
    std::vector<json> skipped = {s.wait_event("scene_skipped")};
    s.send_key("s");  // a frame, paused: its key event gives the HUD's lines
    json key;
    const json hello = s.ok("hello", [&](const json& e) { (e["event"] == "key" ? key : skipped.emplace_back()) = e; });  // (the show may skip more first)
    EXPECT_EQ(hello["cmd"], "hello") << "the show gives way to a command";
    ASSERT_TRUE(key.is_object()) << "the key's event";
    const std::string last = skipped.back()["scene"];
    EXPECT_NE(std::find(key["hud"].begin(), key["hud"].end(), "skipped " + last + ": no memory"), key["hud"].end())
        << "the HUD says which scene the show skipped last: " << key.dump();
    for (const json& e : skipped) {
        ASSERT_EQ(e["event"], "scene_skipped") << e.dump();
        const std::string scene = e["scene"], name = scene.substr(0, scene.size() - 6), error = e["error"];
        EXPECT_GT(need.at(name), room) << scene << " was skipped";
        EXPECT_NE(error.find("not enough memory for this scene"), std::string::npos) << error;
    }
    int loaded = 0;
    uint32_t free_kib = room;
    for (const auto& [n, kib] : need) {
        SCOPED_TRACE(n);
        const json r = s.command("load " + n + ".scene");
        if (r["ok"]) free_kib = r["free_kib"];
        if (kib <= room) EXPECT_TRUE(r["ok"].get<bool>() && r["doubled_copies"].get<bool>()) << r.dump();
        else if (r["ok"]) EXPECT_TRUE(!r["doubled_copies"].get<bool>() && r["memory_kib"].get<uint32_t>() <= room) << r.dump();
        else EXPECT_NE(r["error"].get<std::string>().find("not enough memory for this scene"), std::string::npos) << r.dump();
        loaded += r["ok"].get<bool>();
    }
    std::printf("8 MiB: %d of %zu demo scenes load, %u KiB for a scene's buffers\n", loaded, need.size(), room);
    // a command's own buffers, taken at its first use: refused, not a panic, where the scene leaves too little
    auto footprint = [](size_t bytes) { return ((bytes + 4095) / 4096 + 1) * 4096; };
    const size_t selftest = 2 * footprint(raster::CHECK_DST_BYTES) + footprint(raster::CHECK_TEXEL_BYTES);
    const json st = s.command("selftest 10");
    if (selftest > size_t(free_kib) << 10) {
        ASSERT_FALSE(st["ok"].get<bool>()) << st.dump();
        EXPECT_NE(st["error"].get<std::string>().find("not enough memory for the selftest's buffers: " + std::to_string((selftest + 1023) >> 10) + " KiB needed"),
                  std::string::npos) << st.dump();
    } else {
        EXPECT_TRUE(st["ok"].get<bool>()) << st.dump();
    }
    EXPECT_EQ(s.ok("hello")["cmd"], "hello") << "and it serves on";
}

TEST(Memory, ThePoolIsTheLargestStretchOfRamAboveTheImage) {
    SessionOptions o = options_for_this_test();
    o.memory_mib = 128;
    Session s(o);
    const json& pool = s.boot_line()["pool"];
    const uint32_t start = uint32_t(std::stoul(pool["start"].get<std::string>(), nullptr, 16));
    EXPECT_GE(start, kernel_symbol("__kernel_end")) << "above the image and its static buffers";
    EXPECT_LT(kernel_symbol("__kernel_end"), 8u << 20) << "a small image: the big buffers are the pool's";
    EXPECT_EQ(pool["kib"], 96u << 10) << "128 MiB leave more than the page tables cover";
    EXPECT_GT(pool["taken_kib"].get<uint32_t>(), 0u);
    EXPECT_LT(pool["taken_kib"].get<uint32_t>(), pool["kib"].get<uint32_t>());
}

// GRUB scatters its modules megabytes apart: the kernel gathers them at the top of the largest
// stretch, so that the pool is the RAM above the image less the modules, and the modules still read.
TEST(Memory, GrubsModulesAreGatheredAboveThePool) {
    SessionOptions o = options_for_this_test();
    o.medium = BootMedium::Cdrom, o.memory_mib = 16;
    Session s(o);
    const json& boot = s.boot_line();
    ASSERT_EQ(boot["modules"], int(demo_scenes().size()) + 5);
    const json& pool = boot["pool"];
    const uint32_t start = uint32_t(std::stoul(pool["start"].get<std::string>(), nullptr, 16)), image_end = kernel_symbol("__kernel_end");
    EXPECT_LT(start, image_end + (64u << 10)) << "right above the image (the loader's structures aside)";
    // 16 MiB less QEMU's top 128 KiB, the image's end and the modules (some 350 KiB)
    EXPECT_GT(pool["kib"].get<uint32_t>(), (((16u << 20) - (128u << 10) - image_end) >> 10) - 512);
    const json load = s.ok("load freedoom.scene");
    EXPECT_EQ(load["origin"], "module");
    EXPECT_EQ(load["palette"], "floor") << "its texture files, modules too, read";
    EXPECT_EQ(s.ok("frame 0 exact 0")["pixels"], 76800);
}

TEST(Memory, TooLittleIsRefusedWithWhatItNeedsAndWhatItHas) {
    SessionOptions o = options_for_this_test();
    o.memory_mib = 6;
    try {
        Session s(o);
        FAIL() << "booted in 6 MiB: " << s.boot_line().dump();
    } catch (const HarnessError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("not enough memory: modexlab needs 2048 KiB of free RAM for its buffers beside its "), std::string::npos) << what;
        // the stretch it names, in KiB, below 6 MiB and above the image
        const size_t at = what.find("the largest stretch the loader reports is ");
        ASSERT_NE(at, std::string::npos) << what;
        unsigned kib = 0, start = 0, end = 0;
        ASSERT_EQ(std::sscanf(what.c_str() + at, "the largest stretch the loader reports is %u KiB (0x%x..0x%x)", &kib, &start, &end), 3) << what;
        EXPECT_EQ(kib, (end - start) >> 10);
        EXPECT_LT(kib, 2048u);
        EXPECT_GE(start, kernel_symbol("__kernel_end"));
        EXPECT_LE(end, 6u << 20);
    }
}

}  // namespace
