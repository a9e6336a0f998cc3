// Test helpers for the raster core: random polygons, scenes built in code, per-pixel counts.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernel/core/render.h"
#include "kernel/core/setup.h"
#include "kernel/core/walk.h"
#include "qemu/accuracy/measure.h"

namespace rastertest {

using namespace raster;
using namespace harness;

// The unit tests run twice in make test, plainly and under AddressSanitizer and UBSan. The long
// arithmetic checks (bounds, auto's budgets) take a quarter of their cases under the sanitizers,
// which look for memory errors, not for numbers: the plain run takes them all. The test objects
// are the same in both programs (the Makefile sanitizes the code under test), so which one runs is
// asked at run time: ASan's runtime, in the sanitizer build alone, defines __asan_init.
extern "C" void __asan_init() __attribute__((weak));
inline const int SANITIZED_SHARE = __asan_init ? 4 : 1;

// A texture's copies as prepare_texture builds them (bordered; tiled and 64 KiB-aligned for
// power-of-two sides up to 256; doubled for power-of-two sides up to 1024), owned here, the texture
// pointed at them.
struct TextureCopies {
    std::vector<uint8_t> bordered, aligned, doubled;
    explicit TextureCopies(Texture* t)
        : bordered(size_t(bordered_bytes(t->width, t->height))), aligned(ALIGNED256_BYTES),
          doubled(gets_doubled(t->width, t->height) ? size_t(doubled_bytes(t->width, t->height)) : 0) {
        prepare_texture(t, bordered.data(), aligned.data(), doubled.empty() ? nullptr : doubled.data());
    }
};

// A repeating 256 x 256 texture (its texels 0) with the copies the mappers read.
struct Texture256 {
    std::vector<uint8_t> texels = std::vector<uint8_t>(256 * 256);
    Texture tex{texels.data(), 256, 256, Wrap::Repeat};
    TextureCopies copies{&tex};
};

// A target of the kind whose clip is the whole screen.
inline Target screen_target(Surface kind) {
    Target t = surface_kind(kind);
    t.clip = ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT};
    return t;
}

// The registry's mapper of that name (std::runtime_error where there is none).
inline const Mapper& mapper(const char* name) {
    const Mapper* m = find_mapper(name);
    if (!m) throw std::runtime_error(std::string("no mapper ") + name);
    return *m;
}

inline Vertex vertex_raw(int32_t x_raw, int32_t y_raw, double w = 1, double u = 0, double v = 0) {
    return Vertex{Fixed24_8::from_raw(x_raw), Fixed24_8::from_raw(y_raw), w, u, v};
}

inline Vertex vertex(double x, double y, double w = 1, double u = 0, double v = 0) { return Vertex{snap(x), snap(y), w, u, v}; }

// Random triangles around the screen (some partly outside), with perspective (w over a range of
// `depth_ratio`) and texture coordinates up to `uv_range` texels.
struct TriangleGen {
    std::mt19937 rng;
    double margin = 40, depth_ratio = 20, uv_range = 300;

    explicit TriangleGen(uint32_t seed) : rng(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
    Vertex random_vertex() {
        int32_t x = int32_t(uniform(-margin, SCREEN_WIDTH + margin) * 256);
        int32_t y = int32_t(uniform(-margin, SCREEN_HEIGHT + margin) * 256);
        double w = std::exp(uniform(0, std::log(depth_ratio))) * 0.5;
        return vertex_raw(x, y, w, uniform(-uv_range, uv_range), uniform(-uv_range, uv_range));
    }
    // A triangle of moderate size near a random point (whole-screen triangles are rarer). One in
    // three has its vertices on the half-pixel grid, so pixel centres fall exactly on its edges.
    std::vector<Vertex> triangle() {
        std::vector<Vertex> t;
        bool on_grid = rng() % 3 == 0;
        auto grid = [&](Vertex v) {
            if (on_grid) v = Vertex{Fixed24_8::from_raw(v.x.raw & ~127), Fixed24_8::from_raw(v.y.raw & ~127), v.w, v.u, v.v};
            return v;
        };
        if (rng() % 4 == 0) {
            for (int i = 0; i < 3; ++i) t.push_back(grid(random_vertex()));
            return t;
        }
        Vertex c = random_vertex();
        double size = std::exp(uniform(std::log(0.5), std::log(120.0)));
        for (int i = 0; i < 3; ++i) {
            Vertex v = random_vertex();
            v.x = Fixed24_8::from_raw(c.x.raw + int32_t(uniform(-size, size) * 256));
            v.y = Fixed24_8::from_raw(c.y.raw + int32_t(uniform(-size, size) * 256));
            t.push_back(grid(v));
        }
        return t;
    }
};

// The largest |u| and |v| of a polygon's corners (Frame::texel_most's, for one polygon).
inline double texel_most(const std::vector<Vertex>& p) {
    double most = 0;
    for (const Vertex& v : p) most = std::max({most, std::fabs(v.u), std::fabs(v.v)});
    return most;
}

inline std::unique_ptr<Scene> empty_scene(TextureKind kind, int32_t w, int32_t h, Wrap wrap) {
    auto s = std::make_unique<Scene>();
    s->texture_kind = kind;
    s->texture_width = w;
    s->texture_height = h;
    s->wrap = wrap;
    return s;
}

inline void add_polygon(Scene& s, const std::vector<Vertex>& p) {
    s.polygon_size[s.polygon_count++] = uint8_t(p.size());
    for (const Vertex& v : p) s.vertices[s.vertex_count++] = v;
}

// How often each screen pixel is visited by the walker's spans for these polygons.
inline std::vector<int> walk_counts(const std::vector<std::vector<Vertex>>& polygons, Axis axis,
                                    ClipRect clip = ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT}) {
    std::vector<int> counts(SCREEN_PIXELS, 0);
    for (const auto& p : polygons) {
        PolygonSetup s;
        if (setup_polygon(p.data(), int(p.size()), &s) != SetupStatus::Ok) continue;
        EdgeWalker w(s, axis, clip);
        Span span;
        while (w.next(&span))
            for (int32_t k = 0; k < span.count; ++k) {
                int32_t x = span.x + (axis == Axis::Rows ? k : 0), y = span.y + (axis == Axis::Columns ? k : 0);
                counts[size_t(y) * SCREEN_WIDTH + size_t(x)] += 1;
            }
    }
    return counts;
}

// A screen-space scene drawn by rows by the named mapper, against the reference.
inline AccuracyMetrics accuracy(const LoadedScene& s, const char* name) {
    auto ref = render_reference(s);
    return compare_to_reference(ref->view, measure_mapper(s, mapper(name), Axis::Rows)->view, s.texture.width, s.texture.height, s.texture.wrap);
}

}  // namespace rastertest
