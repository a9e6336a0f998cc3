// Under test: kernel/scene/frame.h.
// From 3D scenes to frames: the projection by hand, back-face culling, the painter's order,
// homogeneous clipping against an independent computation, animation, and the limits every
// vertex that reaches the setup keeps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "kernel/scene/frame.h"

namespace {

using namespace raster;

struct Built {
    std::unique_ptr<HostWorld> world = std::make_unique<HostWorld>();
    std::unique_ptr<HostFrame> frame = std::make_unique<HostFrame>();
    std::unique_ptr<HostFrameScratch> scratch = std::make_unique<HostFrameScratch>();
};

std::unique_ptr<Built> build(const std::string& text, int32_t frame = 0) {
    auto b = std::make_unique<Built>();
    ParseError e;
    FileResolver none;
    EXPECT_TRUE(parse_world(text.data(), text.size(), none, b->world.get(), &e)) << e.line << ": " << e.message;
    build_frame(*b->world, frame, b->frame.get(), b->scratch.get());
    return b;
}

// A unit cube around the origin, faces counter-clockwise seen from outside; `flip` reverses them.
std::string cube(bool flip) {
    std::string s = "mesh cube\n";
    for (int i = 0; i < 8; ++i) s += "v " + std::to_string(i & 1 ? 1 : -1) + " " + std::to_string(i & 2 ? 1 : -1) + " " + std::to_string(i & 4 ? 1 : -1) + "\n";
    s += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
    // (1-based) x-, x+, y-, y+, z-, z+ faces, outward normals, counter-clockwise
    const int faces[6][4] = {{1, 5, 7, 3}, {2, 4, 8, 6}, {1, 2, 6, 5}, {3, 7, 8, 4}, {1, 3, 4, 2}, {5, 6, 8, 7}};
    for (const auto& f : faces) {
        s += "f";
        for (int k = 0; k < 4; ++k) s += " " + std::to_string(f[flip ? 3 - k : k]) + "/" + std::to_string(k + 1);
        s += "\n";
    }
    return s + "end\n";
}

const std::string QUAD = "mesh quad\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 1\nvt 1 1\nvt 1 0\nvt 0 0\nf 1/1 2/2 3/3 4/4\nend\n";

TEST(Frame, ProjectsAsWorkedOutByHand) {
    // fov 90: focal 1 vertically, 0.75 across (4:3); the quad's corners at depth 2
    auto b = build("modexlab-scene 2\ntexture t checker 64 32\n" + QUAD +
                   "object q\nmesh quad\ntexture t\nposition 0 0 -2\nend\ncamera\nposition 0 0 0\ntarget 0 0 -1\nfov 90\nend\n");
    const Frame& f = *b->frame;
    ASSERT_EQ(f.polygon_count, 1);
    ASSERT_EQ(f.polygon_size[0], 4);
    // corner (-1, -1, -2): x = 160 + 160 * (-0.75 / 2) = 100, y = 120 - 120 * (-1 / 2) = 180
    const double want[4][2] = {{100, 180}, {220, 180}, {220, 60}, {100, 60}};
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(f.vertices[i].x.to_double(), want[i][0], 1.0 / 256) << i;
        EXPECT_NEAR(f.vertices[i].y.to_double(), want[i][1], 1.0 / 256) << i;
        EXPECT_NEAR(f.vertices[i].w, 2.0, 1e-12);
    }
    EXPECT_EQ(f.vertices[0].u, 0.0);
    EXPECT_EQ(f.vertices[0].v, 32.0);  // vt (0, 1) in a 64 x 32 texture
    EXPECT_EQ(f.vertices[2].u, 64.0);
    EXPECT_EQ(f.stats.polygons, 1u);
}

TEST(Frame, BackFacesAreCulledAndCullNoneKeepsThem) {
    const std::string cam = "camera\nposition 4 5 6\ntarget 0 0 0\nend\n";
    auto visible = [&](bool flip, const char* cull) {
        auto b = build("modexlab-scene 2\ntexture t checker 8 8\n" + cube(flip) + "object c\nmesh cube\ntexture t\ncull " + cull + "\nend\n" + cam);
        return std::pair<int32_t, uint32_t>{b->frame->polygon_count, b->frame->stats.culled};
    };
    EXPECT_EQ(visible(false, "back"), (std::pair<int32_t, uint32_t>{3, 3})) << "seen from a corner: three faces";
    EXPECT_EQ(visible(true, "back"), (std::pair<int32_t, uint32_t>{3, 3})) << "reversed: the three far ones";
    EXPECT_EQ(visible(false, "none"), (std::pair<int32_t, uint32_t>{6, 0}));
    // and the three kept are the ones facing the camera: +x, +y, +z (their centres nearest)
    auto b = build("modexlab-scene 2\ntexture t checker 8 8\n" + cube(false) + "object c\nmesh cube\ntexture t\nend\n" + cam);
    for (int32_t i = 0, v = 0; i < b->frame->polygon_count; v += b->frame->polygon_size[i], ++i) {
        double mean_w = 0;
        for (int k = 0; k < b->frame->polygon_size[i]; ++k) mean_w += b->frame->vertices[v + k].w / 4;
        EXPECT_LT(mean_w, std::sqrt(16.0 + 25 + 36)) << "a face nearer than the cube's centre";
    }
}

TEST(Frame, FarPolygonsComeFirst) {
    std::string text = "modexlab-scene 2\ntexture t checker 8 8\ntexture u xor 8 8\n" + QUAD +
                       "object near\nmesh quad\ntexture t\nposition 0.5 0 -3\nend\n"
                       "object far\nmesh quad\ntexture u\nposition 0 0 -6\nend\n"
                       "object middle\nmesh quad\ntexture u\nposition -0.5 0 -4\nend\n"
                       "camera\nposition 0 0 0\ntarget 0 0 -1\nend\n";
    auto b = build(text);
    ASSERT_EQ(b->frame->polygon_count, 3);
    EXPECT_EQ(b->frame->polygon_object[0], 1);
    EXPECT_EQ(b->frame->polygon_object[1], 2);
    EXPECT_EQ(b->frame->polygon_object[2], 0);
}

// The painter's order against a plain stable sort by (depth descending, then the order given):
// random depths over wide and narrow ranges, many of them equal, negative ones, +0 and -0 (equal),
// so that byte passes are both taken and skipped, and runs of one high word short and long.
TEST(Frame, PainterOrderIsAStableSortFarFirst) {
    auto scratch = std::make_unique<HostFrameScratch>();
    std::mt19937 rng(4711u);
    for (int round = 0; round < 200; ++round) {
        const int32_t n = round == 0 ? 0 : round == 1 ? 1 : int32_t(rng() % 3000);
        const int kind = round % 4;
        for (int32_t i = 0; i < n; ++i) {
            double d;
            if (kind == 0) d = std::uniform_real_distribution<double>(-1e6, 1e6)(rng);
            else if (kind == 1) d = 2.5 + std::uniform_real_distribution<double>(0, 1e-9)(rng);   // one high word: a long run
            else if (kind == 2) d = double(rng() % 7) - 3;                                        // ties
            else d = rng() % 5 == 0 ? (rng() % 2 ? 0.0 : -0.0) : double(1 + rng() % 500) + double(rng() % 4) * 0x1p-40;  // short runs
            scratch->entries[i] = FrameScratch::Entry{d, int32_t(i / 100), int32_t(i % 100), false};
        }
        std::vector<int32_t> want(size_t(n), 0);
        for (int32_t i = 0; i < n; ++i) want[size_t(i)] = i;
        std::stable_sort(want.begin(), want.end(), [&](int32_t a, int32_t b) { return scratch->entries[a].depth > scratch->entries[b].depth; });
        const int32_t* got = painter_order(scratch.get(), n);
        for (int32_t i = 0; i < n; ++i) ASSERT_EQ(got[i], want[size_t(i)]) << "round " << round << ", place " << i;
    }
}

// The clipper against an independent computation. For random triangles in clip space (many
// crossing w = 0, the near and far planes and the guard band): each output corner satisfies every
// plane, lies in the triangle with the attributes the triangle has there (barycentric, solved
// here), and a random point of the triangle is inside the output exactly when it satisfies every
// plane (away from the boundary).
TEST(Frame, ClippingMatchesAnIndependentComputation) {
    std::mt19937 rng(17);
    auto any = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    const double near = 0.5, far = 50;
    int kept = 0, empty = 0, samples = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        ClipVertex t[3];
        for (ClipVertex& c : t) {
            c.w = any(-10, 80);
            double spread = trial % 3 == 0 ? 100 : 40;
            c.x = any(-spread, spread) * std::fabs(c.w) + any(-5, 5);
            c.y = any(-spread, spread) * std::fabs(c.w) + any(-5, 5);
            c.u = any(-500, 500), c.v = any(-500, 500);
        }
        ClipVertex out[9];
        int n = clip_polygon(t, 3, near, far, out);
        // barycentric coordinates of a point of the triangle's plane, from its x, y, w
        auto bary = [&](const ClipVertex& p, double* b1, double* b2) {
            double a11 = t[1].x - t[0].x, a12 = t[2].x - t[0].x, a21 = t[1].y - t[0].y, a22 = t[2].y - t[0].y, a31 = t[1].w - t[0].w, a32 = t[2].w - t[0].w;
            double r1 = p.x - t[0].x, r2 = p.y - t[0].y, r3 = p.w - t[0].w;
            // least squares on the three equations (the point is on the plane up to rounding)
            double m11 = a11 * a11 + a21 * a21 + a31 * a31, m12 = a11 * a12 + a21 * a22 + a31 * a32, m22 = a12 * a12 + a22 * a22 + a32 * a32;
            double q1 = a11 * r1 + a21 * r2 + a31 * r3, q2 = a12 * r1 + a22 * r2 + a32 * r3;
            double det = m11 * m22 - m12 * m12;
            *b1 = (q1 * m22 - q2 * m12) / det, *b2 = (m11 * q2 - m12 * q1) / det;
        };
        auto satisfies = [&](const ClipVertex& p, double margin) {
            double s = margin * (1 + std::fabs(p.w) * GUARD_BAND);
            return p.w - near >= -s && far - p.w >= -s && GUARD_BAND * p.w - std::fabs(p.x) >= -s && GUARD_BAND * p.w - std::fabs(p.y) >= -s;
        };
        if (n == 0) {
            ++empty;
        } else {
            ASSERT_GE(n, 3);
            ++kept;
        }
        std::vector<std::pair<double, double>> poly;
        for (int i = 0; i < n; ++i) {
            const ClipVertex& p = out[i];
            ASSERT_TRUE(satisfies(p, 1e-9)) << "trial " << trial << " corner " << i;
            double b1, b2;
            bary(p, &b1, &b2);
            ASSERT_GT(b1, -1e-7);
            ASSERT_GT(b2, -1e-7);
            ASSERT_LT(b1 + b2, 1 + 1e-7);
            double u = t[0].u + b1 * (t[1].u - t[0].u) + b2 * (t[2].u - t[0].u);
            double v = t[0].v + b1 * (t[1].v - t[0].v) + b2 * (t[2].v - t[0].v);
            ASSERT_NEAR(p.u, u, 1e-6 * (1 + std::fabs(u))) << "trial " << trial;
            ASSERT_NEAR(p.v, v, 1e-6 * (1 + std::fabs(v))) << "trial " << trial;
            poly.push_back({b1, b2});
        }
        for (int s = 0; s < 20; ++s) {
            double b1 = any(0, 1), b2 = any(0, 1);
            if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;
            ClipVertex p{};
            p.x = t[0].x + b1 * (t[1].x - t[0].x) + b2 * (t[2].x - t[0].x);
            p.y = t[0].y + b1 * (t[1].y - t[0].y) + b2 * (t[2].y - t[0].y);
            p.w = t[0].w + b1 * (t[1].w - t[0].w) + b2 * (t[2].w - t[0].w);
            bool in = satisfies(p, -1e-6), out_by_margin = !satisfies(p, 1e-6);
            if (!in && !out_by_margin) continue;  // too near a plane to call
            // inside the output polygon (convex, in barycentric coordinates)?
            bool inside = poly.size() >= 3;
            double orientation = 0;
            for (size_t i = 0; i < poly.size() && inside; ++i) {
                auto a = poly[i], c = poly[(i + 1) % poly.size()];
                double cr = (c.first - a.first) * (b2 - a.second) - (c.second - a.second) * (b1 - a.first);
                if (std::fabs(cr) < 1e-9) continue;
                if (orientation == 0) orientation = cr;
                else if ((cr > 0) != (orientation > 0)) inside = false;
            }
            ASSERT_EQ(inside, in) << "trial " << trial << " sample " << s;
            ++samples;
        }
    }
    EXPECT_GT(kept, 2000);
    EXPECT_GT(empty, 2000);
    EXPECT_GT(samples, 100000);
}

// A camera inside a long box (a corridor) turning: faces behind and beside the eye are cut; every
// vertex that reaches the setup is in front of the near plane and inside the guard band.
TEST(Frame, NoVertexBehindTheEyeReachesTheSetup) {
    std::string box = "mesh box\n";
    for (int i = 0; i < 8; ++i)
        box += "v " + std::to_string(i & 1 ? 2 : -2) + " " + std::to_string(i & 2 ? 2 : -2) + " " + std::to_string(i & 4 ? 40 : -40) + "\n";
    box += "vt 0 0\nvt 8 0\nvt 8 8\nvt 0 8\n";
    const int faces[6][4] = {{1, 3, 7, 5}, {2, 6, 8, 4}, {1, 5, 6, 2}, {3, 4, 8, 7}, {1, 2, 4, 3}, {5, 7, 8, 6}};  // inward
    for (const auto& f : faces) box += "f " + std::to_string(f[0]) + "/1 " + std::to_string(f[1]) + "/2 " + std::to_string(f[2]) + "/3 " + std::to_string(f[3]) + "/4\n";
    box += "end\n";
    std::string text = "modexlab-scene 2\ntexture t grid 64 64\n" + box + "object b\nmesh box\ntexture t\nend\n" +
                       "camera\nnear 0.05\nfar 100\nkey 0 0 0 30 0 0 0\nkey 2 1.9 1.9 -39 0 0 40\nkey 3 0 0 30 -1 0.5 29\nend\nframes 90\n";
    auto b = std::make_unique<Built>();
    ParseError e;
    FileResolver none;
    ASSERT_TRUE(parse_world(text.data(), text.size(), none, b->world.get(), &e)) << e.message;
    uint32_t clipped = 0, culled = 0;
    for (int32_t n = 0; n < 90; ++n) {
        build_frame(*b->world, n, b->frame.get(), b->scratch.get());
        const Frame& f = *b->frame;
        EXPECT_GE(f.polygon_count, 3) << "inside a box, the walls show; frame " << n;
        for (int32_t i = 0; i < f.vertex_count; ++i) {
            const Vertex& v = f.vertices[i];
            ASSERT_GE(v.w, 0.05) << "frame " << n;
            ASSERT_LE(v.w, 100.0);
            ASSERT_LE(std::fabs(v.x.to_double() - 160), 160 * GUARD_BAND + 1);
            ASSERT_LE(std::fabs(v.y.to_double() - 120), 120 * GUARD_BAND + 1);
        }
        clipped += f.stats.clipped;
        culled += f.stats.culled;
    }
    EXPECT_GT(clipped, 90u) << "the walls reach behind the eye: most frames cut some";
    EXPECT_EQ(culled, 0u) << "seen from inside, every wall faces the eye";
}

// Frame::polygon_whole's promise, on which the drawing skips setup's range checks: every corner of
// an uncut face is within setup's limits, at the parser's limits (texture coordinates of +-16384
// texture sizes on a 1024 x 1024 texture, near and far at MIN_W and MAX_W, positions out to 10^6,
// faces past the guard band and behind the eye, every corner of an uncut face just inside it).
TEST(Frame, UncutFacesAreWithinTheSetupsLimits) {
    std::mt19937 rng(20261125u);
    auto any = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    std::string mesh = "mesh m\n";
    for (int i = 0; i < 60; ++i) {
        const double scale = i % 3 == 0 ? 1e6 : i % 3 == 1 ? 50 : 0.001;
        mesh += "v " + std::to_string(any(-scale, scale)) + " " + std::to_string(any(-scale, scale)) + " " + std::to_string(any(-scale, scale)) + "\n";
    }
    for (int i = 0; i < 60; ++i)
        mesh += i % 4 == 0 ? std::string("vt ") + (i % 8 ? "16384 -16384\n" : "-16384 16384\n") : "vt " + std::to_string(any(-16384, 16384)) + " " + std::to_string(any(-16384, 16384)) + "\n";
    for (int i = 0; i < 400; ++i) {
        int a = int(rng() % 60), b = int(rng() % 60), c = int(rng() % 60);
        mesh += "f " + std::to_string(a + 1) + "/" + std::to_string(int(rng() % 60) + 1) + " " + std::to_string(b + 1) + "/" + std::to_string(int(rng() % 60) + 1) +
                " " + std::to_string(c + 1) + "/" + std::to_string(int(rng() % 60) + 1) + "\n";
    }
    mesh += "end\n";
    const std::string text = "modexlab-scene 2\ntexture t checker 1024 1024\n" + mesh + "object o\nmesh m\ntexture t\ncull none\nspin 1 2 3 40\nend\n" +
                             "camera\nnear 0.000016\nfar 16777216\nfov 120\nkey 0 0 0 60 0 0 0\nkey 4 30 -20 -60 0 0 0\nend\nframes 120\n";
    auto b = std::make_unique<Built>();
    ParseError e;
    FileResolver none;
    ASSERT_TRUE(parse_world(text.data(), text.size(), none, b->world.get(), &e)) << e.line << ": " << e.message;
    uint32_t whole = 0, cut = 0;
    for (int32_t n = 0; n < 120; ++n) {
        build_frame(*b->world, n, b->frame.get(), b->scratch.get());
        const Frame& f = *b->frame;
        const Vertex* v = f.vertices;
        for (int32_t i = 0; i < f.polygon_count; v += f.polygon_size[i], ++i) {
            if (!f.polygon_whole[i]) {
                ++cut;
                continue;
            }
            ++whole;
            ASSERT_TRUE(vertices_in_range(v, f.polygon_size[i])) << "frame " << n << ", polygon " << i;
        }
    }
    EXPECT_GT(whole, 1000u);
    EXPECT_GT(cut, 1000u);
}

TEST(Frame, AnimationFollowsTheFrameNumber) {
    std::string text = "modexlab-scene 2\ntexture t checker 8 8\n" + QUAD +
                       "object q\nmesh quad\ntexture t\nspin 0 0 1 90\nkey 0 0 0 -5\nkey 2 3 0 -5\nend\n"
                       "camera\nposition 0 0 0\ntarget 0 0 -1\nfov 90\nend\n";
    auto b0 = build(text, 0), b30 = build(text, 30), b60 = build(text, 60), b60again = build(text, 60);
    auto centre = [](const Frame& f) {
        double x = 0;
        for (int i = 0; i < f.polygon_size[0]; ++i) x += f.vertices[i].x.to_double() / f.polygon_size[0];
        return x;
    };
    // one second (frame 30): half way along the path; two seconds: the path loops back to its start
    EXPECT_NEAR(centre(*b0->frame), 160, 0.01);
    EXPECT_NEAR(centre(*b30->frame), 160 + 160 * 0.75 * 1.5 / 5, 0.01);
    EXPECT_NEAR(centre(*b60->frame), 160, 0.01);
    // spun 90 degrees a second: at frame 30 the first corner (-1, -1) has turned to (1, -1)
    EXPECT_NEAR(b30->frame->vertices[0].x.to_double(), 160 + 160 * 0.75 * 2.5 / 5, 0.01);
    // the same frame twice: the same bits
    ASSERT_EQ(b60->frame->vertex_count, b60again->frame->vertex_count);
    for (int32_t i = 0; i < b60->frame->vertex_count; ++i) {
        EXPECT_EQ(b60->frame->vertices[i].x.raw, b60again->frame->vertices[i].x.raw);
        EXPECT_EQ(b60->frame->vertices[i].w, b60again->frame->vertices[i].w);
    }
}

TEST(Frame, TexturesPerObjectShareTheirCopies) {
    std::string text = "modexlab-scene 2\ntexture big xor 256 256\ntexture small checker 64 32\ntexture odd checker 48 32\n" + QUAD +
                       "object a\nmesh quad\ntexture big\nend\nobject b\nmesh quad\ntexture big\nwrap clamp\nend\n"
                       "object c\nmesh quad\ntexture small\nend\nobject d\nmesh quad\ntexture odd\nend\ncamera\nend\n";
    auto b = build(text);
    auto set = std::make_unique<HostTextureSet>();
    build_texture_set(*b->world, set.get());
    EXPECT_EQ(set->objects[0].texels, set->objects[1].texels);
    EXPECT_EQ(set->objects[0].bordered, set->objects[1].bordered);
    EXPECT_EQ(set->objects[0].wrap, Wrap::Repeat);
    EXPECT_EQ(set->objects[1].wrap, Wrap::Clamp);
    EXPECT_NE(set->objects[0].aligned256, nullptr);
    EXPECT_EQ(set->objects[0].aligned256, set->objects[1].aligned256);
    EXPECT_EQ(set->objects[2].width, 64);
    EXPECT_EQ(set->objects[3].aligned256, nullptr) << "48 texels: not a power of two, no tiled block";
    // the bordered copy repeats the edge texels
    const Texture& s = set->objects[2];
    EXPECT_EQ(bordered_origin(s)[-1], s.texels[0]);
    EXPECT_EQ(bordered_origin(s)[32 * bordered_pitch(s) + 64], s.texels[31 * 64 + 63]);
    // the 64 x 32 texture tiled over the aligned 64 KiB block, its guard rows continuing the tiling
    ASSERT_NE(s.aligned256, nullptr);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(s.aligned256) & 0xFFFF, 0u);
    int wrong = 0;
    for (int32_t i = -ALIGNED256_GUARD_BEFORE * 256; i < 65536 + ALIGNED256_GUARD_AFTER * 256; ++i) {
        const int32_t u = ((i % 256) + 256) % 256, v = (((i - u) / 256) % 256 + 256) % 256;
        wrong += s.aligned256[i] != s.texels[(v % 32) * 64 + u % 64];
    }
    EXPECT_EQ(wrong, 0);
}

}  // namespace
