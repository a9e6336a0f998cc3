// The demo scenes as code, and the OBJ converter.
#include "qemu/tools/demo_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>

#include "kernel/scene/world.h"
#include "qemu/accuracy/measure.h"
#include "qemu/harness/session.h"
#include "qemu/lib/command_line.h"
#include "qemu/lib/error.h"

namespace harness {

namespace {

// A decimal the scene parser takes: at most 6 digits after the point, trailing zeros trimmed.
std::string num(double x) {
    if (std::fabs(x) < 5e-7) x = 0;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f", x);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    if (s == "-0") s = "0";
    return s;
}

struct P3 {
    double x, y, z;
};
P3 sub(P3 a, P3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
P3 cross3(P3 a, P3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dot3(P3 a, P3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

using FaceCorners = std::vector<std::pair<P3, std::pair<double, double>>>;

// A planar face with texture coordinates affine over it, cut along the lines where u or v (axis 0,
// 1) is a whole number of periods: pieces each within one period along both, as the tools of the
// classics cut their surfaces (Quake's qbsp into pieces of at most 240 texels), so that a loop that
// cannot wrap draws every piece after a whole-period shift. Cut points are interpolated along the
// edges and take the whole number exactly.
std::vector<FaceCorners> cut_by_periods(const FaceCorners& face, int axis = 0) {
    if (axis == 2) return {face};
    auto t = [&](const std::pair<P3, std::pair<double, double>>& c) { return axis == 0 ? c.second.first : c.second.second; };
    double lo = t(face[0]), hi = lo;
    for (const auto& c : face) lo = std::min(lo, t(c)), hi = std::max(hi, t(c));
    const double k = std::floor(lo) + 1;  // the first whole number above the least
    if (!(k < hi - 1e-9)) return cut_by_periods(face, axis + 1);
    FaceCorners below, above;
    for (size_t i = 0; i < face.size(); ++i) {
        const auto& a = face[i];
        const auto& b = face[(i + 1) % face.size()];
        if (t(a) <= k) below.push_back(a);
        if (t(a) >= k) above.push_back(a);  // (a corner on the line belongs to both)
        if ((t(a) < k && t(b) > k) || (t(a) > k && t(b) < k)) {
            const double f = (k - t(a)) / (t(b) - t(a));
            auto mix = [&](double x, double y) { return x + (y - x) * f; };
            std::pair<P3, std::pair<double, double>> c{{mix(a.first.x, b.first.x), mix(a.first.y, b.first.y), mix(a.first.z, b.first.z)},
                                                        {mix(a.second.first, b.second.first), mix(a.second.second, b.second.second)}};
            (axis == 0 ? c.second.first : c.second.second) = k;
            below.push_back(c);
            above.push_back(c);
        }
    }
    std::vector<FaceCorners> out = cut_by_periods(below, axis + 1);
    for (FaceCorners& piece : cut_by_periods(above, axis)) out.push_back(std::move(piece));
    return out;
}

// A mesh being made: positions and texture coordinates shared by value, faces as corner lists.
class MeshMaker {
public:
    // cut: every face cut along its texture's period lines (cut_by_periods)
    explicit MeshMaker(std::string name, bool cut = false) : name_(std::move(name)), cut_(cut) {}
    int position(P3 p) { return index(positions_, {num(p.x), num(p.y), num(p.z)}); }
    int uv(double u, double v) { return index(uvs_, {num(u), num(v)}); }
    // Adds a face given in any winding; `outward` is a direction its front must face.
    void face(FaceCorners corners, P3 outward) {
        if (cut_) {
            cut_ = false;
            for (FaceCorners& piece : cut_by_periods(corners)) face(std::move(piece), outward);
            cut_ = true;
            return;
        }
        P3 n = cross3(sub(corners[1].first, corners[0].first), sub(corners[2].first, corners[0].first));
        if (dot3(n, outward) < 0) std::reverse(corners.begin(), corners.end());
        std::vector<std::pair<int, int>> f;
        for (const auto& c : corners) f.push_back({position(c.first), uv(c.second.first, c.second.second)});
        faces_.push_back(f);
    }
    std::string text() const {
        std::ostringstream o;
        o << "mesh " << name_ << "\n";
        for (const auto& p : ordered(positions_)) o << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
        for (const auto& t : ordered(uvs_)) o << "vt " << t[0] << " " << t[1] << "\n";
        for (const auto& f : faces_) {
            o << "f";
            for (const auto& [p, t] : f) o << " " << p << "/" << t;
            o << "\n";
        }
        o << "end\n";
        return o.str();
    }

private:
    using Key = std::vector<std::string>;
    static int index(std::map<Key, int>& m, const Key& k) {
        auto it = m.find(k);
        if (it != m.end()) return it->second;
        int i = int(m.size()) + 1;
        m[k] = i;
        return i;
    }
    static std::vector<Key> ordered(const std::map<Key, int>& m) {
        std::vector<Key> out(m.size());
        for (const auto& [k, i] : m) out[size_t(i - 1)] = k;
        return out;
    }
    std::string name_;
    bool cut_;
    std::map<Key, int> positions_, uvs_;
    std::vector<std::vector<std::pair<int, int>>> faces_;
};

constexpr double PI = 3.14159265358979323846;

// A box from `lo` to `hi` whose faces look inward (a room), cut into `segments` pieces along z:
// floor and ceiling pieces into their makers, wall pieces into `walls` in turn (the two ends into
// the first); texture coordinates `floor_scale` and `wall_scale` texture sizes a unit.
void room(MeshMaker& floor, MeshMaker& ceiling, std::vector<MeshMaker>& walls, P3 lo, P3 hi, int segments, double floor_scale, double wall_scale) {
    const double dz = (hi.z - lo.z) / segments;
    for (int s = 0; s < segments; ++s) {
        double z0 = lo.z + s * dz, z1 = z0 + dz;
        auto fu = [&](double x) { return (x - lo.x) * floor_scale; };
        auto fv = [&](double z) { return (hi.z - z) * floor_scale; };
        floor.face({{{lo.x, lo.y, z0}, {fu(lo.x), fv(z0)}}, {{hi.x, lo.y, z0}, {fu(hi.x), fv(z0)}}, {{hi.x, lo.y, z1}, {fu(hi.x), fv(z1)}}, {{lo.x, lo.y, z1}, {fu(lo.x), fv(z1)}}},
                   {0, 1, 0});
        ceiling.face({{{lo.x, hi.y, z0}, {fu(lo.x), fv(z0)}}, {{hi.x, hi.y, z0}, {fu(hi.x), fv(z0)}}, {{hi.x, hi.y, z1}, {fu(hi.x), fv(z1)}}, {{lo.x, hi.y, z1}, {fu(lo.x), fv(z1)}}},
                     {0, -1, 0});
        MeshMaker& w = walls[size_t(s) % walls.size()];
        auto wv = [&](double y) { return (hi.y - y) * wall_scale; };
        for (double x : {lo.x, hi.x}) {
            // u runs to the right as one faces the wall from inside: -z on the left wall, +z on the right
            auto wu = [&](double z) { return (x == lo.x ? hi.z - z : z - lo.z) * wall_scale; };
            w.face({{{x, lo.y, z0}, {wu(z0), wv(lo.y)}}, {{x, hi.y, z0}, {wu(z0), wv(hi.y)}}, {{x, hi.y, z1}, {wu(z1), wv(hi.y)}}, {{x, lo.y, z1}, {wu(z1), wv(lo.y)}}},
                   {x == lo.x ? 1.0 : -1.0, 0, 0});
        }
    }
    // the two ends
    MeshMaker& w = walls[0];
    for (double z : {lo.z, hi.z}) {
        auto eu = [&](double x) { return (z == lo.z ? x - lo.x : hi.x - x) * wall_scale; };
        auto ev = [&](double y) { return (hi.y - y) * wall_scale; };
        w.face({{{lo.x, lo.y, z}, {eu(lo.x), ev(lo.y)}}, {{hi.x, lo.y, z}, {eu(hi.x), ev(lo.y)}}, {{hi.x, hi.y, z}, {eu(hi.x), ev(hi.y)}}, {{lo.x, hi.y, z}, {eu(lo.x), ev(hi.y)}}},
               {0, 0, z == lo.z ? 1.0 : -1.0});
    }
}

const char* CORRIDOR_CAMERA =
    "camera\n"
    "  fov 70\n"
    "  near 0.05\n"
    "  far 200\n"
    "  # down the corridor, a look at the right wall, back up it, a look at the left wall\n"
    "  key 0     0 1.5 55      0 1.4 45\n"
    "  key 5     0.8 1.6 -50   0.5 1.3 -60\n"
    "  key 5.5   0.8 1.6 -50   4 1.5 -50\n"
    "  key 6     0.8 1.6 -50   0.5 1.3 -40\n"
    "  key 11    0 1.5 55      0 1.4 65\n"
    "  key 11.5  0 1.5 55      -4 1.5 55\n"
    "  key 12    0 1.5 55      0 1.4 45\n"
    "end\n"
    "frames 360\n";

std::string ball_scene(bool all256) {
    // latitude bands of 30 degrees, 12 facets of 30 degrees around: one copy of the texture spans
    // two neighbouring facets (u 0..0.5 on one, 0.5..1 on the next) and one band
    MeshMaker m("ball");
    const int bands = 6, around = 12;
    auto at = [&](int a, int b) {
        double lat = (90.0 - 180.0 * a / bands) * PI / 180, lon = 360.0 * b / around * PI / 180;
        if (a == 0) return P3{0, 1, 0};
        if (a == bands) return P3{0, -1, 0};
        return P3{std::cos(lat) * std::cos(lon), std::sin(lat), -std::cos(lat) * std::sin(lon)};
    };
    for (int a = 0; a < bands; ++a)
        for (int b = 0; b < around; ++b) {
            double u0 = (b % 2) * 0.5, u1 = u0 + 0.5;
            P3 p00 = at(a, b), p01 = at(a, b + 1), p10 = at(a + 1, b), p11 = at(a + 1, b + 1);
            P3 mid{(p00.x + p11.x) / 2, (p00.y + p11.y) / 2, (p00.z + p11.z) / 2};
            if (a == 0) m.face({{p00, {(u0 + u1) / 2, 0}}, {p10, {u0, 1}}, {p11, {u1, 1}}}, mid);
            else if (a == bands - 1) m.face({{p00, {u0, 0}}, {p01, {u1, 0}}, {p10, {(u0 + u1) / 2, 1}}}, mid);
            else m.face({{p00, {u0, 0}}, {p01, {u1, 0}}, {p11, {u1, 1}}, {p10, {u0, 1}}}, mid);
        }
    return std::string("modexlab-scene 2\n") +
           (all256 ? "# The ball with its texture at 256 x 256 (the same layout), so that fatmap's loops, which take\n"
                     "# only that size, draw it too: every mapper draws all of it.\n"
                     "texture cells numbered 256 256\n"
                   : "# X-Sharp's demo: a spinning polyhedral ball; each copy of the texture spans two\n"
                     "# neighbouring facets, so a mapper's seams and edges show where facets meet.\n"
                     "texture cells numbered 128 64\n") +
           m.text() +
           "object ball\n  mesh ball\n  texture cells\n  wrap repeat\n  spin 0.3 1 0.2 40\n  rotate 1 0 0 20\nend\n"
           "camera\n  position 0 0 3.2\n  target 0 0 0\n  fov 60\nend\n"
           "budget max-error 1 coverage any\n"
           "frames 270\n";
}

std::string corridor_scene(bool cut) {
    MeshMaker floor("floor", cut), ceiling("ceiling", cut);
    std::vector<MeshMaker> walls = {MeshMaker("walls", cut)};
    room(floor, ceiling, walls, {-2, 0, -60}, {2, 3, 60}, 1, 0.5, 0.5);
    return std::string("modexlab-scene 2\n") +
           (cut ? "# The corridor with every face cut along its texture's period lines (each piece within one\n"
                  "# 256-texel period along u and v, as the classics' tools cut surfaces), so that every mapper,\n"
                  "# the classics that cannot wrap included, draws all of it: corridor.scene's camera and\n"
                  "# textures, from 488 faces instead of 6.\n"
                : "# A corridor 120 units deep: floor, ceiling and walls each one polygon receding from the\n"
                  "# eye to the far end (the perspective stress case: depth ratios in the thousands, and the\n"
                  "# near plane cutting every face). Its textures are 256 x 256, so the mappers that need that\n"
                  "# size can draw it too.\n") +
           "texture tiles checker 256 256\ntexture panels grid 256 256\ntexture plates numbered 256 256\n" +
           floor.text() + ceiling.text() + walls[0].text() +
           "object floor\n  mesh floor\n  texture tiles\nend\n"
           "object ceiling\n  mesh ceiling\n  texture panels\nend\n"
           "object walls\n  mesh walls\n  texture plates\nend\n" +
           CORRIDOR_CAMERA + "budget max-error 1 coverage exact\n";
}

std::string corridor() { return corridor_scene(false); }
std::string corridor_cut() { return corridor_scene(true); }

std::string rotozoom() {
    MeshMaker m("quad");
    m.face({{{-1, -1, 0}, {0, 1}}, {{1, -1, 0}, {1, 1}}, {{1, 1, 0}, {1, 0}}, {{-1, 1, 0}, {0, 0}}}, {0, 0, 1});
    std::string keys;
    // the eye's distance shrinks geometrically from 40 to 0.1 and back: every zoom gets equal time
    const int steps = 10;
    for (int i = 0; i <= 2 * steps; ++i) {
        int k = i <= steps ? i : 2 * steps - i;
        double d = 40 * std::pow(0.1 / 40, double(k) / steps);
        keys += "  key " + num(i * 0.5) + "  0 0 " + num(d) + "  0 0 0\n";
    }
    return "modexlab-scene 2\n"
           "# One quad turning through every angle (36 degrees a second) while the eye comes from 40 units\n"
           "# (the 256 x 256 texture on a dozen pixels: heavy minification) to 0.1 (a texel over 16\n"
           "# pixels: heavy magnification) and back.\n"
           "texture cells numbered 256 256\n" +
           m.text() + "object quad\n  mesh quad\n  texture cells\n  spin 0 0 1 36\nend\n" +
           "camera\n  fov 60\n  near 0.01\n  far 100\n" + keys + "end\n" +
           "budget max-error 0.5 coverage exact\n"
           "frames 300\n";
}

std::string mesh() {
    // a torus of 64 x 32 quads, each cut in two: 4096 small triangles
    MeshMaker m("torus");
    const int around = 64, tube = 32;
    const double major = 1, minor = 0.35;
    auto at = [&](int i, int j) {
        double a = 2 * PI * i / around, b = 2 * PI * j / tube;
        return P3{(major + minor * std::cos(b)) * std::cos(a), minor * std::sin(b), -(major + minor * std::cos(b)) * std::sin(a)};
    };
    auto centre = [&](int i) {
        double a = 2 * PI * (i + 0.5) / around;
        return P3{major * std::cos(a), 0, -major * std::sin(a)};
    };
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            P3 p00 = at(i, j), p10 = at(i + 1, j), p01 = at(i, j + 1), p11 = at(i + 1, j + 1);
            double u0 = 2.0 * i / around, u1 = 2.0 * (i + 1) / around, v0 = 1.0 * j / tube, v1 = 1.0 * (j + 1) / tube;
            P3 c = centre(i), mid{(p00.x + p11.x) / 2, (p00.y + p11.y) / 2, (p00.z + p11.z) / 2};
            P3 out = sub(mid, c);
            m.face({{p00, {u0, v0}}, {p10, {u1, v0}}, {p11, {u1, v1}}}, out);
            m.face({{p00, {u0, v0}}, {p11, {u1, v1}}, {p01, {u0, v1}}}, out);
        }
    return "modexlab-scene 2\n"
           "# A closed torus of 4096 triangles of about 12 pixels each, spans of 2 to 3 pixels on average,\n"
           "# so the setup and the edge walking cost more than the inner loops (fatmap's histogram). Tilted\n"
           "# toward the camera and spun about an axis near its own, it turns its hole to the eye at every\n"
           "# frame.\n"
           "texture cells numbered 256 256\n" +
           m.text() + "object torus\n  mesh torus\n  texture cells\n  spin 0.3 0.5 0.866 30\n  rotate 1 0 0 60\nend\n" +
           "camera\n  position 0 0.4 3.6\n  target 0 0 0\n  fov 50\nend\n"
           "budget max-error 1 coverage any\n"
           "frames 360\n";
}

enum class CubeTextures { Mixed, All256, Above256 };

std::string cube_scene(CubeTextures sizes) {
    const char* textures[6] = {"checks", "grid", "cells", "bits", "shades", "big"};
    std::string out =
        sizes == CubeTextures::All256
            ? "modexlab-scene 2\n"
              "# The cube with its six textures all 256 x 256 (the same kinds), so that fatmap's loops, which\n"
              "# take only that size, draw every face: every mapper draws all of it.\n"
              "texture checks checker 256 256\ntexture grid grid 256 256\ntexture cells numbered 256 256\n"
              "texture bits xor 256 256\ntexture shades gradient 256 256\ntexture big checker 256 256\n"
        : sizes == CubeTextures::Above256
            ? "modexlab-scene 2\n"
              "# The cube with its six textures above 256 a side (the same kinds, powers of two up to 1024),\n"
              "# which our affine fast mappers read through their doubled copies: the mappers that take only\n"
              "# the tiled 256 x 256 block refuse it.\n"
              "texture checks checker 1024 1024\ntexture grid grid 512 512\ntexture cells numbered 1024 256\n"
              "texture bits xor 256 1024\ntexture shades gradient 1024 64\ntexture big checker 512 512\n"
            : "modexlab-scene 2\n"
              "# A cube, six faces, six textures of six sizes and kinds (two of them 256 x 256, for the\n"
              "# mappers that need it), spinning about a tilted axis.\n"
              "texture checks checker 32 32\ntexture grid grid 64 64\ntexture cells numbered 128 128\n"
              "texture bits xor 256 256\ntexture shades gradient 128 64\ntexture big checker 256 256\n";
    const P3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int f = 0; f < 6; ++f) {
        MeshMaker m(std::string("face") + char('1' + f));
        P3 n = normals[f];
        // two axes across the face
        P3 a = std::fabs(n.x) > 0 ? P3{0, 1, 0} : P3{1, 0, 0};
        P3 b = cross3(n, a);
        auto corner = [&](double s, double t) { return P3{n.x + s * a.x + t * b.x, n.y + s * a.y + t * b.y, n.z + s * a.z + t * b.z}; };
        m.face({{corner(-1, -1), {0, 1}}, {corner(1, -1), {1, 1}}, {corner(1, 1), {1, 0}}, {corner(-1, 1), {0, 0}}}, n);
        out += m.text();
    }
    for (int f = 0; f < 6; ++f)
        out += std::string("object side") + char('1' + f) + "\n  mesh face" + char('1' + f) + "\n  texture " + textures[f] +
               "\n  spin 1 1 0.3 45\nend\n";
    return out + "camera\n  position 0 0 5\n  target 0 0 0\n  fov 60\nend\nbudget max-error 1 coverage exact\nframes 240\n";
}

std::string freedoom_scene(bool all256) {
    MeshMaker floor("floor", all256), ceiling("ceiling", all256);
    std::vector<MeshMaker> walls = {MeshMaker("walls1", all256), MeshMaker("walls2", all256), MeshMaker("walls3", all256)};
    // 32 texels a unit: the flats 64 x 64 (2 units), the walls 128 high over 4 units; tiled to 256 x 256,
    // a texture is 8 units
    room(floor, ceiling, walls, {-2, 0, -60}, {2, 3, 60}, 15, all256 ? 0.125 : 0.5, all256 ? 0.125 : 0.25);
    const char* names[5][2] = {{"floor", "floor0_1"}, {"ceiling", "ceil3_5"}, {"stone", "startan3"}, {"computers", "comptall"}, {"brown", "brown1"}};
    std::string textures;
    for (const auto& [name, file] : names)
        textures += std::string("texture ") + name + " file freedoom/" + file + ".bmp" + (all256 ? " tile 256 256" : "") + "\n";
    return std::string("modexlab-scene 2\n") +
           (all256 ? "# The Freedoom corridor with its textures tiled to 256 x 256 (each repeats as the original does)\n"
                     "# and its faces cut along their period lines, so that every mapper, fatmap's and the ones that\n"
                     "# cannot wrap included, draws all of it: freedoom.scene's camera, pictures and palette.\n"
                   : "# The corridor with Freedoom's textures (BSD-licensed; made at build time from Debian's\n"
                     "# freedoom package by modexlab-wad, not committed) in Freedoom's own palette.\n") +
           textures + "palette floor\n" + floor.text() + ceiling.text() + walls[0].text() + walls[1].text() + walls[2].text() +
           "object floor\n  mesh floor\n  texture floor\nend\n"
           "object ceiling\n  mesh ceiling\n  texture ceiling\nend\n"
           "object walls1\n  mesh walls1\n  texture stone\nend\n"
           "object walls2\n  mesh walls2\n  texture computers\nend\n"
           "object walls3\n  mesh walls3\n  texture brown\nend\n" +
           CORRIDOR_CAMERA + "budget max-error 1 coverage exact\n";
}

std::string ball() { return ball_scene(false); }
std::string ball_256() { return ball_scene(true); }
std::string cube() { return cube_scene(CubeTextures::Mixed); }
std::string cube_256() { return cube_scene(CubeTextures::All256); }
std::string cube_1024() { return cube_scene(CubeTextures::Above256); }
std::string freedoom() { return freedoom_scene(false); }
std::string freedoom_256() { return freedoom_scene(true); }

}  // namespace

const std::vector<DemoScene>& demo_scenes() {
    static const std::vector<DemoScene> scenes = {
        {"ball", "X-Sharp's demo: a spinning polyhedral ball, a texture across two facets", ball},
        {"ball-256", "the ball with its texture at 256 x 256: every mapper draws all of it", ball_256},
        {"corridor", "floor, ceiling and walls receding 120 units: the perspective stress case, near-plane clipping", corridor},
        {"corridor-cut", "the corridor cut along its textures' period lines: every mapper draws all of it", corridor_cut},
        {"rotozoom", "one quad through every angle, from heavy minification to heavy magnification", rotozoom},
        {"mesh", "a closed torus of 4096 triangles, spans of 2 pixels on average: the setup-bound case", mesh},
        {"cube", "six faces, six textures of different kinds and sizes", cube},
        {"cube-256", "the cube with its six textures at 256 x 256: every mapper draws all of it", cube_256},
        {"cube-1024", "the cube with its six textures above 256 a side, up to 1024: our affine fast mappers' doubled copies", cube_1024},
        {"freedoom", "the corridor in Freedoom's textures and palette (image files, a scene palette)", freedoom},
        {"freedoom-256", "the Freedoom corridor, textures tiled to 256 x 256, faces cut at their periods: every mapper draws all of it", freedoom_256},
    };
    return scenes;
}

SceneChoice choose_scene(const std::string& spec) {
    for (const DemoScene& d : demo_scenes())
        if (spec == d.name) return {spec, "scenes/" + spec + ".scene", &d};
    const bool a_path = spec.find('/') != std::string::npos || std::filesystem::path(spec).extension() == ".scene";
    if (!a_path && !std::filesystem::is_regular_file(spec)) {  // (a path's errors come when it is read)
        std::vector<std::string> names;
        for (const DemoScene& d : demo_scenes()) names.push_back(d.name);
        throw HarnessError("no demo scene or scene file '" + spec + "' (the demo scenes, the nearest first: " + nearest_first(spec, names) + ")");
    }
    return {std::filesystem::path(spec).stem().string(), spec, nullptr};
}

void load_scene_in_kernel(Session& s, const SceneChoice& scene, const LoadedWorld& host) {
    auto ok = [&](const json& r, const std::string& what) {
        if (!r.value("ok", false)) throw HarnessError(what + ": the kernel refused it: " + r.value("error", std::string("?")));
    };
    if (scene.demo) return ok(s.command("load " + scene.name + ".scene"), scene.path);
    for (const auto& [name, bytes] : host.files) ok(s.upload_file(name, bytes), name);
    const std::string name = std::filesystem::path(scene.path).filename().string();
    ok(s.upload_file(name, read_whole_file(scene.path)), scene.path);
    ok(s.command("load " + name), scene.path);
}

std::vector<std::string> demo_scenes_drawn_whole(const raster::Mapper& m) {
    std::vector<std::string> whole;
    for (const DemoScene& d : demo_scenes()) {
        const LoadedWorld w = load_world_file("scenes/" + std::string(d.name) + ".scene");
        raster::RenderStats stats;
        render_world_frame(w, *world_frame(w, 0), m, raster::home_axis(m), &stats);
        if (!stats.rejected && stats.pixels) whole.push_back(d.name);
    }
    return whole;
}

std::string obj_to_mesh(const std::string& obj, const std::string& mesh_name, const std::string& file) {
    using namespace raster;
    if (!world_name_ok(lib::StrView{mesh_name.data(), mesh_name.size()}))
        throw HarnessError("bad mesh name '" + mesh_name + "' (" + WORLD_NAME_RULE + ")");
    std::istringstream in(obj);
    std::string line;
    int line_no = 0;
    std::vector<std::string> v, vt;
    std::vector<int> v_lines, vt_lines, f_lines;  // the OBJ's line of each
    std::vector<std::vector<std::pair<int, int>>> faces;
    size_t corners = 0;
    auto fail = [&](const std::string& what) { throw HarnessError(file + ":" + std::to_string(line_no) + ": " + what); };
    // a number the scene format takes: within its limit, written back with the digits it reads
    auto number = [&](const std::string& w, double limit, const char* what) {
        char* end = nullptr;
        const double x = std::strtod(w.c_str(), &end);
        if (!end || *end || !std::isfinite(x)) fail("bad number '" + w + "'");
        if (std::fabs(x) > limit) fail(std::string(what) + " " + w + " is beyond the scene format's limit of " + num(limit) + " either way");
        return x;
    };
    auto at_most = [&](size_t count, int32_t limit, const char* what) {
        if (count > size_t(limit)) fail(std::string("more than ") + std::to_string(limit) + " " + what + ": the scene format's limit for a mesh");
    };
    while (std::getline(in, line)) {
        ++line_no;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line.substr(0, line.find('#')));
        std::string kind;
        if (!(words >> kind)) continue;
        std::vector<std::string> w;
        for (std::string x; words >> x;) w.push_back(x);
        if (kind == "v") {
            if (w.size() < 3) fail("v needs x y z");
            const char* what = "coordinate";
            v.push_back("v " + num(number(w[0], MAX_WORLD_COORD, what)) + " " + num(number(w[1], MAX_WORLD_COORD, what)) + " " +
                        num(number(w[2], MAX_WORLD_COORD, what)));
            v_lines.push_back(line_no);
            at_most(v.size(), MAX_WORLD_POSITIONS, "positions (v)");
        } else if (kind == "vt") {
            if (w.size() < 2) fail("vt needs u v");
            const char* what = "texture coordinate";
            vt.push_back("vt " + num(number(w[0], MAX_TEXCOORD, what)) + " " + num(1 - number(w[1], MAX_TEXCOORD - 1, what)));  // OBJ's v runs up
            vt_lines.push_back(line_no);
            at_most(vt.size(), MAX_WORLD_UVS, "texture coordinates (vt)");
        } else if (kind == "f") {
            if (w.size() < 3 || w.size() > size_t(MAX_FACE_CORNERS)) fail("a face needs 3 to " + std::to_string(MAX_FACE_CORNERS) + " corners");
            std::vector<std::pair<int, int>> f;
            for (const std::string& c : w) {
                size_t s1 = c.find('/');
                if (s1 == std::string::npos) fail("corner '" + c + "' has no texture coordinate (v/vt)");
                size_t s2 = c.find('/', s1 + 1);
                auto resolve = [&](const std::string& s, size_t count) {
                    char* end = nullptr;
                    long i = std::strtol(s.c_str(), &end, 10);
                    if (s.empty() || *end || i == 0) fail("bad index in corner '" + c + "'");
                    long r = i > 0 ? i : long(count) + 1 + i;
                    if (r < 1 || r > long(count)) fail("corner '" + c + "' points past the list");
                    return int(r);
                };
                f.push_back({resolve(c.substr(0, s1), v.size()), resolve(c.substr(s1 + 1, s2 == std::string::npos ? std::string::npos : s2 - s1 - 1), vt.size())});
            }
            faces.push_back(f);
            f_lines.push_back(line_no);
            corners += f.size();
            at_most(faces.size(), MAX_WORLD_FACES, "faces (f)");
            at_most(corners, MAX_WORLD_CORNERS, "corners of faces");
        }  // o, g, s, vn, usemtl, mtllib and others: not needed
    }
    if (faces.empty()) throw HarnessError(file + ": no faces (f lines with v/vt corners): not a mesh");
    std::string out = "mesh " + mesh_name + "\n";
    for (const std::string& x : v) out += x + "\n";
    for (const std::string& x : vt) out += x + "\n";
    for (const auto& f : faces) {
        out += "f";
        for (const auto& [p, t] : f) out += " " + std::to_string(p) + "/" + std::to_string(t);
        out += "\n";
    }
    out += "end\n";
    // what the scene parser says of it, in a scene of its own (the mesh from its line 3): its rules
    // (a name's, a face's) are its alone; an error on a line of the mesh names the OBJ's line
    const std::string scene = "modexlab-scene 2\ntexture t checker 8 8\n" + out + "object o\nmesh " + mesh_name + "\ntexture t\nend\ncamera\nend\n";
    auto world = std::make_unique<HostWorld>();
    ParseError e;
    if (!parse_world(scene.data(), scene.size(), FileResolver{}, world.get(), &e)) {
        std::vector<int> obj_lines = {0};  // the mesh's lines in order: its header, v, vt, f
        for (const std::vector<int>* l : {&v_lines, &vt_lines, &f_lines}) obj_lines.insert(obj_lines.end(), l->begin(), l->end());
        const size_t k = e.line >= 3 ? size_t(e.line - 3) : obj_lines.size();
        line_no = k < obj_lines.size() ? obj_lines[k] : 0;
        throw HarnessError(file + (line_no ? ":" + std::to_string(line_no) : std::string()) + ": the scene parser refuses the mesh (mesh " +
                           mesh_name + "): " + e.message);
    }
    return out;
}

}  // namespace harness
