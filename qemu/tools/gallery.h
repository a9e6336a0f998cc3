// The gallery (make gallery; docs/bench.md, "The gallery"): for each scene one HTML page with every
// mapper's frame beside its footprint-error map, sorted by speed, and auto at each budget with a
// map of the mapper that drew each pixel. The colour scales here are the pages' legends and what
// the tests read the maps back with.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "qemu/accuracy/measure.h"
#include "qemu/lib/host_image.h"

namespace harness {

struct Colour {
    uint8_t r, g, b;
    bool operator==(const Colour&) const = default;
};

// The footprint-error scale: a compared pixel takes the first bin whose limit its error does not
// exceed (0 exactly, then up to 0.25, 0.5, 1, 2, 4, 8 footprints, then beyond); luminance rises
// with the error. Bins end where budgets do: auto at budget 1 shows nothing past "≤ 1".
struct ErrorBin {
    double limit;  // the bin holds errors up to and including it (the last: any)
    Colour colour;
    const char* label;
};
extern const ErrorBin ERROR_BINS[];
extern const int ERROR_BIN_COUNT;
const Colour& error_colour(double footprint_error);

// The pixels an error map does not compare.
inline constexpr Colour BACKGROUND_COLOUR{0, 0, 0};    // covered by neither
inline constexpr Colour GAP_COLOUR{47, 111, 255};      // the reference's, not drawn
inline constexpr Colour OVERDRAW_COLOUR{255, 255, 0};  // drawn, not the reference's

// A colour a registry row (the mapper map); background black.
Colour mapper_colour(const raster::Mapper& m);

// The maps of a measured frame, 320x240: the footprint error (or gap, overdraw, background) of
// each pixel, and the mapper that drew it.
RgbImage error_map_image(const FrameMap& map);
RgbImage mapper_map_image(const FrameMap& map);

// One picture of a page: the reference, a mapper at the scene's budget or auto at one of its own.
struct GalleryCard {
    std::string title;                    // "affine", "auto@0.5", "reference"
    std::string file;                     // its images' stem: "affine", "auto-at-0.5", "reference"
    const raster::Mapper* mapper = nullptr;  // nullptr: the reference
    bool at_budget = false;               // auto at a budget of its own (AUTO_BUDGETS), not the scene's
    raster::Budget budget;                // what auto drew to
    IndexImage picture;                   // the frame drawn whole, in the scene's palette
    raster::RenderStats stats;            // its statistics
    raster::AccuracyMetrics metrics;      // measured polygon by polygon (measure_world_frame)
    FrameMap map;
    double speed = -1;                    // draw instructions per pixel; below 0: none
    uint32_t reference_pixels = 0;        // the reference card: the pixels it covers
    std::string refused;                  // why it does not draw every polygon ("": it does)
};

struct GalleryPage {
    std::string scene, exercises;  // the scene's name and what it is for ("" for a file)
    int32_t frame = 0, frames = 0;  // the frame shown, of the animation's
    std::string budget;             // the scene's, in words
    bool measured = false;          // speeds from a bench report, else the cost model's
    std::string speed_source;       // where they come from, in words
    std::vector<GalleryCard> cards; // the reference, the mappers fastest first, then auto's budgets
};

// The speeds of a bench report (DIR/trade.csv): draw instructions per pixel by scene and row
// ("auto@0.5"); found false when there is no report. Throws HarnessError for a file that is not one.
struct MeasuredSpeeds {
    bool found = false;
    std::string path;
    struct Row {
        std::string scene, mapper;
        double draw_per_pixel;
        uint64_t pixels, frames;
    };
    std::vector<Row> rows;
    const Row* find(const std::string& scene, const std::string& mapper) const;
};
MeasuredSpeeds read_speeds(const std::string& report_dir);

// The cost model's estimate (kernel/mappers/auto/costs.cpp) of draw instructions per pixel for the
// polygons as the map records them (each by the mapper that drew it; auto's own choosing is not
// in the model); below 0 when a mapper drew nothing or was not measured.
double estimated_speed(const FrameMap& map);

// Sets every card's speed, from the report when it has a row for every card of the scene, else
// from the cost model, and says which in page.speed_source; sorts the mappers' cards fastest first
// (those that draw nothing last), the reference first, auto's budgets last in their order.
void rank_cards(GalleryPage& page, const MeasuredSpeeds& speeds);

// DIR/SCENE.html with its images in DIR/img/ (file:// links only; a script of its own for the
// tools below, whose state the page's address keeps after '#').
void write_page(const std::string& dir, const GalleryPage& page, const raster::Palette& palette);

// The page's tools (gallery_view.cpp): the summary table, one row a mapper card, sortable by speed,
// max and mean footprint error and the Pareto front (#sort=speed|max|mean|pareto); the plot of
// speed against mean footprint error (inline SVG, both axes log, names placed apart: place_labels);
// two mappers compared (#compare=A,B): their difference (CSS difference blending: black where they
// agree), each flickering against the exact picture (#flicker=1), a region 4 times larger pixel
// for pixel (#zoom=X,Y); with the style and the script they need.
std::string summary_html(const GalleryPage& page);
std::string plot_svg(const GalleryPage& page);
std::string compare_html(const GalleryPage& page);
extern const char* const TOOLS_STYLE;
extern const char* const PAGE_SCRIPT;

// HTML-escaped text; the path of a card's image ("frame", "error", "mappers"; "" the reference's).
std::string escape(const std::string& s);
std::string image_path(const GalleryPage& page, const GalleryCard& card, const char* what);
// DIR/index.html: a link and a thumbnail a scene.
void write_index(const std::string& dir, const std::vector<GalleryPage>& pages);

}  // namespace harness
