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
#include "qemu/tools/demo_scenes.h"
#include "qemu/tools/trade.h"

namespace {

using namespace harness;

const char* USAGE =
    "usage: modexlab-render SCENE --mapper NAME|reference [--axis rows|columns] [--out FILE.png]\n"
    "                       [--frame N] [--compare [--diff FILE.png]]\n"
    "  SCENE      a scene file, or a demo scene's name (corridor, cube, freedoom, ...)\n"
    "  --frame    a 3D scene's frame (default 0; frame n shows time n/30 s)\n"
    "  --mapper   a mapper of the registry (docs/mappers.md and docs/classics.md: exact, affine, fast-affine, ...) or 'reference'\n"
    "  --axis     the walker: rows or columns (default: the mapper's own, rows for those that walk\n"
    "             both; our generic walkers cover the same pixels either way)\n"
    "  --out      the picture, 320x240, in the scene's palette (needed unless --compare)\n"
    "  --compare  print the accuracy metrics against the reference (a 3D frame: polygon by polygon)\n"
    "  --diff     with --compare: a picture of the differences (red: palette index differs, yellow: drawn\n"
    "             but not covered by the reference, blue: covered but not drawn; elsewhere the picture, dimmed)\n"
    "Every line printed is 'key value' (docs/accuracy.md, \"modexlab-render\"); drawn_by lines name the\n"
    "mappers that drew (auto: the ones it chose), with their polygons and pixels.\n";

// Per pixel: covered by the reference, drawn by the mapper, and each one's palette index.
struct PixelPair {
    const std::vector<uint8_t>& reference_covers;
    const std::vector<uint8_t>& drawn;
    const std::vector<uint8_t>& reference_index;
    const std::vector<uint8_t>& drawn_index;
};

RgbImage difference_picture(const PixelPair& p, const raster::Palette& pal) {
    RgbImage out{raster::SCREEN_WIDTH, raster::SCREEN_HEIGHT, std::vector<uint8_t>(p.drawn.size() * 3)};
    for (size_t i = 0; i < p.drawn.size(); ++i) {
        uint8_t* c = &out.rgb[3 * i];
        const bool r = p.reference_covers[i], d = p.drawn[i];
        if (d && !r) c[0] = 255, c[1] = 255, c[2] = 0;
        else if (r && !d) c[0] = 0, c[1] = 0, c[2] = 255;
        else if (p.reference_index[i] != p.drawn_index[i]) c[0] = 255, c[1] = 0, c[2] = 0;
        else {
            const raster::Rgb6& e = pal.entry[p.reference_index[i]];
            c[0] = uint8_t(qemu_widen(e.r) / 4), c[1] = uint8_t(qemu_widen(e.g) / 4), c[2] = uint8_t(qemu_widen(e.b) / 4);
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

// The mappers that drew, by registry row: "drawn_by NAME POLYGONS PIXELS" (auto: those it chose).
void print_drawn_by(const raster::RenderStats& st) {
    for (int i = 0; i < raster::MAPPER_COUNT; ++i)
        if (st.mapper_polygons[i]) std::printf("drawn_by %s %u %u\n", raster::MAPPERS[i].name, st.mapper_polygons[i], st.mapper_pixels[i]);
}

// A frame of a 3D scene: the picture and the frame's and the drawing's figures; with compare, the
// metrics measured polygon by polygon (docs/accuracy.md, 3D frames), and with diff their picture.
int render_world(const std::string& path, const std::string& text, const raster::Mapper* mapper, raster::Axis axis, int32_t n,
                 const std::string& out, bool compare, const std::string& diff) {
    LoadedWorld w = parse_world_text(text, path, world_search_path(path));
    auto frame = world_frame(w, n);
    std::printf("modexlab-render 1\nscene %s\nversion 2\nframe %d\n", path.c_str(), n);
    const raster::FrameStats& f = frame->stats;
    std::printf("faces %u\nculled %u\noutside %u\nclipped %u\npolygons %u\noverflow %u\n", f.faces, f.culled, f.outside, f.clipped,
                f.polygons, f.overflow);
    Picture ref(raster::SCREEN_WIDTH, raster::SCREEN_HEIGHT);
    raster::reference_frame(*frame, *w.textures, ref.view);
    IndexImage picture{ref.view.width, ref.view.height, ref.index};
    if (!mapper) {
        uint32_t covered = 0;
        for (uint8_t c : ref.coverage) covered += c ? 1 : 0;
        std::printf("mapper reference\npixels_drawn %u\n", covered);
    } else {
        raster::RenderStats stats;
        picture = render_world_frame(w, *frame, *mapper, axis, &stats);
        std::printf("mapper %s %s\n", mapper->name, axis == raster::Axis::Rows ? "rows" : "columns");
        std::printf("polygons_drawn %u\npolygons_skipped %u\npolygons_rejected %u\nspans %u\npixels_drawn %u\n", stats.polygons,
                    stats.skipped, stats.rejected, stats.spans, stats.pixels);
        print_drawn_by(stats);
        if (compare) {
            FrameMap map;
            print_metrics(measure_world_frame(w, *frame, *mapper, axis, &map));
            if (!diff.empty()) {
                std::vector<uint8_t> covers(map.kind.size()), drawn(map.kind.size());
                for (size_t i = 0; i < map.kind.size(); ++i)
                    covers[i] = map.kind[i] == FrameMap::GAP || map.kind[i] == FrameMap::COMPARED,
                    drawn[i] = map.kind[i] == FrameMap::OVERDRAW || map.kind[i] == FrameMap::COMPARED;
                save_png(diff, difference_picture({covers, drawn, ref.index, picture.index}, w.world->palette));
            }
        }
    }
    if (!out.empty()) save_png(out, colourise_with(picture, w.world->palette));
    return 0;
}

// The mapper a --mapper names, or nullptr for the reference.
const raster::Mapper* mapper_named(const std::string& name) {
    if (name == "reference") return nullptr;
    if (const raster::Mapper* m = raster::find_mapper({name.data(), name.size()})) return m;
    throw UsageError(unknown_mapper(name, {"reference"}));
}

int render(const std::vector<std::string>& words) {
    const CommandLine args = parse_command_line(words, {"--mapper", "--out", "--diff", "--frame", "--axis"}, {"--compare"});
    if (args.help()) return show_usage(USAGE);
    const int32_t frame = args.integer("--frame", 0, raster::MAX_FRAMES - 1, 0);
    raster::Axis axis = args.choice<raster::Axis>("--axis", {{"rows", raster::Axis::Rows}, {"columns", raster::Axis::Columns}},
                                                  raster::Axis::Rows);
    if (args.positionals().size() > 1) throw UsageError("more than one scene");
    if (args.positionals().empty()) throw UsageError("no scene");
    const std::string mapper_name = args.text("--mapper"), out = args.text("--out");
    const std::string diff = args.text("--diff");
    const bool compare_to_reference = args.has("--compare");
    if (mapper_name.empty()) throw UsageError("no --mapper");
    if (out.empty() && !compare_to_reference) throw UsageError("no --out (the picture) and no --compare (the metrics): nothing to do");
    if (!diff.empty() && !compare_to_reference) throw UsageError("--diff goes with --compare");
    const raster::Mapper* mapper = mapper_named(mapper_name);
    if (mapper) {
        if (!args.has("--axis")) axis = raster::home_axis(*mapper);
        if (!raster::mapper_walks(*mapper, axis))
            throw UsageError(mapper_name + " does not walk " + (axis == raster::Axis::Rows ? "rows" : "columns"));
    }
    std::string scene_path;
    try {
        scene_path = choose_scene(args.positionals()[0]).path;
    } catch (const HarnessError& e) {
        throw UsageError(e.what());
    }
    std::string text = read_whole_file(scene_path);
    raster::ParseError version_error;
    if (raster::scene_version(text.data(), text.size(), &version_error) == 2) return render_world(scene_path, text, mapper, axis, frame, out, compare_to_reference, diff);
    LoadedScene s = parse_scene_text(text, scene_path);
    const raster::Palette& pal = raster::palette(raster::PaletteId::Default);
    std::printf("modexlab-render 1\n");
    std::printf("scene %s\n", scene_path.c_str());
    std::printf("texture %s %dx%d %s\n", raster::texture_kind_name(s.scene->texture_kind), s.texture.width, s.texture.height,
                raster::wrap_name(s.texture.wrap));
    std::printf("polygons %d\n", s.scene->polygon_count);
    std::unique_ptr<Picture> ref = render_reference(s);
    if (!mapper) {
        if (!out.empty()) save_png(out, colourise(IndexImage{ref->view.width, ref->view.height, ref->index}, pal));
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
    if (!out.empty()) save_png(out, colourise(picture, pal));
    std::printf("mapper %s %s\n", mapper->name, axis == raster::Axis::Rows ? "rows" : "columns");
    std::printf("polygons_drawn %u\npolygons_skipped %u\npolygons_rejected %u\nspans %u\npixels_drawn %u\n", stats.polygons,
                stats.skipped, stats.rejected, stats.spans, stats.pixels);
    print_drawn_by(stats);
    if (!compare_to_reference) return 0;
    std::unique_ptr<Picture> drawn = measure_mapper(s, *mapper, axis);
    print_metrics(raster::compare_to_reference(ref->view, drawn->view, s.texture.width, s.texture.height, s.texture.wrap));
    if (!diff.empty()) save_png(diff, difference_picture({ref->coverage, drawn->coverage, ref->index, drawn->index}, pal));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return run_cli("modexlab-render", USAGE, argc, argv, render);
}
