// System tests: the kernel's guard pages (kernel/platform/guard.h) catch a mapper reading past its texture or
// writing past its surface, and the kernel's `fuzz` command draws the host's random extreme polygons
// (kernel/core/fuzz.h) with every mapper between guard pages, with the host's very counts.
#include <memory>
#include <vector>

#include "kernel/core/fuzz.h"
#include "kernel/core/policy.h"
#include "qemu/accuracy/measure.h"
#include "tests/system/system.h"

namespace {

using namespace systest;

// A mapper that reads past its texture or writes past its surface runs into a guard page (kernel/
// guard.h): the page fault is the reply, with the address (CR2), the buffer it hit and how far past
// its end, the mapper and the polygon being drawn; QEMU ends with the fault's status.
void expect_guard_fault(const std::string& which, const std::string& buffer, uint32_t error_code) {
    Session s(options_for_this_test());
    EXPECT_TRUE(s.boot_line()["guard_pages"].get<bool>()) << "paging with guard pages is on";
    s.ok("hello");
    try {
        s.command("fault " + which);
        FAIL() << "fault " << which << " was not caught";
    } catch (const KernelFault& f) {
        const json& r = f.report();
        EXPECT_EQ(r["vector"], 14);
        EXPECT_EQ(r["name"], "#PF");
        char want[16];
        std::snprintf(want, sizeof want, "0x%08x", error_code);
        EXPECT_EQ(r["error_code"], want) << "bit 1: a write";
        EXPECT_EQ(r["buffer"], buffer);
        EXPECT_EQ(r["mapper"], "exact");
        EXPECT_EQ(r["polygon"], 0);
        // the address is the buffer's first byte past its end: on a page boundary
        const uint32_t cr2 = uint32_t(std::stoul(r["cr2"].get<std::string>(), nullptr, 16));
        EXPECT_EQ(cr2 % 4096, 0u) << r["cr2"];
    }
    auto e = s.exit_info();
    ASSERT_TRUE(e);
    EXPECT_EQ(e->status, 2 * (0x40 + 14) + 1) << e->describe();
}

TEST(Guard, AReadPastATextureHitsItsGuardPage) {
    expect_guard_fault("texture-read", "a read 1 byte past the end of fault texture (32 of its 64 rows)", 0);
}
TEST(Guard, AWritePastASurfaceHitsItsGuardPage) {
    expect_guard_fault("surface-write", "a write 1 byte past the end of fault surface (120 of its 240 rows)", 2);
}

// Every mapper draws 64 polygons in the kernel (the NASM loops where there are, between guard
// pages) and on the host (the C++ twins): no fault, nothing outside the clip, and the same polygons
// drawn and refused for the same reasons, with the same pixel count.
TEST(Guard, TheKernelFuzzesEveryMapperAsTheHostDoes) {
    constexpr uint32_t POLYGONS = 64;
    std::vector<std::vector<uint8_t>> texels, bordered, aligned, doubled;
    raster::Texture bank[raster::FUZZ_TEXTURE_COUNT];
    for (int i = 0; i < raster::FUZZ_TEXTURE_COUNT; ++i) {
        const raster::FuzzTextureSize size = raster::fuzz_texture_size(i);
        texels.emplace_back(size_t(size.width) * size_t(size.height));
        bordered.emplace_back(size_t(raster::bordered_bytes(size.width, size.height)));
        aligned.emplace_back(raster::ALIGNED256_BYTES);
        doubled.emplace_back(raster::gets_doubled(size.width, size.height) ? size_t(raster::doubled_bytes(size.width, size.height)) : 0);
        raster::generate_texture(raster::TextureKind::Xor, size.width, size.height, texels.back().data());
        bank[i] = raster::Texture{texels.back().data(), size.width, size.height, raster::fuzz_texture_wrap(i)};
        raster::prepare_texture(&bank[i], bordered.back().data(), aligned.back().data(), doubled.back().data());
    }
    std::vector<uint8_t> surface(raster::SCREEN_PIXELS);
    auto give_surface = [](void* ctx, bool) { return static_cast<std::vector<uint8_t>*>(ctx)->data(); };
    Session s(options_for_this_test());
    for (int m = 0; m < raster::MAPPER_COUNT; ++m) {
        const raster::Mapper& mapper = raster::MAPPERS[m];
        // a seed whose batch draws something on the host (a batch takes one texture: on some, such
        // as a clamped 1 x 1 for fast-table, whose texel more never fits, every polygon is refused),
        // so that the comparison is not of nothing
        uint32_t seed = 1000 + uint32_t(m);
        raster::FuzzStats want = raster::fuzz_mapper(mapper, seed, POLYGONS, bank, give_surface, &surface);
        for (int tries = 1; tries < 8 && want.pixels == 0; ++tries)
            seed += 64, want = raster::fuzz_mapper(mapper, seed, POLYGONS, bank, give_surface, &surface);
        const json r = s.ok("fuzz " + std::to_string(POLYGONS) + " " + mapper.name + " " + std::to_string(seed));
        EXPECT_EQ(r["polygons"], POLYGONS) << mapper.name;
        EXPECT_EQ(r["written_outside_clip"], 0) << mapper.name;
        EXPECT_EQ(want.written_outside, 0u) << mapper.name;
        EXPECT_EQ(r["drawn"], want.by_status[0]) << mapper.name;
        for (int k = 1; k < 7; ++k)
            EXPECT_EQ(r["refused"][raster::setup_status_name(raster::SetupStatus(k))], want.by_status[k]) << mapper.name;
        EXPECT_EQ(r["pixels"], want.pixels) << mapper.name;
        EXPECT_GT(want.pixels, 0u) << mapper.name;
    }
    // a long run shows progress once a second and a line stops it between batches
    const json r = stopped_at_first_progress(s, "fuzz 100000000 exact 9", "fuzz", 100000000);
    EXPECT_TRUE(r["interrupted"].get<bool>()) << r.dump();
    EXPECT_GT(r["polygons"].get<int>(), 0);
    EXPECT_LT(r["polygons"].get<int>(), 100000000);
    EXPECT_EQ(r["polygons"].get<int>() % 256, 0) << "stopped between batches";
    EXPECT_EQ(s.raw("")["cmd"], "hello");
}

// The 3D scene's textures are taken again on every load, from the pool's other end: a later load
// never reuses what the fuzz command (or anything else kept for the boot) took in between, so the
// frame after loads and fuzz runs interleaved is still the host's.
TEST(Guard, TexturesOfALaterLoadLeaveOtherBuffersAlone) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    s.ok("load cube.scene");
    s.ok("fuzz 64 exact 1");
    s.ok("load corridor.scene");  // larger textures than the cube's
    s.ok("fuzz 256 exact 2");
    s.ok("fuzz 256 fast-affine 3");
    const json r = s.ok("frame 30 exact 0 linear");
    LoadedWorld host = load_world_file("scenes/corridor.scene");
    auto f = world_frame(host, 30);
    const IndexImage want = render_world_frame(host, *f, *raster::find_mapper("exact"), raster::Axis::Rows);
    const Comparison rb = compare(s.readback(0), want);
    EXPECT_TRUE(rb.equal()) << rb.summary();
    EXPECT_EQ(s.ok("fuzz 64 exact 1")["written_outside_clip"], 0);
}

}  // namespace
