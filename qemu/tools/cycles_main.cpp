// modexlab-cycles: real host cycles of each mapper drawing frames of real scenes, as a 32-bit static
// program with the NASM loops, timed by rdtsc (docs/bench.md, "Real cycles on the host").
#include <x86intrin.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "kernel/scene/frame.h"
#include "kernel/core/mapper.h"
#include "kernel/core/policy.h"
#include "kernel/scene/world.h"
#include "qemu/lib/choice_lists.h"

namespace {

using namespace raster;

constexpr int REPEATS = 9;

std::vector<std::string> g_dirs;  // where texture files are looked for
std::vector<std::vector<uint8_t>> g_files;

bool read_file(const std::string& path, std::vector<uint8_t>* out) {
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return false;
    out->clear();
    uint8_t buf[65536];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) out->insert(out->end(), buf, buf + n);
    std::fclose(f);
    return true;
}

bool find_file(const void*, lib::StrView name, const uint8_t** data, size_t* size) {
    for (const std::string& dir : g_dirs) {
        std::vector<uint8_t> bytes;
        if (!read_file(dir + "/" + std::string(name.data, name.size), &bytes)) continue;
        g_files.push_back(std::move(bytes));
        *data = g_files.back().data(), *size = g_files.back().size();
        return true;
    }
    return false;
}

[[noreturn]] void fail(const std::string& why) {
    std::fprintf(stderr, "modexlab-cycles: %s\n", why.c_str());
    std::exit(1);
}

std::vector<std::string> split_commas(const char* s) {
    std::vector<std::string> out;
    std::string item;
    for (const char* p = s;; ++p) {
        if (*p == ',' || !*p) {
            if (!item.empty()) out.push_back(item);
            item.clear();
            if (!*p) break;
        } else {
            item += *p;
        }
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: modexlab-cycles SCENE.scene,... MAPPER[@BUDGET],... FRAMES TEXTURE_DIR\n"
                             "  times each mapper drawing FRAMES frames of each scene (spread over its animation)\n");
        return 2;
    }
    std::vector<std::string> scenes = split_commas(argv[1]), mapper_names = split_commas(argv[2]);
    int frames = std::atoi(argv[3]);
    if (frames < 1 || frames > 1000) fail("FRAMES takes 1..1000");
    auto world = std::make_unique<HostWorld>();
    auto textures = std::make_unique<HostTextureSet>();
    auto frame = std::make_unique<HostFrame>();
    auto scratch = std::make_unique<HostFrameScratch>();
    std::vector<uint8_t> surface(SCREEN_PIXELS);
    for (const std::string& path : scenes) {
        std::vector<uint8_t> text;
        if (!read_file(path, &text)) fail(path + ": cannot read");
        size_t slash = path.rfind('/');
        g_dirs = {slash == std::string::npos ? "." : path.substr(0, slash), argv[4]};
        g_files.clear();
        FileResolver files;
        files.find = find_file;
        ParseError e;
        if (!parse_world(reinterpret_cast<const char*>(text.data()), text.size(), files, world.get(), &e))
            fail(path + ":" + std::to_string(e.line) + ": " + e.message);
        world->budget.lists = harness::host_choice_lists();
        build_texture_set(*world, textures.get());
        std::string name = path.substr(slash == std::string::npos ? 0 : slash + 1);
        name = name.substr(0, name.rfind('.'));
        for (const std::string& full_name : mapper_names) {
            // auto@B: auto at a budget of B footprints with exact coverage (the bench's rows)
            const size_t at = full_name.find('@');
            const std::string mapper_name = full_name.substr(0, at);
            const Mapper* m = find_mapper({mapper_name.data(), mapper_name.size()});
            if (!m) fail("unknown mapper '" + mapper_name + "'");
            Budget budget;
            if (at != std::string::npos) {
                char* end = nullptr;
                const std::string b = full_name.substr(at + 1);
                budget = Budget{true, std::strtod(b.c_str(), &end), true, CostTarget::Icount, harness::host_choice_lists()};
                if (!m->is_auto || b.empty() || *end || !(budget.max_error >= 0)) fail("'" + full_name + "': only auto takes @BUDGET, a number of footprints from 0");
            }
            const Axis axis = home_axis(*m);
            const bool planar = ram_planar(*m, axis);
            uint64_t pixels = 0, cycles = 0;
            for (int i = 0; i < frames; ++i) {
                build_frame(*world, int32_t(int64_t(i) * world->frames / frames), frame.get(), scratch.get());
                if (at != std::string::npos) frame->budget = budget;
                uint64_t best = ~uint64_t(0);
                RenderStats stats;
                for (int r = 0; r < REPEATS; ++r) {
                    std::memset(surface.data(), 0, surface.size());
                    Target t = ram_target(surface.data(), planar);
                    uint64_t t0 = __rdtsc();
                    stats = render_frame(*frame, *textures, *m, axis, t, Variant::Asm);
                    uint64_t t1 = __rdtsc();
                    if (t1 - t0 < best) best = t1 - t0;
                }
                pixels += stats.pixels;
                cycles += best;
            }
            std::printf("%s %s %llu %llu\n", name.c_str(), full_name.c_str(), (unsigned long long)pixels, (unsigned long long)cycles);
            std::fflush(stdout);
        }
    }
    return 0;
}
