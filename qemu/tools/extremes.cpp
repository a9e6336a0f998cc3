// The extremes report (extremes.h): the classes, the measures, the children, the report files.
#include "qemu/tools/extremes.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "kernel/core/bound.h"
#include "kernel/core/fuzz.h"
#include "kernel/core/policy.h"
#include "kernel/scene/math3d.h"
#include "qemu/accuracy/guarded_surface.h"
#include "qemu/accuracy/measure.h"
#include "qemu/lib/command_line.h"
#include "qemu/lib/error.h"
#include "qemu/tools/trade.h"

namespace harness {

using namespace raster;

namespace {

constexpr uint8_t POISON = 0xEE;  // around every texture copy: a pixel of it was read outside
constexpr size_t MARGIN = 65536 + 4096;
constexpr double SLACK = 1e-6;    // the measure divides by the footprint as stored (a float)

// A texture and its copies inside POISON, which no texel holds.
struct PoisonedTexture {
    std::vector<uint8_t> texels, bordered, aligned, doubled;
    Texture tex;
    PoisonedTexture(int32_t w, int32_t h, Wrap wrap, const uint8_t* source = nullptr)
        : texels(2 * MARGIN + size_t(w) * size_t(h), POISON),
          bordered(2 * MARGIN + size_t(bordered_bytes(w, h)), POISON),
          aligned(ALIGNED256_BYTES, POISON),
          doubled(2 * MARGIN + (gets_doubled(w, h) ? size_t(doubled_bytes(w, h)) : 0), POISON) {
        uint8_t* t = texels.data() + MARGIN;
        if (source) std::memcpy(t, source, size_t(w) * size_t(h));
        else generate_texture(TextureKind::Xor, w, h, t);
        for (size_t i = 0; i < size_t(w) * size_t(h); ++i)
            if (t[i] == POISON) t[i] = POISON - 1;
        tex = Texture{t, w, h, wrap};
        prepare_texture(&tex, bordered.data() + MARGIN, aligned.data(), doubled.data() + MARGIN);
    }
};

// The measures of one mapper on one class.
struct Measurer {
    const Mapper& mapper;
    Axis axis;
    PolygonMeter meter;
    GuardedSurface surface;
    ExtremeRow& row;
    Measurer(const Mapper& m, ExtremeRow& r) : mapper(m), axis(home_axis(m)), meter(m, home_axis(m)), surface(ram_planar(m, home_axis(m))), row(r) {}

    // One polygon; with `centroid`, the drawn and the reference pixels' centroids and the largest
    // footprint error (the rotation sweep). False when the mapper did not draw it.
    bool measure(const Vertex* v, int n, const Texture& tex, double* centroid = nullptr, double* max_error = nullptr) {
        ++row.tried;
        surface.reset();
        RenderStats st;
        const SetupStatus status = draw_polygon(v, n, tex, mapper, axis, surface.target(), &st);
        const GuardedSurface::Scan scan = surface.scan(POISON);
        row.writes_outside += scan.written_outside;
        row.reads_outside += scan.inside_marked;
        if (status != SetupStatus::Ok) {
            ++row.refused[int(status) < 7 ? int(status) : 6];
            return false;
        }
        ++row.drawn;
        const ErrorBound b = mapper.bound(BoundContext{mapper, tex, axis, ClipRect{0, 0, SCREEN_WIDTH, SCREEN_HEIGHT}}, v, n);
        uint32_t differs = 0;
        double sums[4] = {0, 0, 0, 0}, counts[2] = {0, 0};
        bool drawn = false;
        AccuracyMetrics e = meter.measure(v, n, tex, &drawn, [&](int32_t x, int32_t y, bool rc, bool dc, double) {
            differs += rc != dc;
            row.gaps += rc && !dc;
            row.overdraw += dc && !rc;
            if (rc) sums[0] += x, sums[1] += y, ++counts[0];
            if (dc) sums[2] += x, sums[3] += y, ++counts[1];
        });
        row.compared += e.compared;
        row.sum_footprint += e.mean_footprint_error * double(e.compared);
        row.max_footprint = std::max(row.max_footprint, e.max_footprint_error);
        if (b.draws && e.max_footprint_error > b.footprint * (1 + SLACK) + SLACK) {
            ++row.bound_exceeded;
            if (std::getenv("MODEXLAB_EXTREMES_DEBUG")) {
                std::fprintf(stderr, "above bound: %s polygon %u: measured %.4f bound %.4f drawn by", mapper.name, row.tried, e.max_footprint_error, b.footprint);
                for (int k = 0; k < MAPPER_COUNT; ++k) if (st.mapper_polygons[k]) std::fprintf(stderr, " %s", MAPPERS[k].name);
                for (int k = 0; k < n; ++k) std::fprintf(stderr, " (%.4f %.4f w %.9g u %.9g v %.9g)", v[k].x.to_double(), v[k].y.to_double(), v[k].w, v[k].u, v[k].v);
                std::fprintf(stderr, "\n");
            }
        }
        if (b.draws && b.exact_coverage && differs) ++row.coverage_broken;
        if (centroid && counts[0] > 0 && counts[1] > 0)
            *centroid = std::hypot(sums[0] / counts[0] - sums[2] / counts[1], sums[1] / counts[0] - sums[3] / counts[1]);
        if (max_error) *max_error = e.max_footprint_error;
        return true;
    }
};

bool classic(const Mapper& m) { return std::string(m.family) == "classic"; }
constexpr double CLASSIC_LIMIT = 8192;

// The bank of fuzz_mapper's textures, poisoned (made once: the mappers only read them).
const std::vector<std::unique_ptr<PoisonedTexture>>& fuzz_bank() {
    static const auto bank = [] {
        std::vector<std::unique_ptr<PoisonedTexture>> b;
        for (int i = 0; i < FUZZ_TEXTURE_COUNT; ++i)
            b.push_back(std::make_unique<PoisonedTexture>(fuzz_texture_size(i).width, fuzz_texture_size(i).height, fuzz_texture_wrap(i)));
        return b;
    }();
    return bank;
}

const PoisonedTexture* pick_texture(const std::vector<std::unique_ptr<PoisonedTexture>>& bank, const Mapper& m, Random& r) {
    std::vector<const PoisonedTexture*> usable;
    for (const auto& t : bank)
        if (mapper_accepts(m, t->tex)) usable.push_back(t.get());
    return usable.empty() ? nullptr : usable[r.below(uint32_t(usable.size()))];
}

// A class of RandomPolygons (kernel/core/fuzz.h).
void random_class(Measurer& me, PolygonClass c, const ExtremesOptions& o) {
    const auto& bank = fuzz_bank();
    Random pick(o.seed * 16 + uint32_t(c));
    for (int i = 0; i < o.polygons; ++i) {
        const PoisonedTexture* t = pick_texture(bank, me.mapper, pick);
        if (!t) return;
        const bool cl = classic(me.mapper);
        RandomPolygons gen(pick.next(), cl ? CLASSIC_LIMIT : MAX_COORD_PIXELS, cl ? std::min(t->tex.width, t->tex.height) : 0);
        Vertex v[MAX_FUZZ_CORNERS];
        const int n = gen.next(v, c);
        me.measure(v, n, t->tex);
    }
}

// Texture coordinates at the format's limits (bases near +-2^24 texels, large offsets with tiny
// gradients) on every texture size the format allows, odd and non-square, repeat and clamp.
void texture_limits(Measurer& me, const ExtremesOptions& o) {
    static const auto bank = [] {
        const int32_t sizes[][2] = {{1, 1}, {2, 2}, {3, 5}, {17, 256}, {64, 64}, {100, 37}, {256, 256}, {333, 1024}, {1024, 3}, {1024, 1024}};
        std::vector<std::unique_ptr<PoisonedTexture>> b;
        for (const auto& s : sizes)
            for (Wrap w : {Wrap::Repeat, Wrap::Clamp}) b.push_back(std::make_unique<PoisonedTexture>(s[0], s[1], w));
        return b;
    }();
    Random r(o.seed * 16 + 101);
    for (int i = 0; i < o.polygons; ++i) {
        const PoisonedTexture* t = pick_texture(bank, me.mapper, r);
        if (!t) return;
        const double radius = r.octaves(2, 8), gradient = r.below(2) ? r.octaves(-16, -4) : r.octaves(-4, 4);
        const double reach = radius * 2 * gradient, limit = classic(me.mapper) ? double(std::min(t->tex.width, t->tex.height)) : MAX_UV;
        // the base as far out as the texture coordinates may go, on either side
        const double u0 = classic(me.mapper) ? r.uniform(0, std::max(0.0, limit - reach)) : (r.below(2) ? 1 : -1) * (limit - reach * r.uniform(1, 2));
        const double v0 = classic(me.mapper) ? r.uniform(0, std::max(0.0, limit - reach)) : (r.below(2) ? 1 : -1) * (limit - reach * r.uniform(1, 2));
        const double cx = r.uniform(0, 320), cy = r.uniform(0, 240), angle = r.uniform(0, 360);
        Vertex v[4];
        for (int k = 0; k < 4; ++k) {
            double s, c;
            sin_cos_degrees(angle + 90.0 * k, &s, &c);
            const double du = (c + 1) * radius * gradient, dv = (s + 1) * radius * gradient;
            v[k] = Vertex{snap(cx + radius * c), snap(cy + radius * s), 1, std::clamp(u0 + du, -MAX_UV, MAX_UV), std::clamp(v0 + dv, -MAX_UV, MAX_UV)};
            if (classic(me.mapper)) v[k].u = std::clamp(v[k].u, 0.0, limit), v[k].v = std::clamp(v[k].v, 0.0, limit);
        }
        me.measure(v, 4, t->tex);
    }
}

// Strong perspective: quads whose far side has 2^k times the near side's w, k from 0 to 24.
void perspective(Measurer& me, const ExtremesOptions& o) {
    random_class(me, PolygonClass::Perspective, o);
    PoisonedTexture t(256, 256, Wrap::Repeat);
    if (!mapper_accepts(me.mapper, t.tex)) return;
    Random r(o.seed * 16 + 102);
    for (int i = 0; i < o.polygons; ++i) {
        const double ratio = std::ldexp(1.0, i % 25), angle = r.uniform(0, 360), radius = r.octaves(3, 9);
        const double cx = r.uniform(0, 320), cy = r.uniform(0, 240), wn = r.octaves(-4, 0);
        Vertex v[4];
        for (int k = 0; k < 4; ++k) {
            double s, c;
            sin_cos_degrees(angle + 90.0 * k, &s, &c);
            const double w = k < 2 ? wn : std::min(wn * ratio, MAX_W);
            v[k] = Vertex{snap(cx + radius * c), snap(cy + radius * s), w, k == 1 || k == 2 ? 255.0 : 0.0, k >= 2 ? 255.0 : 0.0};
        }
        me.measure(v, 4, t.tex);
    }
}

// A textured quad turned through 360 degrees in 1-degree steps about a point off the pixel grid:
// coverage and error must not depend on the angle.
void rotation(Measurer& me, ExtremeRow& row, int step) {
    PoisonedTexture t(256, 256, Wrap::Repeat);  // every mapper takes it; the quad maps 64 x 64 of it
    if (!mapper_accepts(me.mapper, t.tex)) return;
    double shift = 0, lo = 1e300, hi = 0;
    for (int deg = 0; deg < 360; deg += step) {
        Vertex v[4];
        for (int k = 0; k < 4; ++k) {
            double s, c;
            sin_cos_degrees(deg + 45.0 + 90.0 * k, &s, &c);
            v[k] = Vertex{snap(160.3 + 70 * c), snap(120.7 + 70 * s), 1, k == 1 || k == 2 ? 64.0 : 0.0, k >= 2 ? 64.0 : 0.0};
        }
        double centroid = 0, err = 0;
        if (!me.measure(v, 4, t.tex, &centroid, &err)) continue;
        shift = std::max(shift, centroid);
        lo = std::min(lo, err), hi = std::max(hi, err);
    }
    row.centroid_shift = shift;
    row.error_spread = hi >= lo ? hi - lo : 0;
}

// The near plane: a camera walking through a wall, then down through a floor, until w reaches the
// clip limits; the polygons clipped to slivers of the near plane, frame by frame.
void near_plane(Measurer& me, const ExtremesOptions& o) {
    const std::string text =
        "modexlab-scene 2\n"
        "texture bricks checker 64 64\ntexture tiles grid 256 256\n"
        "mesh wall\nv -4 -2 0\nv 4 -2 0\nv 4 2 0\nv -4 2 0\nvt 0 4\nvt 8 4\nvt 8 0\nvt 0 0\nf 1/1 2/2 3/3 4/4\nend\n"
        "mesh floor\nv -4 -1 20\nv 4 -1 20\nv 4 -1 -20\nv -4 -1 -20\nvt 0 40\nvt 8 40\nvt 8 0\nvt 0 0\nf 1/1 2/2 3/3 4/4\nend\n"
        "object wall\nmesh wall\ntexture bricks\ncull none\nend\nobject floor\nmesh floor\ntexture tiles\ncull none\nend\n"
        "camera\nfov 90\nnear 0.000016\nfar 16000000\n"
        "key 0 0.3 0.2 3 0 0 -5\nkey 2 0.3 0.2 -0.5 0 0 -8\nkey 2.5 0.3 0.2 -0.5 0.3 -5 -0.6\nkey 4 0.3 -1.5 -0.5 0.3 -6 -0.6\n"
        "end\nframes 120\n";
    LoadedWorld w = parse_world_text(text, "near-plane", {});
    std::map<const uint8_t*, std::unique_ptr<PoisonedTexture>> poisoned;
    const int frames = std::max(2, std::min(120, o.polygons / 2));
    for (int f = 0; f < frames; ++f) {
        auto frame = world_frame(w, int32_t(f * 120 / frames));
        const Vertex* v = frame->vertices;
        for (int32_t i = 0; i < frame->polygon_count; ++i) {
            const Texture& src = w.textures->objects[frame->polygon_object[i]];
            auto& p = poisoned[src.texels];
            if (!p) p = std::make_unique<PoisonedTexture>(src.width, src.height, src.wrap, src.texels);
            me.measure(v, frame->polygon_size[i], p->tex);
            v += frame->polygon_size[i];
        }
    }
}

}  // namespace

uint32_t ExtremeRow::refused_total() const {
    uint32_t n = 0;
    for (int s = 1; s < 7; ++s) n += refused[s];
    return n;
}

std::string ExtremeRow::broken_promise() const {
    if (!fault.empty()) return "fault (" + fault + ")";
    if (hang) return "hang";
    if (writes_outside) return "writes outside the clip";
    if (bound_exceeded) return "error above its bound";
    if (coverage_broken) return "coverage not exact";
    return "";
}

const std::vector<std::string>& extreme_classes() {
    static const std::vector<std::string> names = {"near-plane", "convex", "sliver", "tiny", "huge", "degenerate", "perspective",
                                                   "anywhere", "beyond", "texture-limits", "rotation"};
    return names;
}

ExtremeRow run_extreme_class(const Mapper& mapper, const std::string& cls, const ExtremesOptions& o) {
    ExtremeRow row;
    row.mapper = mapper.name, row.cls = cls;
    Measurer me(mapper, row);
    if (cls == "near-plane") near_plane(me, o);
    else if (cls == "perspective") perspective(me, o);
    else if (cls == "texture-limits") texture_limits(me, o);
    else if (cls == "rotation") rotation(me, row, o.rotation_step);
    else {
        bool found = false;
        for (int c = 0; c < POLYGON_CLASS_COUNT && !found; ++c)
            if (cls == polygon_class_name(PolygonClass(c))) random_class(me, PolygonClass(c), o), found = true;
        if (!found) throw UsageError("unknown class '" + cls + "'");
    }
    return row;
}

namespace {

// A row through a pipe: the numbers as text, one per line.
std::string encode(const ExtremeRow& r) {
    std::string s = std::to_string(r.tried) + "\n" + std::to_string(r.drawn) + "\n";
    for (uint32_t x : r.refused) s += std::to_string(x) + "\n";
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.17g\n%.17g\n%.17g\n%.17g\n", r.max_footprint, r.sum_footprint, r.centroid_shift, r.error_spread);
    s += buf;
    for (uint64_t x : {r.compared, r.gaps, r.overdraw, r.reads_outside, r.writes_outside, uint64_t(r.bound_exceeded), uint64_t(r.coverage_broken)})
        s += std::to_string(x) + "\n";
    return s;
}

bool decode(const std::string& s, ExtremeRow* r) {
    std::istringstream in(s);
    in >> r->tried >> r->drawn;
    for (uint32_t& x : r->refused) in >> x;
    in >> r->max_footprint >> r->sum_footprint >> r->centroid_shift >> r->error_spread;
    in >> r->compared >> r->gaps >> r->overdraw >> r->reads_outside >> r->writes_outside >> r->bound_exceeded >> r->coverage_broken;
    return bool(in);
}

struct Child {
    pid_t pid;
    int fd;
    size_t index;
    std::string out;
    std::chrono::steady_clock::time_point started;
};

}  // namespace

std::vector<ExtremeRow> run_extremes(const ExtremesOptions& o, const std::function<void(const ExtremeRow&, size_t, size_t)>& done) {
    std::vector<ExtremeRow> rows;
    for (int m = 0; m < MAPPER_COUNT; ++m) {
        if (!o.mappers.empty() && std::find(o.mappers.begin(), o.mappers.end(), MAPPERS[m].name) == o.mappers.end()) continue;
        for (const std::string& c : extreme_classes())
            if (o.classes.empty() || std::find(o.classes.begin(), o.classes.end(), c) != o.classes.end()) {
                ExtremeRow r;
                r.mapper = MAPPERS[m].name, r.cls = c;
                rows.push_back(r);
            }
    }
    const size_t parallel = std::max<size_t>(1, std::min<size_t>(2, size_t(sysconf(_SC_NPROCESSORS_ONLN))));
    std::vector<Child> running;
    size_t next = 0, finished = 0;
    auto finish = [&](Child& c, int status, bool timed_out) {
        ExtremeRow& r = rows[c.index];
        if (timed_out) r.hang = true;
        else if (WIFSIGNALED(status)) r.fault = strsignal(WTERMSIG(status));
        else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !decode(c.out, &r)) r.fault = "ended with status " + std::to_string(WEXITSTATUS(status));
        ::close(c.fd);
        if (done) done(r, ++finished, rows.size());
    };
    while (next < rows.size() || !running.empty()) {
        while (next < rows.size() && running.size() < parallel) {
            int fds[2];
            if (::pipe(fds) != 0) throw HarnessError("extremes: pipe failed");
            const pid_t pid = ::fork();
            if (pid < 0) throw HarnessError("extremes: fork failed");
            if (pid == 0) {
                ::close(fds[0]);
                const ExtremeRow r = run_extreme_class(*find_mapper(rows[next].mapper.c_str()), rows[next].cls, o);
                const std::string s = encode(r);
                for (size_t at = 0; at < s.size();) {
                    const ssize_t n = ::write(fds[1], s.data() + at, s.size() - at);
                    if (n <= 0) ::_exit(3);
                    at += size_t(n);
                }
                ::_exit(0);
            }
            ::close(fds[1]);
            running.push_back(Child{pid, fds[0], next++, "", std::chrono::steady_clock::now()});
        }
        std::vector<pollfd> polls;
        for (const Child& c : running) polls.push_back(pollfd{c.fd, POLLIN, 0});
        ::poll(polls.data(), polls.size(), 1000);
        for (size_t i = 0; i < running.size();) {
            Child& c = running[i];
            char buf[4096];
            bool ended = false;
            if (polls[i].revents) {
                const ssize_t n = ::read(c.fd, buf, sizeof buf);
                if (n > 0) c.out.append(buf, size_t(n));
                else ended = true;
            }
            const bool late = std::chrono::steady_clock::now() - c.started > std::chrono::seconds(o.timeout_seconds);
            if (late) ::kill(c.pid, SIGKILL);
            if (ended || late) {
                int status = 0;
                ::waitpid(c.pid, &status, 0);
                finish(c, status, late && !ended);
                running.erase(running.begin() + std::ptrdiff_t(i));
                polls.erase(polls.begin() + std::ptrdiff_t(i));
                continue;
            }
            ++i;
        }
    }
    return rows;
}

void write_extremes_report(const std::vector<ExtremeRow>& rows, const ExtremesOptions& o, const std::string& dir) {
    std::filesystem::create_directories(dir);
    std::ofstream csv(dir + "/extremes.csv");
    csv << "mapper,class,tried,drawn,refused,refused_degenerate,refused_not_convex,refused_too_many_vertices,refused_out_of_range,"
           "refused_outside_texture,refused_unsupported,max_footprint_error,mean_footprint_error,gaps,overdraw,reads_outside_texture,"
           "writes_outside_clip,bound_exceeded,coverage_broken,fault,hang,centroid_shift,error_spread,broken_promise\n";
    for (const ExtremeRow& r : rows) {
        csv << r.mapper << "," << r.cls << "," << r.tried << "," << r.drawn << "," << r.refused_total();
        for (int s = 1; s < 7; ++s) csv << "," << r.refused[s];
        csv << "," << fixed(r.max_footprint, 4) << "," << fixed(r.mean_footprint(), 4) << "," << r.gaps << "," << r.overdraw << ","
            << r.reads_outside << "," << r.writes_outside << "," << r.bound_exceeded << "," << r.coverage_broken << "," << r.fault << ","
            << (r.hang ? 1 : 0) << "," << (r.centroid_shift >= 0 ? fixed(r.centroid_shift, 3) : "") << ","
            << (r.error_spread >= 0 ? fixed(r.error_spread, 3) : "") << "," << r.broken_promise() << "\n";
    }
    std::ofstream md(dir + "/extremes.md");
    md << "# Stability at the extremes\n\n"
       << "`make extremes` (modexlab-extremes, seed " << o.seed << ", " << o.polygons
       << " polygons a random class; docs/accuracy.md, \"Stability at the extremes\"): every mapper through each class, measured "
          "polygon by polygon against the exact reference on the host (the C++ twins). Footprint errors over the pixels both "
          "cover; gaps and overdraw in pixels; reads outside: pixels drawn from outside the texture and its copies; writes "
          "outside: bytes outside the clip rectangle; bound: polygons measured above the mapper's own bound; each mapper and "
          "class ran in a child process (fault: the signal that ended it; hang: past "
       << o.timeout_seconds << " s).\n\n";
    uint32_t broken = 0;
    for (const ExtremeRow& r : rows) broken += !r.broken_promise().empty();
    md << "Broken promises: " << broken << " of " << rows.size() << " rows.\n\n";
    for (const std::string& cls : extreme_classes()) {
        bool header = false;
        for (const ExtremeRow& r : rows) {
            if (r.cls != cls) continue;
            if (!header) {
                header = true;
                md << "\n## " << cls << "\n\n| mapper | tried | drawn | refused (why) | max / mean footprint error | gaps | overdraw | reads outside | writes outside | above bound | broken |"
                   << (cls == "rotation" ? " centroid shift | error spread |" : "") << "\n|---|--:|--:|---|--:|--:|--:|--:|--:|--:|---|"
                   << (cls == "rotation" ? "--:|--:|" : "") << "\n";
            }
            std::string why;
            for (int s = 1; s < 7; ++s)
                if (r.refused[s]) why += (why.empty() ? "" : ", ") + std::string(setup_status_name(SetupStatus(s))) + " " + std::to_string(r.refused[s]);
            md << "| " << r.mapper << " | " << r.tried << " | " << r.drawn << " | " << r.refused_total() << (why.empty() ? "" : " (" + why + ")")
               << " | " << fixed(r.max_footprint, 3) << " / " << fixed(r.mean_footprint(), 3) << " | " << r.gaps << " | " << r.overdraw << " | "
               << r.reads_outside << " | " << r.writes_outside << " | " << r.bound_exceeded << " | " << r.broken_promise() << " |";
            if (cls == "rotation") md << " " << fixed(r.centroid_shift, 3) << " | " << fixed(r.error_spread, 3) << " |";
            md << "\n";
        }
    }
}

}  // namespace harness
