// The kernel's C++ built for the P6 (CMOV, FCOMI; the Makefile's p6 bundle, every symbol p6.NAME)
// draws every random polygon with every mapper exactly as the 486's build does, byte for byte,
// through each mapper's home surface, with the C++ twin loops and with the NASM ones (those that run
// off the VGA), auto included.
#include <gtest/gtest.h>

#include <vector>

#include "kernel/core/fuzz.h"
#include "kernel/core/policy.h"
#include "kernel/core/render.h"
#include "kernel/core/surface.h"
#include "tests/unit/kernel/core/raster_helpers.h"

// the P6 build's registry and draw_polygon (kernel/core/render.h), by their renamed symbols
extern const raster::Mapper P6_MAPPERS[] asm("p6._ZN6raster7MAPPERSE");
raster::SetupStatus p6_draw_polygon(const raster::Vertex* vertices, int count, const raster::Texture& tex, const raster::Mapper& mapper,
                                    raster::Axis axis, raster::Target& target, raster::RenderStats* stats, raster::Variant variant,
                                    const raster::Budget& budget, raster::Input input)
    asm("p6._ZN6raster12draw_polygonEPKNS_6VertexEiRKNS_7TextureERKNS_6MapperENS_4AxisERNS_6TargetEPNS_11RenderStatsENS_7VariantERKNS_6BudgetENS_5InputE");

namespace {

using namespace raster;
using rastertest::TextureCopies;

constexpr int POLYGONS = 200;  // a mapper, each loop (under qemu-i386 where this machine runs no 32-bit programs)

TEST(P6Build, DrawsEveryPolygonAsThe486BuildDoes) {
    std::vector<uint8_t> texels(256 * 256);
    generate_texture(TextureKind::Xor, 256, 256, texels.data());
    Texture tex{texels.data(), 256, 256, Wrap::Repeat};
    TextureCopies copies(&tex);
    int distinct = 0;
    for (int i = 0; i < MAPPER_COUNT; ++i) {
        const Mapper& m = MAPPERS[i];
        const Mapper& p6 = P6_MAPPERS[i];
        ASSERT_STREQ(m.name, p6.name) << "the two builds list the same rows";
        distinct += (m.span && m.span != p6.span) || (m.draw && m.draw != p6.draw);
        const Surface surface = home_surface(m);
        const Axis axis = home_axis(m);
        for (Variant variant : {Variant::Twin, Variant::Asm}) {
            if (variant == Variant::Asm && (!m.asm_loop || (m.needs & NEED_VGA_FOR_ASM))) continue;
            std::vector<uint8_t> pixels[2];
            for (auto& p : pixels) p.assign(320 * 240 + 4096, 0);
            auto target = [&](int k) {
                return surface == Surface::Linear ? linear_target(pixels[k].data(), 320, 240, 320) : planar_target(pixels[k].data());
            };
            Target targets[2] = {target(0), target(1)};
            RandomPolygons polygons(20261128u + uint32_t(i), 8192, (m.needs & NEED_INSIDE) ? 256 : 0);
            int drawn = 0;
            for (int n = 0; n < POLYGONS; ++n) {
                Vertex v[MAX_FUZZ_CORNERS];
                const int count = polygons.next(v);
                RenderStats stats[2];
                const SetupStatus a = draw_polygon(v, count, tex, m, axis, targets[0], &stats[0], variant, DEFAULT_BUDGET, Input::Any);
                const SetupStatus b = p6_draw_polygon(v, count, tex, p6, axis, targets[1], &stats[1], variant, DEFAULT_BUDGET, Input::Any);
                ASSERT_EQ(a, b) << m.name << " polygon " << n;
                drawn += a == SetupStatus::Ok;
                ASSERT_EQ(pixels[0], pixels[1]) << m.name << (variant == Variant::Asm ? " (NASM)" : " (twin)") << " polygon " << n;
            }
            EXPECT_GT(drawn, POLYGONS / 4) << m.name << ": most random polygons drawn";
        }
    }
    EXPECT_GT(distinct, MAPPER_COUNT / 2) << "the P6 build's rows point at its own code";
}

}  // namespace
