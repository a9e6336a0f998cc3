// Under test: kernel/mappers/registry.cpp (every mapper's Guarantee).
// Every mapper on every screen-space scene against the reference: the accuracy table is printed
// (what each mapper is), and only what the registry promises is asserted (Mapper::guarantee).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "tests/unit/kernel/core/raster_helpers.h"

namespace {

using namespace rastertest;

// A scene without perspective: every vertex has the same w.
bool flat(const Scene& s) {
    for (int32_t i = 1; i < s.vertex_count; ++i)
        if (s.vertices[i].w != s.vertices[0].w) return false;
    return true;
}

TEST(Promises, EveryMapperKeepsItsGuaranteeOnTheScreenScenes) {
    std::vector<std::string> files;
    for (const auto& f : std::filesystem::directory_iterator("scenes/screen"))
        if (f.path().extension() == ".scene") files.push_back(f.path().string());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 10u);
    int checked = 0, flat_scenes = 0;
    std::printf("%-18s %-16s %7s %6s %6s %4s %8s %7s\n", "scene", "mapper", "drawn", "gaps", "over", "max", "mean", "exact");
    for (const std::string& file : files) {
        LoadedScene s = load_scene_file(file);
        const std::string name = std::filesystem::path(file).stem().string();
        const bool no_perspective = flat(*s.scene);
        flat_scenes += no_perspective;
        auto ref = render_reference(s);
        for (int m = 0; m < MAPPER_COUNT; ++m) {
            const Mapper& mapper = MAPPERS[m];
            if (!mapper_takes(s, mapper)) continue;
            RenderStats stats;
            render_mapper(s, mapper, home_axis(mapper), &stats);
            auto drawn = measure_mapper(s, mapper, home_axis(mapper));
            AccuracyMetrics a = compare_to_reference(ref->view, drawn->view, s.texture.width, s.texture.height, s.texture.wrap);
            std::printf("%-18s %-16s %7u %6u %6u %4u %8.4f %7.4f%s", name.c_str(), mapper.name, a.drawn_pixels, a.gaps, a.overdraw,
                        a.max_texel_error, a.mean_texel_error, a.compared ? double(a.exact) / a.compared : 1.0,
                        no_perspective ? "  no perspective" : "");
            if (stats.rejected > 0) {
                // a mapper that cannot take a polygon (texture coordinates beyond what it can
                // address) refuses it whole: its promises hold for what it draws
                std::printf("  refused %u of %u polygons\n", stats.rejected, uint32_t(s.scene->polygon_count));
                continue;
            }
            std::printf("\n");
            const Guarantee& g = mapper.guarantee;
            if (g.exact_coverage) {
                EXPECT_EQ(a.gaps, 0u) << mapper.name << " on " << s.name;
                EXPECT_EQ(a.overdraw, 0u) << mapper.name << " on " << s.name;
                EXPECT_EQ(a.overlaps, 0u) << mapper.name << " on " << s.name;
            }
            if (g.max_error >= 0) {
                EXPECT_LE(a.max_texel_error, uint32_t(g.max_error)) << mapper.name << " on " << s.name;
            }
            if (g.max_error_flat >= 0 && no_perspective) {
                EXPECT_LE(a.max_texel_error, uint32_t(g.max_error_flat)) << mapper.name << " on " << s.name;
            }
            if (g.max_error == 0) {
                EXPECT_EQ(a.index_differs, 0u) << mapper.name << " on " << s.name << ": equal to the reference";
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, int(files.size()) * 5);
    EXPECT_GE(flat_scenes, 3) << "scenes without perspective, for the flat bound";
}

}  // namespace
