// modexlab-render: renders a screen-space scene (or a frame of a 3D scene) on the host with a mapper
// or the reference, writes a PNG and, with --compare, prints the accuracy metrics against the
// reference. The output lines are "key value" pairs whose names and meanings are fixed
// (docs/accuracy.md, "modexlab-render").
#include <cstdio>
#include <string>
#include <vector>

#include "qemu/lib/command_line.h"
#include "qemu/lib/error.h"
#include "qemu/lib/host_image.h"
#include "qemu/accuracy/measure.h"

namespace {

using namespace harness;

const char* USAGE =
    "usage: modexlab-render SCENE --mapper NAME|reference [--axis rows|columns] --out FILE.png\n"
    "                       [--frame N] [--compare [--diff FILE.png]]\n"
    "  --frame    a 3D scene's frame (default 0; frame n shows time n/30 s)\n"
    "  --mapper   a mapper of the registry (docs/mappers.md and docs/classics.md: exact, affine, fast-affine, ...) or 'reference'\n"
    "  --axis     the walker: rows or columns (default: the mapper's own, rows for those that walk\n"
    "             both; our generic walkers cover the same pixels either way)\n"
    "  --out      the picture, 320x240, in the scene's palette\n"
    "  --compare  print the accuracy metrics against the reference (a 3D frame: polygon by polygon)\n"
    "  --diff     with --compare, screen-space scenes: a picture of the differences (red: palette index differs,\n"
    "             yellow: drawn but not covered by the reference, blue: covered but not drawn)\n";

RgbImage difference_picture(const raster::PixelImage& ref, const raster::PixelImage& drawn) {
    RgbImage out{ref.width, ref.height, std::vector<uint8_t>(size_t(ref.width) * size_t(ref.height) * 3)};
    const raster::Palette& pal = raster::palette(raster::PaletteId::Default);
    for (int32_t i = 0; i < ref.width * ref.height; ++i) {
        uint8_t* p = &out.rgb[3 * size_t(i)];
        bool r = ref.coverage[i], d = drawn.coverage[i];
        if (d && !r) p[0] = 255, p[1] = 255, p[2] = 0;
        else if (r && !d) p[0] = 0, p[1] = 0, p[2] = 255;
        else if (ref.index[i] != drawn.index[i]) p[0] = 255, p[1] = 0, p[2] = 0;
        else {
            const raster::Rgb6& c = pal.entry[ref.index[i]];
            p[0] = uint8_t(qemu_widen(c.r) / 4), p[1] = uint8_t(qemu_widen(c.g) / 4), p[2] = uint8_t(qemu_widen(c.b) / 4);
        }
    }
    return out;
}

double share(uint32_t part, uint32_t whole) { return whole ? double(part) / double(whole) : 0.0; }

RgbImage colourise_with(const IndexImage& img, const raster::Palette& pal) {
    RgbImage out{img.width, img.height, std::vector<uint8_t>(img.index.size() * 3)};
    for (size_t i = 0; i < img.index.size(); ++i) {
        const raster::Rgb6& c = pal.entry[img.index[i]];
        out.rgb[3 * i] = uint8_t(qemu_widen(c.r)), out.rgb[3 * i + 1] = uint8_t(qemu_widen(c.g)), out.rgb[3 * i + 2] = uint8_t(qemu_widen(c.b));
    }
    return out;
}

// The accuracy metrics, as `key value` lines (docs/accuracy.md).
void print_metrics(const raster::AccuracyMetrics& m) {
    std::printf("reference_pixels %u\noverdraw %u\ngaps %u\noverlaps %u\ncompared_pixels %u\n", m.reference_pixels, m.overdraw,
                m.gaps, m.overlaps, m.compared);
    std::printf("max_texel_error %u\nmean_texel_error %.6f\nshare_exact %.6f\nshare_within_one %.6f\n", m.max_texel_error,
                m.mean_texel_error, share(m.exact, m.compared), share(m.within_one, m.compared));
    std::printf("pixels_index_differs %u\nshare_index_differs %.6f\n", m.index_differs, share(m.index_differs, m.union_pixels));
    std::printf("p999_texel_error %u\nmax_footprint_error %.6f\nmean_footprint_error %.6f\np999_footprint_error %.6f\nfolded_pixels %u\n",
                m.p999_texel_error, m.max_footprint_error, m.mean_footprint_error, m.p999_footprint_error, m.folded);
}

// A frame of a 3D scene: the picture and the frame's and the drawing's figures; with compare, the
// metrics measured polygon by polygon (docs/accuracy.md, 3D frames).
int render_world(const std::string& path, const std::string& text, const raster::Mapper* mapper, raster::Axis axis, int32_t n,
                 const std::string& out, bool compare, bool diff) {
    if (diff) throw HarnessError("--diff takes screen-space scenes (a 3D frame's metrics come polygon by polygon)");
    LoadedWorld w = parse_world_text(text, path, world_search_path(path));
    auto frame = world_frame(w, n);
    std::printf("modexlab-render 1\nscene %s\nversion 2\nframe %d\n", path.c_str(), n);
    const raster::FrameStats& f = frame->stats;
    std::printf("faces %u\nculled %u\noutside %u\nclipped %u\npolygons %u\noverflow %u\n", f.faces, f.culled, f.outside, f.clipped,
                f.polygons, f.overflow);
    IndexImage picture;
    if (!mapper) {
        Picture ref(raster::SCREEN_WIDTH, raster::SCREEN_HEIGHT);
        raster::reference_frame(*frame, *w.textures, ref.view);
        picture = IndexImage{ref.view.width, ref.view.height, ref.index};
        uint32_t covered = 0;
        for (uint8_t c : ref.coverage) covered += c ? 1 : 0;
        std::printf("mapper reference\npixels_drawn %u\n", covered);
    } else {
        raster::RenderStats stats;
        picture = render_world_frame(w, *frame, *mapper, axis, &stats);
        std::printf("mapper %s %s\n", mapper->name, axis == raster::Axis::Rows ? "rows" : "columns");
        std::printf("polygons_drawn %u\npolygons_skipped %u\npolygons_rejected %u\nspans %u\npixels_drawn %u\n", stats.polygons,
                    stats.skipped, stats.rejected, stats.spans, stats.pixels);
        if (compare) print_metrics(measure_world_frame(w, *frame, *mapper, axis));
    }
    save_png(out, colourise_with(picture, w.world->palette));
    return 0;
}

// The mapper a --mapper names, or nullptr for the reference.
const raster::Mapper* mapper_named(const std::string& name) {
    if (name == "reference") return nullptr;
    if (const raster::Mapper* m = raster::find_mapper({name.data(), name.size()})) return m;
    std::string known;
    for (int k = 0; k < raster::MAPPER_COUNT; ++k) known += std::string(" ") + raster::MAPPERS[k].name;
    throw UsageError("unknown mapper '" + name + "' (mappers:" + known + ", or reference)");
}

int render(const std::vector<std::string>& words) {
    const CommandLine args = parse_command_line(words, {"--mapper", "--out", "--diff", "--frame", "--axis"}, {"--compare"});
    if (args.help()) return show_usage(USAGE);
    const int32_t frame = args.integer("--frame", 0, raster::MAX_FRAMES - 1, 0);
    raster::Axis axis = args.choice<raster::Axis>("--axis", {{"rows", raster::Axis::Rows}, {"columns", raster::Axis::Columns}},
                                                  raster::Axis::Rows);
    if (args.positionals().size() > 1) throw UsageError("more than one scene");
    if (args.positionals().empty()) throw UsageError("no scene");
    const std::string scene_path = args.positionals()[0], mapper_name = args.text("--mapper"), out = args.text("--out");
    const std::string diff = args.text("--diff");
    const bool compare_to_reference = args.has("--compare");
    if (mapper_name.empty()) throw UsageError("no --mapper");
    if (out.empty()) throw UsageError("no --out");
    if (!diff.empty() && !compare_to_reference) throw UsageError("--diff goes with --compare");
    const raster::Mapper* mapper = mapper_named(mapper_name);
    if (mapper) {
        if (!args.has("--axis")) axis = raster::home_axis(*mapper);
        if (!raster::mapper_walks(*mapper, axis))
            throw UsageError(mapper_name + " does not walk " + (axis == raster::Axis::Rows ? "rows" : "columns"));
    }
    std::string text = read_whole_file(scene_path);
    raster::ParseError version_error;
    if (raster::scene_version(text.data(), text.size(), &version_error) == 2) return render_world(scene_path, text, mapper, axis, frame, out, compare_to_reference, !diff.empty());
    LoadedScene s = parse_scene_text(text, scene_path);
    const raster::Palette& pal = raster::palette(raster::PaletteId::Default);
    std::printf("modexlab-render 1\n");
    std::printf("scene %s\n", scene_path.c_str());
    std::printf("texture %s %dx%d %s\n", raster::texture_kind_name(s.scene->texture_kind), s.texture.width, s.texture.height,
                raster::wrap_name(s.texture.wrap));
    std::printf("polygons %d\n", s.scene->polygon_count);
    std::unique_ptr<Picture> ref = render_reference(s);
    if (!mapper) {
        save_png(out, colourise(IndexImage{ref->view.width, ref->view.height, ref->index}, pal));
        std::printf("mapper reference\n");
        uint32_t covered = 0;
        for (uint8_t c : ref->coverage) covered += c ? 1 : 0;
        std::printf("pixels_drawn %u\n", covered);
        return 0;
    }
    if (!mapper_takes(s, *mapper))
        throw HarnessError(std::string(mapper->name) + " cannot take this scene's texture (" +
                           raster::texture_kind_name(s.scene->texture_kind) + " " + std::to_string(s.texture.width) + "x" +
                           std::to_string(s.texture.height) + " " + raster::wrap_name(s.texture.wrap) +
                           "): see its needs in docs/mappers.md or docs/classics.md");
    raster::RenderStats stats;
    IndexImage picture = render_mapper(s, *mapper, axis, &stats);
    save_png(out, colourise(picture, pal));
    std::printf("mapper %s %s\n", mapper->name, axis == raster::Axis::Rows ? "rows" : "columns");
    std::printf("polygons_drawn %u\npolygons_skipped %u\npolygons_rejected %u\nspans %u\npixels_drawn %u\n", stats.polygons,
                stats.skipped, stats.rejected, stats.spans, stats.pixels);
    if (!compare_to_reference) return 0;
    std::unique_ptr<Picture> drawn = measure_mapper(s, *mapper, axis);
    print_metrics(raster::compare_to_reference(ref->view, drawn->view, s.texture.width, s.texture.height, s.texture.wrap));
    if (!diff.empty()) save_png(diff, difference_picture(ref->view, drawn->view));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return run_cli("modexlab-render", USAGE, [&] { return render(std::vector<std::string>(argv + 1, argv + argc)); });
}
