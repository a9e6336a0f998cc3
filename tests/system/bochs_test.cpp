// The kernel in Bochs 2.7, a second VGA implementation beside QEMU's: the ISO booted from Bochs's CD
// drive (GRUB, the demo's modules), COM1 on a socket; mode 13h, Mode X patterns in every page, flips
// and 3D frames drawn with several mappers and surfaces, each page read back over the serial line
// and compared with the host's picture (mode 13h's whole, the others by their CRC-32); every NASM
// loop against its twin, the VGA ones in Bochs's video memory. Bochs has no QMP: the pages come
// back by `readback` alone. All of it twice: on Bochs's default CPU (a P6: the P6 build) and on its
// Pentium model (a P5 without CMOV: the 486's build).
#include "tests/system/system.h"

#include "qemu/accuracy/measure.h"

namespace {

using namespace systest;

// A page against the host's picture by its checksum (Bochs models the line's 115200 baud: a whole
// page is seconds of it); where they differ, the page itself says how.
void expect_page(Session& s, int page, const IndexImage& want, const std::string& what) {
    if (s.readback_crc(page) != crc32_of(want)) ADD_FAILURE() << what << ": " << compare(s.readback(page), want).summary();
}

SessionOptions bochs_options(const std::string& cpu) {
    SessionOptions o = options_for_this_test();
    o.cpu = cpu;
    o.emulator = Emulator::Bochs;
    o.medium = BootMedium::Cdrom;
    o.boot_timeout = std::chrono::seconds(180);
    o.command_timeout = std::chrono::seconds(180);
    return o;
}

void boots_the_iso_and_draws(const std::string& cpu) {
    Session s(bochs_options(cpu));
    const json& b = s.boot_line();
    EXPECT_EQ(b["isa"], cpu == "pentium" ? "i486" : "p6") << b.dump();
    if (cpu == "pentium") {
        EXPECT_EQ(b["cpu_class"], "Pentium (P5)");
    }
    EXPECT_EQ(b["boot"], "demo") << "GRUB's default entry";
    EXPECT_GT(b["modules"].get<int>(), 0) << "the demo scenes as Multiboot modules";
    EXPECT_TRUE(b["keyboard"]["irq"].get<bool>()) << b.dump();
    json hello = s.ok("hello");  // (ends the show)
    EXPECT_EQ(hello["mode"], "modex");

    // mode 13h: one linear page
    EXPECT_EQ(s.ok("mode 13h")["height"], 200);
    s.ok("pattern ramp 0");
    Comparison c13 = compare(s.readback(0), render_pattern(raster::Pattern::Ramp, MODE_13H));
    EXPECT_TRUE(c13.equal()) << "13h ramp: " << c13.summary();

    // Mode X: a different pattern in each page, each page read back; the flips report the retrace
    EXPECT_EQ(s.ok("mode modex")["pages"], 3);
    const raster::Pattern in_page[3] = {raster::Pattern::Planes, raster::Pattern::Grid, raster::Pattern::Border};
    for (int page = 0; page < 3; ++page) s.ok("pattern " + std::string(raster::pattern_name(in_page[page])) + " " + std::to_string(page));
    for (int page = 0; page < 3; ++page) {
        json f = s.ok("flip " + std::to_string(page));
        EXPECT_TRUE(f["retrace"].get<bool>()) << "flip " << page;
        expect_page(s, page, render_pattern(in_page[page], MODE_X), std::string(raster::pattern_name(in_page[page])) + " in page " + std::to_string(page));
    }

    // every NASM loop against its C++ twin, those that program the VGA (map mask, write modes) into
    // Bochs's own page 2
    json st = s.ok("selftest 300");
    EXPECT_TRUE(st["vga_loops_checked"].get<bool>());
    for (const json& l : st["loops"]) EXPECT_EQ(l["mismatches"], 0) << l.dump();

    // a 3D scene: frames drawn by rows into RAM and blitted, by columns into RAM planes, and by
    // columns straight into the page (the map mask a column)
    LoadedWorld host = load_world_file("scenes/cube.scene");
    s.ok("load cube.scene");
    const struct {
        const char* mapper;
        const char* surface;
        int32_t frame;
    } runs[] = {{"exact", "linear", 37}, {"persp-subdiv-16", "planar", 80}, {"fast-columns", "vga", 131}, {"auto", "linear", 200}};
    int page = 0;
    for (const auto& r : runs) {
        SCOPED_TRACE(std::string(r.mapper) + " " + r.surface);
        json reply = s.ok("frame " + std::to_string(r.frame) + " " + r.mapper + " " + std::to_string(page) + " " + r.surface);
        const raster::Axis axis = reply["walker"] == "rows" ? raster::Axis::Rows : raster::Axis::Columns;
        auto f = world_frame(host, r.frame);
        raster::RenderStats stats;
        IndexImage want = render_world_frame(host, *f, *raster::find_mapper(r.mapper), axis, &stats);
        EXPECT_EQ(reply["pixels"], stats.pixels);
        expect_page(s, page, want, "frame " + std::to_string(r.frame));
        page = (page + 1) % 3;
    }
}

TEST(Bochs, BootsTheIsoAndDrawsWhatQemuAndTheHostDraw) { boots_the_iso_and_draws(""); }
TEST(Bochs, OnItsPentiumModelToo) { boots_the_iso_and_draws("pentium"); }

}  // namespace
