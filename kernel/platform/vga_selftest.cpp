// VGA loop checks: xsharp-row-out's OUT-per-pixel loop against its twin.
#include "kernel/platform/vga_selftest.h"

#include "drivers/vga.h"
#include "kernel/lib/mem.h"
#include "kernel/mappers/xsharp.h"

namespace vga_selftest {

namespace {

constexpr int PAGE = 2;
alignas(4) uint8_t g_planes[raster::SCREEN_PIXELS];

// Row y of the page, all four planes, against the RAM copy.
bool row_matches(int32_t y) {
    volatile const uint8_t* page = vga::page_base(PAGE);
    for (uint8_t plane = 0; plane < 4; ++plane) {
        vga::set_read_plane(plane);
        for (int32_t i = 0; i < raster::PLANE_ROW_BYTES; ++i)
            if (page[y * raster::PLANE_ROW_BYTES + i] != g_planes[plane * raster::PLANE_BYTES + y * raster::PLANE_ROW_BYTES + i]) return false;
    }
    return true;
}

void clear_row(int32_t y) {
    volatile uint8_t* page = vga::page_base(PAGE);
    vga::set_map_mask(0x0F);
    for (int32_t i = 0; i < raster::PLANE_ROW_BYTES; ++i) page[y * raster::PLANE_ROW_BYTES + i] = raster::CHECK_GUARD;
    for (int plane = 0; plane < 4; ++plane)
        memset(g_planes + plane * raster::PLANE_BYTES + y * raster::PLANE_ROW_BYTES, raster::CHECK_GUARD, raster::PLANE_ROW_BYTES);
}

}  // namespace

raster::LoopCheck check(const raster::Mapper& mapper, uint32_t seed, uint32_t cases, uint8_t* texels) {
    raster::LoopCheck result;
    result.loop = mapper.name;
    raster::Random r(seed);
    raster::fill_check_texels(r, texels);
    for (uint32_t c = 0; c < cases; ++c) {
        raster::XSharpRowArgs a;
        int32_t x, y;
        raster::random_xsharp_row(r, texels, &a, &x, &y);
        clear_row(y);
        raster::XSharpRowArgs twin = a;
        twin.dst = g_planes + y * raster::PLANE_ROW_BYTES + (x >> 2);
        twin.plane_bytes = raster::PLANE_BYTES;
        a.dst = const_cast<uint8_t*>(vga::page_base(PAGE)) + y * raster::PLANE_ROW_BYTES + (x >> 2);
        a.plane_bytes = 0;
        mapper.twin(&twin);
        mapper.asm_loop(&a);
        ++result.cases;
        result.pixels += uint32_t(a.count);
        if (!row_matches(y) && result.mismatches++ == 0) result.first_mismatch = c;
    }
    return result;
}

}  // namespace vga_selftest
