// The scene parser: line by line, word by word, numbers as exact decimals.
#include "kernel/scene/scene.h"

#include "kernel/lib/fmt.h"
#include "kernel/lib/words.h"
#include "kernel/scene/scene_text.h"

namespace raster {

namespace {

using lib::StrView;
using scene_text::parse_decimal;
using scene_text::parse_int;

constexpr int MAX_LINE_WORDS = 4 + 5 * MAX_POLYGON_VERTICES;

struct Parser {
    Scene* scene;
    ParseError* error;
    int32_t line = 0;
    bool have_texture = false;

    bool fail(const lib::Fmt& m) { return scene_text::fail(error, line, m.c_str()); }
};

bool parse_vertex(Parser& p, const StrView* w, Vertex* v) {
    double x, y, wv, u, vv;
    const char* names[5] = {"x", "y", "w", "u", "v"};
    double* values[5] = {&x, &y, &wv, &u, &vv};
    for (int k = 0; k < 5; ++k)
        if (!parse_decimal(w[k], values[k]))
            return p.fail(lib::Fmt().s("bad number '").s(w[k]).s("' for ").s(names[k]).s(" (a decimal with at most 6 digits after the point)"));
    if (x < -MAX_COORD_PIXELS || x > MAX_COORD_PIXELS || y < -MAX_COORD_PIXELS || y > MAX_COORD_PIXELS)
        return p.fail(lib::Fmt().s("vertex x, y must lie within -16384..16384 pixels"));
    if (!(wv >= MIN_W && wv <= MAX_W)) return p.fail(lib::Fmt().s("w must lie within 1/65536..16777216 (w > 0)"));
    if (u < -MAX_UV || u > MAX_UV || vv < -MAX_UV || vv > MAX_UV) return p.fail(lib::Fmt().s("u, v must lie within -16777216..16777216 texels"));
    *v = Vertex{snap(x), snap(y), wv, u, vv};
    return true;
}

bool add_polygon(Parser& p, const StrView* w, size_t count, int32_t vertices) {
    Scene& s = *p.scene;
    if (count != size_t(5 * vertices))
        return p.fail(lib::Fmt().s("expected ").u(uint32_t(5 * vertices)).s(" numbers (x y w u v for each of ").u(uint32_t(vertices)).s(" vertices), found ").u(uint32_t(count)));
    if (s.polygon_count >= MAX_SCENE_POLYGONS) return p.fail(lib::Fmt().s("too many polygons (at most ").u(MAX_SCENE_POLYGONS).s(")"));
    if (s.vertex_count + vertices > MAX_SCENE_VERTICES) return p.fail(lib::Fmt().s("too many vertices (at most ").u(MAX_SCENE_VERTICES).s(")"));
    for (int32_t k = 0; k < vertices; ++k)
        if (!parse_vertex(p, w + 5 * k, &s.vertices[s.vertex_count + k])) return false;
    s.polygon_size[s.polygon_count++] = uint8_t(vertices);
    s.vertex_count += vertices;
    return true;
}

bool parse_line(Parser& p, const char* text) {
    StrView w[MAX_LINE_WORDS];
    size_t n = lib::split_words(text, w, MAX_LINE_WORDS);
    if (n == 0) return true;
    if (n > MAX_LINE_WORDS) return p.fail(lib::Fmt().s("too many words on one line"));
    Scene& s = *p.scene;
    if (w[0].equals("texture")) {
        if (p.have_texture) return p.fail(lib::Fmt().s("a second 'texture' line (version 1 scenes have one texture)"));
        if (n != 4) return p.fail(lib::Fmt().s("usage: texture checker|grid|numbered|xor|gradient WIDTH HEIGHT"));
        if (!texture_kind_from_name(w[1], &s.texture_kind))
            return p.fail(lib::Fmt().s("unknown texture '").s(w[1]).s("' (checker, grid, numbered, xor, gradient)"));
        if (!parse_int(w[2], 1, MAX_TEXTURE_SIZE, &s.texture_width) || !parse_int(w[3], 1, MAX_TEXTURE_SIZE, &s.texture_height))
            return p.fail(lib::Fmt().s("texture size '").s(w[2]).s(" ").s(w[3]).s("' out of range: width and height 1..1024"));
        p.have_texture = true;
        return true;
    }
    if (w[0].equals("wrap")) {
        if (n != 2 || !wrap_from_name(w[1], &s.wrap)) return p.fail(lib::Fmt().s("usage: wrap repeat|clamp"));
        return true;
    }
    if (w[0].equals("triangle")) return add_polygon(p, w + 1, n - 1, 3);
    if (w[0].equals("polygon")) {
        int32_t vertices;
        if (n < 2 || !parse_int(w[1], 3, MAX_POLYGON_VERTICES, &vertices))
            return p.fail(lib::Fmt().s("usage: polygon N (3..16) then x y w u v for each vertex"));
        return add_polygon(p, w + 2, n - 2, vertices);
    }
    return p.fail(lib::Fmt().s("unknown keyword '").s(w[0]).s("'"));
}

}  // namespace

bool parse_scene(const char* text, size_t length, Scene* scene, ParseError* error) {
    *error = ParseError{};
    scene->polygon_count = scene->vertex_count = 0;
    scene->wrap = Wrap::Repeat;
    Parser p{scene, error};
    if (length > MAX_SCENE_BYTES) return scene_text::fail(error, 0, "file too large (at most 1048576 bytes)");
    scene_text::Lines lines(text, length);
    char buf[scene_text::MAX_LINE + 1];
    int version = scene_text::read_header(lines, buf, error);
    if (version == 0) return false;
    if (version != 1)
        return scene_text::fail(error, lines.line, "a version 2 (3D) scene: load it as a world, not as a screen-space scene");
    bool ok = scene_text::each_line(lines, buf, error, [&](char* line) {
        p.line = lines.line;
        return parse_line(p, line);
    });
    if (!ok) return false;
    if (!p.have_texture) return scene_text::fail(error, 0, "no 'texture' line");
    return true;
}

}  // namespace raster
