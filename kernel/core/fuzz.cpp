// Random extreme polygons and a mapper drawing them (fuzz.h).
#include "kernel/core/fuzz.h"

#include "kernel/core/policy.h"
#include "kernel/lib/words.h"
#include "kernel/scene/math3d.h"

namespace raster {

namespace {

double clamp(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }

constexpr double CLASSIC_LIMIT = 8192;  // the classics' coordinates (kernel/mappers/classic.h)
constexpr double INF = __builtin_inf();

}  // namespace

const char* polygon_class_name(PolygonClass c) {
    constexpr const char* NAMES[POLYGON_CLASS_COUNT] = {"convex", "sliver", "tiny", "huge", "degenerate", "perspective", "anywhere", "beyond"};
    return NAMES[int(c) % POLYGON_CLASS_COUNT];
}

// The mixture, in 64ths: convex polygons (24), slivers and needles (12), below a pixel (8), huge (1),
// collinear or repeated corners (4), strong perspective (8), corners anywhere (5), a value beyond
// its limit or not finite (2).
int RandomPolygons::next(Vertex* out) {
    const uint32_t k = rng_.below(64);
    const PolygonClass c = k < 24   ? PolygonClass::Convex
                           : k < 36 ? PolygonClass::Sliver
                           : k < 44 ? PolygonClass::Tiny
                           : k < 45 ? PolygonClass::Huge
                           : k < 49 ? PolygonClass::Degenerate
                           : k < 57 ? PolygonClass::Perspective
                           : k < 62 ? PolygonClass::Anywhere
                                    : PolygonClass::Beyond;
    return next(out, c);
}

int RandomPolygons::next(Vertex* out, PolygonClass kind) {
    Random& r = rng_;
    const double L = limit_;
    const double cx = r.below(8) ? r.uniform(-20, 340) : r.uniform(-L, L), cy = r.below(8) ? r.uniform(-20, 260) : r.uniform(-L, L);
    const double u0 = inside_ ? r.uniform(0, inside_) : r.below(4) ? r.uniform(-300, 300) : r.uniform(-MAX_UV, MAX_UV);
    const double v0 = inside_ ? r.uniform(0, inside_) : r.below(4) ? r.uniform(-300, 300) : r.uniform(-MAX_UV, MAX_UV);
    const double gradient = r.below(4) ? r.octaves(-6, 3) : r.octaves(-16, 12);  // texels a pixel
    const double angle = r.uniform(0, 360);
    double sin_a, cos_a;
    sin_cos_degrees(angle, &sin_a, &cos_a);
    auto w = [&] { return r.below(4) ? r.octaves(-2, 6) : r.octaves(-16, 24); };
    int n = 0;
    // a corner: the texture mapped by (u0, v0) + the gradient, turned by the angle
    auto add = [&](double x, double y, double ww) {
        x = clamp(x, -L, L), y = clamp(y, -L, L);
        const double du = (x - cx) * gradient, dv = (y - cy) * gradient;
        double u = u0 + du * cos_a - dv * sin_a, v = v0 + du * sin_a + dv * cos_a;
        u = inside_ ? clamp(u, 0, inside_) : clamp(u, -MAX_UV, MAX_UV);
        v = inside_ ? clamp(v, 0, inside_) : clamp(v, -MAX_UV, MAX_UV);
        out[n++] = Vertex{snap(x), snap(y), clamp(ww, MIN_W, MAX_W), u, v};
    };
    if (kind == PolygonClass::Convex) {  // 3 to 12 corners on an ellipse, 1 to 1024 pixels across
        const int corners = r.below(2) ? 3 : 3 + int(r.below(10));
        const double radius = r.octaves(-1, 8), squash = r.below(3) ? 1 : r.octaves(-8, 0);
        for (int k = 0; k < corners; ++k) {
            double s, c;
            sin_cos_degrees(angle + 360.0 * k / corners, &s, &c);
            const double x = radius * c, y = radius * squash * s;
            add(cx + x * cos_a - y * sin_a, cy + x * sin_a + y * cos_a, w());
        }
    } else if (kind == PolygonClass::Sliver) {  // 1/256 to 4 pixels thick, 1 to 1024 long
        const double length = r.octaves(0, 9), thick = r.octaves(-8, 1), along = r.uniform(0, 1);
        add(cx, cy, w());
        add(cx + cos_a * length, cy + sin_a * length, w());
        add(cx + cos_a * length * along - sin_a * thick, cy + sin_a * length * along + cos_a * thick, w());
    } else if (kind == PolygonClass::Tiny) {  // inside one pixel
        for (int k = 0; k < 3; ++k) add(cx + r.uniform(0, 1), cy + r.uniform(0, 1), w());
    } else if (kind == PolygonClass::Huge) {  // corners at the limits
        for (int k = 0; k < 3; ++k) add(r.below(2) ? -L : L, r.uniform(-L, L), w());
    } else if (kind == PolygonClass::Degenerate) {  // collinear or repeated corners
        const double length = r.octaves(0, 9);
        add(cx, cy, w());
        add(cx + cos_a * length, cy + sin_a * length, w());
        if (r.below(2)) add(cx + cos_a * length * 0.5, cy + sin_a * length * 0.5, w());
        else add(cx, cy, w());
    } else if (kind == PolygonClass::Perspective) {  // w from near 2^-16 to near 2^24 across a quad
        const double radius = r.octaves(2, 9);
        for (int k = 0; k < 4; ++k) {
            double s, c;
            sin_cos_degrees(angle + 90.0 * k, &s, &c);
            add(cx + radius * c, cy + radius * s, k < 2 ? MIN_W * r.uniform(1, 16) : MAX_W / r.uniform(1, 16));
        }
    } else if (kind == PolygonClass::Anywhere) {  // corners anywhere within the limits
        const int corners = 3 + int(r.below(6));
        for (int k = 0; k < corners; ++k) add(r.uniform(-L, L), r.uniform(-L, L), r.octaves(-16, 24));
    } else {  // Beyond: one value beyond its limit or not finite, refused, never drawn
        for (int k = 0; k < 3; ++k) add(cx + r.uniform(-50, 50), cy + r.uniform(-50, 50), w());
        const double BEYOND[] = {2 * MAX_UV, -2 * MAX_UV, INF, -INF, __builtin_nan("")};
        const double bad = BEYOND[r.below(5)];
        Vertex& v = out[r.below(3)];
        switch (r.below(5)) {
        case 0: v.w = bad > 0 ? bad : 0; break;
        case 1: v.u = bad; break;
        case 2: v.v = bad; break;
        case 3: v.w = MIN_W / 2; break;
        default: v.w = MAX_W * 2; break;
        }
    }
    return n;
}

FuzzStats fuzz_mapper(const Mapper& mapper, uint32_t seed, uint32_t count, const Texture* bank, FuzzSurface surface, void* ctx,
                      Variant variant, const Watch* watch) {
    FuzzStats f;
    const bool classic = lib::StrView{mapper.family, lib::c_length(mapper.family)}.equals("classic");
    int usable[FUZZ_TEXTURE_COUNT], usable_count = 0;
    for (int i = 0; i < FUZZ_TEXTURE_COUNT; ++i)
        if (mapper_accepts(mapper, bank[i])) usable[usable_count++] = i;
    Axis axes[2];
    int axis_count = 0;
    for (int a = 0; a < 2; ++a)
        if (mapper_walks(mapper, Axis(a))) axes[axis_count++] = Axis(a);
    if (usable_count == 0 || axis_count == 0) return f;
    Random pick(seed);
    RenderStats watched;  // the watch's: whether it stopped the run
    while (f.tried < count) {
        static_assert(FUZZ_BATCH % Watch::WATCH_EVERY == 0, "the watch is asked between batches");
        if (watch && watch->stops(f.tried, count, &watched)) break;
        RenderStats stats;  // a batch's (its pixel count fits 32 bits; the run's need not)
        const Texture& tex = bank[usable[pick.below(uint32_t(usable_count))]];
        const Axis axis = axes[pick.below(uint32_t(axis_count))];
        const bool planar = ram_planar(mapper, axis);
        uint8_t* pixels = surface(ctx, planar);
        for (int32_t i = 0; i < SCREEN_PIXELS; ++i) pixels[i] = FUZZ_FILL;
        Target target = ram_target(pixels, planar);
        target.clip = FUZZ_CLIP;
        const int32_t smaller_side = tex.width < tex.height ? tex.width : tex.height;
        // texture coordinates inside the texture for the classics, and on a clamped texture for the
        // mappers that draw it only so (NEED_TILED256_OR_INSIDE, NEED_POW2_OR_INSIDE: they refuse the rest)
        const bool inside = classic || (tex.wrap == Wrap::Clamp && (mapper.needs & (NEED_TILED256_OR_INSIDE | NEED_POW2_OR_INSIDE)));
        RandomPolygons polygons(pick.next(), classic ? CLASSIC_LIMIT : MAX_COORD_PIXELS, inside ? smaller_side : 0);
        const uint32_t batch = count - f.tried < FUZZ_BATCH ? count - f.tried : FUZZ_BATCH;
        for (uint32_t i = 0; i < batch; ++i) {
            Vertex corners[MAX_FUZZ_CORNERS];
            const int n = polygons.next(corners);
            if (watch) watch->drawing(mapper, f.tried + i);
            const SetupStatus s = draw_polygon(corners, n, tex, mapper, axis, target, &stats, variant);
            ++f.by_status[int(s) < 7 ? int(s) : 6];
        }
        f.tried += batch;
        ++f.batches;
        f.pixels += stats.pixels;
        uint32_t outside = 0;
        for (int32_t y = 0; y < SCREEN_HEIGHT; ++y)
            for (int32_t x = 0; x < SCREEN_WIDTH; ++x) {
                if (x >= FUZZ_CLIP.x0 && x < FUZZ_CLIP.x1 && y >= FUZZ_CLIP.y0 && y < FUZZ_CLIP.y1) continue;
                const int32_t at = planar ? (x & 3) * PLANE_BYTES + y * PLANE_ROW_BYTES + (x >> 2) : y * SCREEN_WIDTH + x;
                outside += pixels[at] != FUZZ_FILL;
            }
        if (outside && !f.first_bad_batch) f.first_bad_batch = f.batches;
        f.written_outside += outside;
    }
    if (watch) watch->drawn();
    f.interrupted = watched.interrupted;
    return f;
}

}  // namespace raster
