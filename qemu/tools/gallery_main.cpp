// modexlab-gallery: for each demo scene an HTML page (opened from disk, no server) with every
// mapper's frame beside its footprint-error map, fastest first, and auto at each budget with the
// mapper that drew each pixel; all drawn on the host by the kernel's own code (docs/bench.md,
// "The gallery").
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "qemu/accuracy/measure.h"
#include "qemu/harness/session.h"
#include "qemu/lib/command_line.h"
#include "qemu/lib/error.h"
#include "qemu/tools/demo_scenes.h"
#include "qemu/tools/gallery.h"
#include "qemu/tools/trade.h"

namespace {

using namespace harness;

const char* USAGE =
    "usage: modexlab-gallery [--scenes NAME,...] [--mappers NAME,...] [--frame N] [--report DIR] [--out DIR]\n"
    "  --scenes   demo scenes (default: all; modexlab-scene list) or scene files\n"
    "  --mappers  mappers (default: all of the registry; auto brings its budgets 0, 0.5, 1, 2, 4)\n"
    "  --frame    the frame shown (default: the middle of each scene's animation, one the bench measures)\n"
    "  --report   a make bench report whose trade.csv gives the speeds (default build/report; without\n"
    "             one, the cost model's estimates)\n"
    "  --out      where the gallery goes (default build/gallery): index.html, SCENE.html, img/\n";

struct Args {
    std::vector<std::string> scenes, mappers;
    int frame = -1;
    std::string report, out;
};

std::optional<Args> parse(const std::vector<std::string>& words) {
    const CommandLine args = parse_command_line(words, {"--scenes", "--mappers", "--frame", "--report", "--out"}, {});
    if (args.help()) return std::nullopt;
    if (!args.positionals().empty()) throw UsageError("unexpected argument '" + args.positionals()[0] + "'");
    Args a;
    a.scenes = args.list("--scenes");
    a.mappers = known_mappers(args.list("--mappers"));
    a.frame = args.integer("--frame", 0, raster::MAX_FRAMES - 1, -1);
    a.report = args.text("--report", build_dir() + "/report");
    a.out = args.text("--out", build_dir() + "/gallery");
    if (a.scenes.empty())
        for (const DemoScene& d : demo_scenes()) a.scenes.push_back(d.name);
    if (a.mappers.empty())
        for (int i = 0; i < raster::MAPPER_COUNT; ++i) a.mappers.push_back(raster::MAPPERS[i].name);
    return a;
}

// A mapper's card: the frame drawn whole and measured polygon by polygon, auto at `budget`.
GalleryCard mapper_card(const LoadedWorld& w, raster::Frame& frame, const raster::Mapper& m, const raster::Budget& budget, bool at_budget) {
    GalleryCard c;
    c.mapper = &m, c.budget = budget, c.at_budget = at_budget;
    c.title = m.name + (at_budget ? "@" + budget_text(budget.max_error) : std::string());
    c.file = m.name + (at_budget ? "-at-" + budget_text(budget.max_error) : std::string());
    const raster::Budget scene_budget = frame.budget;
    frame.budget = budget;
    const raster::Axis axis = raster::home_axis(m);
    c.picture = render_world_frame(w, frame, m, axis, &c.stats);
    c.metrics = measure_world_frame(w, frame, m, axis, &c.map);
    frame.budget = scene_budget;
    c.refused = refusal(m, c.stats);
    return c;
}

GalleryPage scene_page(const std::string& spec, const Args& a) {
    const SceneChoice choice = choose_scene(spec);
    const LoadedWorld w = load_world_file(choice.path);
    GalleryPage page;
    page.scene = choice.name, page.exercises = choice.demo ? choice.demo->exercises : "";
    page.frames = w.world->frames;
    page.frame = a.frame >= 0 ? a.frame : page.frames / 2;
    if (page.frame >= page.frames)
        throw HarnessError(choice.path + ": frame " + std::to_string(page.frame) + " is beyond its " + std::to_string(page.frames) + " frames");
    page.budget = budget_words(w.world->budget);
    auto frame = world_frame(w, page.frame);

    GalleryCard ref;
    ref.title = ref.file = "reference";
    Picture whole(raster::SCREEN_WIDTH, raster::SCREEN_HEIGHT);
    raster::reference_frame(*frame, *w.textures, whole.view);
    ref.picture = IndexImage{raster::SCREEN_WIDTH, raster::SCREEN_HEIGHT, whole.index};
    for (uint8_t covered : whole.coverage) ref.reference_pixels += covered != 0;
    page.cards.push_back(std::move(ref));

    auto progress = [&](const GalleryCard& c) {
        const raster::AccuracyMetrics& m = c.metrics;
        std::printf("%s %s: footprint error max %.3f, mean %.4f; gaps %u, overdraw %u%s\n", page.scene.c_str(), c.title.c_str(),
                    m.max_footprint_error, m.mean_footprint_error, m.gaps, m.overdraw, c.refused.empty() ? "" : "; refuses polygons");
        std::fflush(stdout);
    };
    for (const std::string& name : a.mappers) {
        const raster::Mapper& m = *raster::find_mapper({name.data(), name.size()});
        page.cards.push_back(mapper_card(w, *frame, m, frame->budget, false));
        progress(page.cards.back());
    }
    for (const std::string& name : a.mappers) {
        const raster::Mapper& m = *raster::find_mapper({name.data(), name.size()});
        if (!m.is_auto) continue;
        for (double e : AUTO_BUDGETS) {
            page.cards.push_back(mapper_card(w, *frame, m, raster::Budget{true, e, true}, true));
            progress(page.cards.back());
        }
    }
    rank_cards(page, read_speeds(a.report));
    write_page(a.out, page, w.world->palette);
    std::printf("%s: %s/%s.html (speeds %s)\n", page.scene.c_str(), a.out.c_str(), page.scene.c_str(),
                page.measured ? "measured by make bench" : "estimated by the cost model");
    return page;
}

int run(const Args& a) {
    std::vector<GalleryPage> pages;
    for (const std::string& spec : a.scenes) {
        GalleryPage page = scene_page(spec, a);
        for (GalleryCard& c : page.cards) c.map = {}, c.picture = {}, c.metrics = {};  // the index needs names and counts only
        pages.push_back(std::move(page));
    }
    write_index(a.out, pages);
    std::printf("gallery: %s/index.html (%zu %s)\n", a.out.c_str(), pages.size(), pages.size() == 1 ? "scene" : "scenes");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return run_cli("modexlab-gallery", USAGE, argc, argv, [](const std::vector<std::string>& words) {
        std::optional<Args> a = parse(words);
        return a ? run(*a) : show_usage(USAGE);
    });
}
