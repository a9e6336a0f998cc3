// Host-side rendering of screen-space scenes: loading scene files, the reference picture, a
// mapper's picture, and what a mapper drew measured pixel by pixel for the accuracy metrics.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "kernel/scene/frame.h"
#include "kernel/core/mapper.h"
#include "kernel/core/policy.h"
#include "qemu/accuracy/metrics.h"
#include "qemu/accuracy/reference.h"
#include "kernel/core/render.h"
#include "kernel/scene/scene.h"
#include "qemu/lib/host_image.h"

namespace harness {

struct LoadedScene {
    std::string name;
    std::unique_ptr<raster::Scene> scene;
    std::vector<uint8_t> texels;
    raster::Texture texture;
};

// Throws HarnessError "NAME:LINE: message" (the parser's message) on a bad scene.
LoadedScene parse_scene_text(const std::string& text, const std::string& name);
// A scene built in code: generates its texture.
LoadedScene make_loaded_scene(std::unique_ptr<raster::Scene> scene, const std::string& name);
LoadedScene load_scene_file(const std::string& path);

// A PixelImage with its own storage.
struct Picture {
    std::vector<uint8_t> index, coverage;
    std::vector<int32_t> tu, tv;
    std::vector<float> footprint;
    raster::PixelImage view;
    Picture(int32_t width, int32_t height);
    Picture(const Picture&) = delete;
    Picture& operator=(const Picture&) = delete;
};

constexpr uint8_t BACKGROUND = 0;  // the colour a picture is cleared to before drawing

std::unique_ptr<Picture> render_reference(const LoadedScene& s);

// Whether the mapper takes the scene's texture, given the copies the host builds for it (bordered,
// 64 KiB-aligned): what the kernel's `render` accepts.
bool mapper_takes(const LoadedScene& s, const raster::Mapper& mapper);

// The mapper's picture on a cleared 320x240 surface (linear, or planes for mappers that write
// planes), as a linear picture (rows or columns); stats if wanted.
IndexImage render_mapper(const LoadedScene& s, const raster::Mapper& mapper, raster::Axis axis, raster::RenderStats* stats = nullptr);

// What the mapper drew: its palette indices, how often each pixel was drawn (one polygon at a
// time on a scratch surface), and the texel it read (from renders with coordinate textures whose
// texels hold their own coordinates, 8 bits at a time). Only the mapper's drawing path is used.
std::unique_ptr<Picture> measure_mapper(const LoadedScene& s, const raster::Mapper& mapper, raster::Axis axis);

// A 3D scene (version 2) on the host, its texture files found in `search` directories in order,
// with the textures as the mappers take them.
struct LoadedWorld {
    std::string name;
    std::unique_ptr<raster::HostWorld> world;
    std::unique_ptr<raster::HostTextureSet> textures;
    std::map<std::string, std::string> files;  // the files it read (texture images), by the name the scene gave, and their bytes
};

// Throws HarnessError "NAME:LINE: message" on a bad scene or a texture file it cannot read.
LoadedWorld parse_world_text(const std::string& text, const std::string& name, const std::vector<std::string>& search);
// The file's own directory first, then <build>/scenes (the files made at build time).
LoadedWorld load_world_file(const std::string& path);
// The textures without their doubled copies, as the kernel has them where memory is short.
void leave_out_doubled_copies(LoadedWorld& w);
std::vector<std::string> world_search_path(const std::string& scene_path);

// Frame n, as the kernel builds it.
std::unique_ptr<raster::HostFrame> world_frame(const LoadedWorld& w, int32_t n);

// The frame drawn with the mapper on a cleared surface (linear, or planes for mappers that write
// planes), as a linear picture in the scene's palette indices.
IndexImage render_world_frame(const LoadedWorld& w, const raster::Frame& frame, const raster::Mapper& mapper, raster::Axis axis,
                              raster::RenderStats* stats = nullptr);

// A mapper's polygons measured one at a time against the reference: the texel and footprint
// errors on the pixels both cover (only the mapper's drawing path is used: five renders, with a
// texture of ones and four that hold their own coordinates). `pixel` sees, for every pixel of
// the polygon's box, whether the reference and the mapper cover it and, where both do, its
// footprint error (0 elsewhere). `stats` gets the statistics of the first render: the polygon's
// spans and pixels and, in mapper_polygons, the mapper that drew it (auto: the one it chose).
// auto chooses for `budget`.
class PolygonMeter {
public:
    using PixelFn = std::function<void(int32_t x, int32_t y, bool rc, bool dc, double footprint_error)>;
    PolygonMeter(const raster::Mapper& mapper, raster::Axis axis, const raster::Budget& budget = raster::DEFAULT_BUDGET);
    ~PolygonMeter();
    raster::AccuracyMetrics measure(const raster::Vertex* v, int n, const raster::Texture& tex, bool* drawn = nullptr,
                                    const PixelFn& pixel = {}, raster::RenderStats* stats = nullptr);

    struct Parts;

private:
    const raster::Mapper& mapper_;
    raster::Axis axis_;
    raster::Budget budget_;
    std::unique_ptr<Parts> parts_;
};

// What the mapper draws of a frame against the reference (docs/accuracy.md, 3D frames): each
// polygon alone, its texel errors on the pixels both cover for it, with its own texture's size and
// wrap; coverage counts summed over the polygons; palette indices on the whole pictures. auto
// chooses for the frame's budget.
// With `map`, also what it saw where (the gallery's maps): the figures stay the same.
struct FrameMap {
    enum Kind : uint8_t { UNCOVERED, GAP, OVERDRAW, COMPARED };  // UNCOVERED: the background
    // Per pixel (row-major, 320x240), from the last polygon in drawing order that the reference or
    // the mapper covers there (the one the pictures show): a gap (the reference's, not drawn),
    // overdraw (drawn, not the reference's) or compared, with its footprint error.
    std::vector<uint8_t> kind;
    std::vector<double> footprint_error;
    std::vector<int32_t> drawn_by;  // the last polygon that drew the pixel; -1: none
    // Per polygon of the frame, in order: the mapper that drew it (auto: its choice; nullptr: not
    // drawn, refused or degenerate), its spans and pixels.
    struct Polygon {
        const raster::Mapper* mapper;
        uint32_t spans, pixels;
    };
    std::vector<Polygon> polygons;
    // The mapper that drew pixel p last, or nullptr.
    const raster::Mapper* mapper_at(size_t p) const { return drawn_by[p] < 0 ? nullptr : polygons[size_t(drawn_by[p])].mapper; }
};
raster::AccuracyMetrics measure_world_frame(const LoadedWorld& w, const raster::Frame& frame, const raster::Mapper& mapper,
                                            raster::Axis axis, FrameMap* map = nullptr);

// What a single mapper proves on a frame before drawing it: the largest of its error bounds
// (footprints, the tightest it gives) over the polygons it draws, NO_BOUND where one has none, and
// whether every one of them promises exact coverage (docs/bounds.md); the
// screen's clip.
struct FrameBound {
    double footprint = 0;
    bool exact_coverage = true;
};
FrameBound world_frame_bound(const LoadedWorld& w, const raster::Frame& frame, const raster::Mapper& mapper, raster::Axis axis);

// Why the mapper did not draw every polygon it was given (its stats), or "": "Cannot draw this
// scene: refuses every polygon (it needs ...)." or "Draws part of the frame: refuses R of its N
// polygons (it needs ...)." (the needs: what a scene can fail to give, raster::SCENE_NEEDS).
std::string refusal(const raster::Mapper& m, const raster::RenderStats& st);

// Reads a whole file; throws HarnessError when it cannot.
std::string read_whole_file(const std::string& path);

}  // namespace harness
