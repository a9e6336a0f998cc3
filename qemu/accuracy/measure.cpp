// Scene loading and the pictures the metrics compare.
#include "qemu/accuracy/measure.h"
#include "qemu/lib/choice_lists.h"
#include "qemu/lib/command_line.h"
#include "qemu/lib/paths.h"
#include "kernel/core/bound.h"

#include "kernel/core/policy.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <list>
#include <map>
#include <mutex>
#include <fstream>
#include <sstream>
#include <tuple>

#include "qemu/lib/error.h"

namespace harness {

using namespace raster;

LoadedScene make_loaded_scene(std::unique_ptr<Scene> scene, const std::string& name) {
    LoadedScene s;
    s.name = name;
    s.scene = std::move(scene);
    s.texels.resize(size_t(s.scene->texture_width) * size_t(s.scene->texture_height));
    generate_texture(s.scene->texture_kind, s.scene->texture_width, s.scene->texture_height, s.texels.data());
    s.texture = Texture{s.texels.data(), s.scene->texture_width, s.scene->texture_height, s.scene->wrap};
    return s;
}

LoadedScene parse_scene_text(const std::string& text, const std::string& name) {
    auto scene = std::make_unique<Scene>();
    ParseError e;
    if (!parse_scene(text.data(), text.size(), scene.get(), &e))
        throw HarnessError(name + (e.line ? ":" + std::to_string(e.line) : std::string()) + ": " + e.message);
    return make_loaded_scene(std::move(scene), name);
}

std::string refusal(const raster::Mapper& m, const raster::RenderStats& st) {
    if (!st.rejected) return "";
    lib::Fmt needs;
    raster::describe_needs(needs, m.needs & raster::SCENE_NEEDS);
    const uint32_t all = st.polygons + st.skipped + st.rejected;
    std::string why = *needs.c_str() ? std::string(" (it needs ") + needs.c_str() + ")" : std::string();
    return st.polygons ? "Draws part of the frame: refuses " + std::to_string(st.rejected) + " of its " + std::to_string(all) + " polygons" + why + "."
                       : "Cannot draw this scene: refuses every polygon" + why + ".";
}

std::string read_whole_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw HarnessError(path + ": cannot open (" + std::strerror(errno) + ")");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

LoadedScene load_scene_file(const std::string& path) { return parse_scene_text(read_whole_file(path), path); }

namespace {

// Where a file the scene names was looked for, and the name it may have meant there: "(looked in
// A and B; is it 'tiles.bmp'?)".
std::string where_looked(const std::string& wanted, const std::vector<std::string>& search) {
    namespace fs = std::filesystem;
    std::string dirs;
    std::vector<std::string> names;
    const fs::path sub = fs::path(wanted).parent_path();
    for (size_t i = 0; i < search.size(); ++i) {
        dirs += (i == 0 ? "" : i + 1 == search.size() ? " and " : ", ") + search[i];
        std::error_code e;
        for (const fs::directory_entry& f : fs::directory_iterator(fs::path(search[i]) / sub, e))
            if (f.is_regular_file()) names.push_back((sub / f.path().filename()).string());
    }
    const std::string near = near_name(wanted, names);
    return "(looked in " + dirs + (near.empty() ? "" : "; is it '" + near + "'?") + ")";
}

}  // namespace

LoadedWorld parse_world_text(const std::string& text, const std::string& name, const std::vector<std::string>& search) {
    struct Finder {
        const std::vector<std::string>* search;
        std::map<std::string, std::string> read;  // the files read, kept while parsing
        std::string missing;                      // the last file not found
    } finder{&search, {}, {}};
    FileResolver r;
    r.context = &finder;
    r.find = [](const void* ctx, lib::StrView file, const uint8_t** data, size_t* size) {
        auto& f = *static_cast<Finder*>(const_cast<void*>(ctx));
        std::string wanted(file.data, file.size);
        for (const std::string& dir : *f.search) {
            std::filesystem::path p = std::filesystem::path(dir) / wanted;
            if (!std::filesystem::is_regular_file(p)) continue;
            std::string& bytes = f.read[wanted] = read_whole_file(p.string());
            *data = reinterpret_cast<const uint8_t*>(bytes.data()), *size = bytes.size();
            return true;
        }
        f.missing = wanted;
        return false;
    };
    LoadedWorld w;
    w.name = name;
    w.world = std::make_unique<HostWorld>();
    ParseError e;
    if (!parse_world(text.data(), text.size(), r, w.world.get(), &e))
        throw HarnessError(name + (e.line ? ":" + std::to_string(e.line) : std::string()) + ": " + e.message +
                           (finder.missing.empty() ? std::string() : " " + where_looked(finder.missing, search)));
    w.world->budget.lists = host_choice_lists();
    w.textures = std::make_unique<HostTextureSet>();
    build_texture_set(*w.world, w.textures.get());
    w.files = std::move(finder.read);
    return w;
}

void leave_out_doubled_copies(LoadedWorld& w) { build_texture_set(*w.world, w.textures.get(), false); }

std::vector<std::string> world_search_path(const std::string& scene_path) {
    std::string dir = std::filesystem::path(scene_path).parent_path().string();
    return {dir.empty() ? "." : dir, build_dir() + "/scenes"};
}

LoadedWorld load_world_file(const std::string& path) { return parse_world_text(read_whole_file(path), path, world_search_path(path)); }

std::unique_ptr<HostFrame> world_frame(const LoadedWorld& w, int32_t n) {
    auto frame = std::make_unique<HostFrame>();
    // build_frame's working memory, megabytes: one a thread, as the kernel keeps one
    static thread_local std::unique_ptr<HostFrameScratch> scratch = std::make_unique<HostFrameScratch>();
    build_frame(*w.world, n, frame.get(), scratch.get());
    return frame;
}

Picture::Picture(int32_t width, int32_t height)
    : index(size_t(width) * size_t(height)), coverage(index.size()), tu(index.size()), tv(index.size()), footprint(index.size()) {
    view = PixelImage{width, height, index.data(), coverage.data(), tu.data(), tv.data(), footprint.data()};
    clear_pixel_image(view, BACKGROUND);
}

std::unique_ptr<Picture> render_reference(const LoadedScene& s) {
    auto p = std::make_unique<Picture>(SCREEN_WIDTH, SCREEN_HEIGHT);
    reference_scene(*s.scene, s.texture, p->view);
    return p;
}

namespace {

// A 320x240 surface of the kind the mapper draws into (ram_planar).
struct HostSurface {
    bool planar;
    std::vector<uint8_t> data;
    HostSurface(const Mapper& m, Axis axis, uint8_t fill) : planar(ram_planar(m, axis)), data(SCREEN_PIXELS, fill) {}
    Target target() { return ram_target(data.data(), planar); }
    uint8_t& at(int32_t x, int32_t y) {
        return planar ? data[size_t(x & 3) * PLANE_BYTES + size_t(y) * PLANE_ROW_BYTES + size_t(x >> 2)]
                      : data[size_t(y) * SCREEN_WIDTH + size_t(x)];
    }
    std::vector<uint8_t> linear() const {
        if (!planar) return data;
        std::vector<uint8_t> out(SCREEN_PIXELS);
        linear_from_planar(data.data(), out.data());
        return out;
    }
};

// A texture with the copies the mappers read (prepare_texture).
struct HostTexture {
    Texture texture;
    std::vector<uint8_t> bordered, aligned, doubled;
    explicit HostTexture(const Texture& t)
        : texture(t), bordered(size_t(bordered_bytes(t.width, t.height))), aligned(ALIGNED256_BYTES),
          doubled(gets_doubled(t.width, t.height) ? size_t(doubled_bytes(t.width, t.height)) : 0) {
        prepare_texture(&texture, bordered.data(), aligned.data(), doubled.data());
    }
};

// A texture's stand-ins for measuring: ones (coverage) and four that hold their own coordinates
// (u low and high byte, v low and high byte), each with the copies the mapper reads.
struct MeasureTextures {
    std::vector<uint8_t> texels[5];
    std::unique_ptr<HostTexture> textures[5];
    size_t bytes = 0;  // all of them, copies included
    explicit MeasureTextures(const Texture& t) {
        const int32_t w = t.width, h = t.height;
        for (int k = 0; k < 5; ++k) {
            texels[k].resize(size_t(w) * size_t(h));
            for (int32_t v = 0; v < h; ++v)
                for (int32_t u = 0; u < w; ++u) {
                    int32_t c = k == 0 ? 1 : k < 3 ? u : v;
                    texels[k][size_t(v) * size_t(w) + size_t(u)] = uint8_t(k == 0 ? 1 : k % 2 ? c & 255 : c >> 8);
                }
            textures[k] = std::make_unique<HostTexture>(Texture{texels[k].data(), w, h, t.wrap});
            bytes += texels[k].size() + textures[k]->bordered.size() + textures[k]->aligned.size() + textures[k]->doubled.size();
        }
    }
};

// By what the stand-ins depend on, a texture's size and wrap (not its texels' address: a texture
// freed and another of another size allocated there would find the first one's stand-ins).
using StandInKey = std::tuple<int32_t, int32_t, Wrap>;

// The stand-ins for a texture, shared by every meter in the process: building them (five textures
// with their copies, tens of megabytes for the large ones) is most of a small polygon's measure.
// Those used last are kept, up to KEPT_BYTES (the newest whatever its size).
std::shared_ptr<const MeasureTextures> shared_stand_ins(const Texture& t) {
    constexpr size_t KEPT_BYTES = size_t(256) << 20;
    static std::mutex lock;
    static std::list<std::pair<StandInKey, std::shared_ptr<const MeasureTextures>>> recent;  // the last used first
    const StandInKey key{t.width, t.height, t.wrap};
    std::lock_guard<std::mutex> held(lock);
    auto it = std::find_if(recent.begin(), recent.end(), [&](const auto& e) { return e.first == key; });
    if (it != recent.end()) recent.splice(recent.begin(), recent, it);
    else recent.emplace_front(key, std::make_shared<const MeasureTextures>(t));
    size_t kept = 0;
    for (auto e = recent.begin(); e != recent.end();) {
        kept += e->second->bytes;
        e = e != recent.begin() && kept > KEPT_BYTES ? recent.erase(e) : std::next(e);
    }
    return recent.front().second;
}

// The pixels a polygon can touch: every mapper draws inside the box of its vertices, give or take
// a pixel; clipped to the screen.
struct Box {
    int32_t x0, y0, x1, y1;  // inclusive
    static Box around(const Vertex* v, int n) {
        int64_t min_x = v[0].x.raw, max_x = v[0].x.raw, min_y = v[0].y.raw, max_y = v[0].y.raw;
        for (int k = 1; k < n; ++k) {
            min_x = std::min<int64_t>(min_x, v[k].x.raw), max_x = std::max<int64_t>(max_x, v[k].x.raw);
            min_y = std::min<int64_t>(min_y, v[k].y.raw), max_y = std::max<int64_t>(max_y, v[k].y.raw);
        }
        return Box{int32_t(std::max<int64_t>(0, floor_div(min_x, SUBPIXEL_ONE) - 1)),
                   int32_t(std::max<int64_t>(0, floor_div(min_y, SUBPIXEL_ONE) - 1)),
                   int32_t(std::min<int64_t>(SCREEN_WIDTH - 1, floor_div(max_x, SUBPIXEL_ONE) + 1)),
                   int32_t(std::min<int64_t>(SCREEN_HEIGHT - 1, floor_div(max_y, SUBPIXEL_ONE) + 1))};
    }
    template <typename F>
    void each(F&& f) const {
        for (int32_t y = y0; y <= y1; ++y)
            for (int32_t x = x0; x <= x1; ++x) f(x, y);
    }
};

// The scene drawn with a texture prepared as the mapper reads it.
std::vector<uint8_t> draw_prepared(const LoadedScene& s, const Texture& prepared, const Mapper& mapper, Axis axis, RenderStats* stats) {
    HostSurface surface(mapper, axis, BACKGROUND);
    Target target = surface.target();
    RenderStats st = render_scene(*s.scene, prepared, mapper, axis, target);
    if (stats) *stats = st;
    return surface.linear();
}

std::vector<uint8_t> draw(const LoadedScene& s, const Texture& tex, const Mapper& mapper, Axis axis, RenderStats* stats) {
    HostTexture t(tex);
    return draw_prepared(s, t.texture, mapper, axis, stats);
}

}  // namespace

IndexImage render_world_frame(const LoadedWorld& w, const Frame& frame, const Mapper& mapper, Axis axis, RenderStats* stats) {
    HostSurface surface(mapper, axis, BACKGROUND);
    Target target = surface.target();
    RenderStats st = render_frame(frame, *w.textures, mapper, axis, target);
    if (stats) *stats = st;
    return IndexImage{SCREEN_WIDTH, SCREEN_HEIGHT, surface.linear()};
}

bool mapper_takes(const LoadedScene& s, const Mapper& mapper) {
    HostTexture t(s.texture);
    return mapper_accepts(mapper, t.texture);
}


IndexImage render_mapper(const LoadedScene& s, const Mapper& mapper, Axis axis, RenderStats* stats) {
    return IndexImage{SCREEN_WIDTH, SCREEN_HEIGHT, draw(s, s.texture, mapper, axis, stats)};
}

std::unique_ptr<Picture> measure_mapper(const LoadedScene& s, const Mapper& mapper, Axis axis) {
    auto p = std::make_unique<Picture>(SCREEN_WIDTH, SCREEN_HEIGHT);
    std::vector<uint8_t> indices = draw(s, s.texture, mapper, axis, nullptr);
    std::copy(indices.begin(), indices.end(), p->index.begin());

    // texel coordinates: four renders with the textures that hold their own coordinates
    const std::shared_ptr<const MeasureTextures> stand_in = shared_stand_ins(s.texture);
    std::vector<uint8_t> parts[4];
    for (int k = 0; k < 4; ++k) parts[k] = draw_prepared(s, stand_in->textures[k + 1]->texture, mapper, axis, nullptr);
    for (size_t i = 0; i < p->index.size(); ++i) {
        p->tu[i] = parts[0][i] | (parts[1][i] << 8);
        p->tv[i] = parts[2][i] | (parts[3][i] << 8);
    }

    // coverage counts: each polygon alone on a scratch surface, with the texture of ones of the
    // scene's size (mappers that cannot wrap check coordinates against it)
    HostSurface scratch(mapper, axis, 0);
    const Texture& ones_texture = stand_in->textures[0]->texture;
    Target t = scratch.target();
    const Vertex* v = s.scene->vertices;
    RenderStats ignored;
    for (int32_t i = 0; i < s.scene->polygon_count; ++i) {
        int n = s.scene->polygon_size[i];
        if (draw_polygon(v, n, ones_texture, mapper, axis, t, &ignored) == SetupStatus::Ok) {
            Box::around(v, n).each([&](int32_t x, int32_t y) {
                uint8_t& c = scratch.at(x, y);
                size_t i2 = size_t(y) * SCREEN_WIDTH + size_t(x);
                if (c && p->coverage[i2] < 255) ++p->coverage[i2];
                c = 0;
            });
        }
        v += n;
    }
    for (size_t i = 0; i < p->index.size(); ++i)
        if (!p->coverage[i]) p->tu[i] = p->tv[i] = -1;
    return p;
}

// A meter's pictures: measure() leaves them cleared, so a meter that ends hands them to the next
// one of its thread (the same layout), which saves clearing megabytes a frame. Its stand-ins are
// the meter's own shortcut into shared_stand_ins, dropped at its end: that cache alone keeps them.
struct PolygonMeter::Parts {
    Picture ref{SCREEN_WIDTH, SCREEN_HEIGHT};  // one polygon at a time
    std::vector<HostSurface> scratch;
    std::map<StandInKey, std::shared_ptr<const MeasureTextures>> stand_ins;
};

namespace {
thread_local std::vector<std::unique_ptr<PolygonMeter::Parts>> spare_parts;
constexpr size_t SPARE_PARTS = 4;
}  // namespace

PolygonMeter::PolygonMeter(const Mapper& mapper, Axis axis, const Budget& budget) : mapper_(mapper), axis_(axis), budget_(budget) {
    const bool planar = ram_planar(mapper, axis);
    for (auto it = spare_parts.begin(); it != spare_parts.end(); ++it)
        if ((*it)->scratch[0].planar == planar) {
            parts_ = std::move(*it);
            spare_parts.erase(it);
            return;
        }
    parts_ = std::make_unique<Parts>();
    for (int k = 0; k < 5; ++k) parts_->scratch.emplace_back(mapper, axis, 0);
}

PolygonMeter::~PolygonMeter() {
    if (!parts_) return;
    parts_->stand_ins.clear();
    if (spare_parts.size() == SPARE_PARTS) spare_parts.erase(spare_parts.begin());
    spare_parts.push_back(std::move(parts_));
}

AccuracyMetrics PolygonMeter::measure(const Vertex* v, int n, const Texture& tex, bool* drawn_out, const PixelFn& pixel,
                                      RenderStats* stats) {
    Parts& p = *parts_;
    auto& stand_in = p.stand_ins[{tex.width, tex.height, tex.wrap}];
    if (!stand_in) stand_in = shared_stand_ins(tex);
    reference_polygon(v, n, tex, p.ref.view);
    bool drawn = true;
    for (int k = 0; k < 5 && drawn; ++k) {
        Target t = p.scratch[size_t(k)].target();
        RenderStats st;
        drawn = draw_polygon(v, n, stand_in->textures[k]->texture, mapper_, axis_, t, &st, Variant::Twin, budget_) == SetupStatus::Ok;
        if (k == 0 && stats) *stats = st;
    }
    AccuracyMetrics m;
    Box::around(v, n).each([&](int32_t x, int32_t y) {
        size_t i = size_t(y) * SCREEN_WIDTH + size_t(x);
        bool rc = p.ref.coverage[i] != 0, dc = drawn && p.scratch[0].at(x, y) != 0;
        double fe = 0;
        if (rc && dc) {
            int32_t tu = p.scratch[1].at(x, y) | (p.scratch[2].at(x, y) << 8), tv = p.scratch[3].at(x, y) | (p.scratch[4].at(x, y) << 8);
            bool folded;
            uint32_t e = texel_error(p.ref.tu[i], p.ref.tv[i], tu, tv, tex.width, tex.height, tex.wrap, &folded);
            add_texel_error(m, e, double(p.ref.footprint[i]), folded);
            fe = footprint_error(e, double(p.ref.footprint[i]));
        }
        if (pixel) pixel(x, y, rc, dc, fe);
        p.ref.coverage[i] = 0;
        for (HostSurface& s : p.scratch) s.at(x, y) = 0;
    });
    finish_metrics(m);
    if (drawn_out) *drawn_out = drawn;
    return m;
}

FrameBound world_frame_bound(const LoadedWorld& w, const Frame& frame, const Mapper& mapper, Axis axis) {
    FrameBound f;
    const Vertex* v = frame.vertices;
    for (int32_t i = 0; i < frame.polygon_count; v += frame.polygon_size[i], ++i) {
        const BoundContext c{mapper, w.textures->objects[frame.polygon_object[i]], axis, ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT}};
        const ErrorBound b = mapper.bound(c, v, frame.polygon_size[i]);
        if (!b.draws) continue;  // (refused: the row says so by its rejected polygons; or degenerate)
        f.footprint = b.footprint > f.footprint ? b.footprint : f.footprint;
        f.exact_coverage = f.exact_coverage && b.exact_coverage;
    }
    return f;
}

AccuracyMetrics measure_world_frame(const LoadedWorld& w, const Frame& frame, const Mapper& mapper, Axis axis, FrameMap* map) {
    AccuracyMetrics m;
    std::vector<uint8_t> ref_count(SCREEN_PIXELS, 0), drawn_count(SCREEN_PIXELS, 0);
    if (map) {
        map->kind.assign(SCREEN_PIXELS, FrameMap::UNCOVERED);
        map->footprint_error.assign(SCREEN_PIXELS, 0.0);
        map->drawn_by.assign(SCREEN_PIXELS, -1);
        map->polygons.clear();
    }
    PolygonMeter meter(mapper, axis, frame.budget);
    const Vertex* v = frame.vertices;
    for (int32_t i = 0; i < frame.polygon_count; ++i) {
        const int n = frame.polygon_size[i];
        bool drawn = false;
        RenderStats stats;
        AccuracyMetrics one = meter.measure(v, n, w.textures->objects[frame.polygon_object[i]], &drawn,
                                            [&](int32_t x, int32_t y, bool rc, bool dc, double fe) {
                                                size_t p = size_t(y) * SCREEN_WIDTH + size_t(x);
                                                if (rc && ref_count[p] < 255) ++ref_count[p];
                                                if (dc && drawn_count[p] < 255) ++drawn_count[p];
                                                if (!map || !(rc || dc)) return;
                                                map->kind[p] = rc && dc ? FrameMap::COMPARED : rc ? FrameMap::GAP : FrameMap::OVERDRAW;
                                                map->footprint_error[p] = fe;
                                                if (dc) map->drawn_by[p] = i;
                                            }, &stats);
        if (map) {
            const Mapper* by = nullptr;
            for (int row = 0; row < MAPPER_COUNT && drawn; ++row)
                if (stats.mapper_polygons[row]) by = &MAPPERS[row];
            map->polygons.push_back({by, stats.spans, stats.pixels});
        }
        merge(m, one);
        v += n;
    }
    finish_metrics(m);
    for (size_t p = 0; p < size_t(SCREEN_PIXELS); ++p) add_coverage(m, ref_count[p], drawn_count[p]);

    // the palette indices: the whole pictures
    Picture whole(SCREEN_WIDTH, SCREEN_HEIGHT);
    reference_frame(frame, *w.textures, whole.view);
    IndexImage mine = render_world_frame(w, frame, mapper, axis);
    for (size_t p = 0; p < size_t(SCREEN_PIXELS); ++p) {
        if (!whole.coverage[p] && !drawn_count[p]) continue;
        ++m.union_pixels;
        if (whole.index[p] != mine.index[p]) ++m.index_differs;
    }
    return m;
}

}  // namespace harness
