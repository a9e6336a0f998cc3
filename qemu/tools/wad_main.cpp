// modexlab-wad: lists a Doom WAD's flats and wall textures, or extracts some as 8-bit BMPs in the WAD's palette.
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "qemu/lib/command_line.h"
#include "qemu/lib/error.h"
#include "qemu/tools/wad.h"

namespace {

using namespace harness;

const char* USAGE =
    "usage: modexlab-wad WAD --list\n"
    "       modexlab-wad WAD OUTDIR NAME...\n"
    "  --list  print every flat and wall texture: kind, name, width x height\n"
    "  NAME    a flat or a wall texture, in any case; written as OUTDIR/<name in lower case>.bmp (8-bit,\n"
    "          the WAD's palette). A name that is both a flat and a texture needs a prefix:\n"
    "          flat:NAME or texture:NAME (the prefixes are always accepted).\n"
    "  Texture pixels no patch covers are palette index 0.\n";

struct Request {
    std::string argument;  // as given, for messages
    std::string name;      // upper case, prefix removed
    bool want_flat = true, want_texture = true;
};

Request parse_request(const std::string& argument) {
    Request r;
    r.argument = argument;
    r.name = argument;
    const std::string upper = wad_upper(argument);
    if (upper.rfind("FLAT:", 0) == 0) {
        r.name = argument.substr(5);
        r.want_texture = false;
    } else if (upper.rfind("TEXTURE:", 0) == 0) {
        r.name = argument.substr(8);
        r.want_flat = false;
    }
    if (r.name.empty()) throw UsageError("'" + argument + "' names nothing");
    r.name = wad_upper(r.name);
    return r;
}

// The output file is named after the lump; a name that could leave OUTDIR or hide is refused.
std::string file_name_for(const std::string& name) {
    std::string out;
    for (char c : name) {
        unsigned char u = static_cast<unsigned char>(c);
        if (u < 0x21 || u >= 0x7F || c == '/')
            throw HarnessError("'" + name + "' cannot be a file name (it holds a '/', a space or a control character)");
        out += (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
    }
    return out + ".bmp";
}

struct Job {
    WadKind kind;
    std::string name;
    std::string file;
};

int list(const Wad& wad) {
    for (const WadListEntry& e : wad.list()) {
        if (e.problem.empty()) std::printf("%-7s %-8s %dx%d\n", wad_kind_name(e.kind), e.name.c_str(), e.width, e.height);
        else std::printf("%-7s %-8s unusable: %s\n", wad_kind_name(e.kind), e.name.c_str(), e.problem.c_str());
    }
    return 0;
}

int extract(const Wad& wad, const std::string& out_dir, const std::vector<Request>& requests) {
    // Resolve and compose everything before writing, so a bad name leaves no partial output.
    std::vector<Job> jobs;
    std::map<std::string, size_t> by_file;
    for (const Request& r : requests) {
        const bool flat = r.want_flat && wad.has_flat(r.name);
        const bool texture = r.want_texture && wad.has_texture(r.name);
        if (flat && texture)
            throw HarnessError("'" + r.name + "' is both a flat and a wall texture in " + wad.label() + "; say flat:" + r.name +
                               " or texture:" + r.name);
        if (!flat && !texture) {
            const char* what = !r.want_texture ? "flat" : !r.want_flat ? "wall texture" : "flat or wall texture";
            throw HarnessError(std::string("no ") + what + " named '" + r.name + "' in " + wad.label() +
                               " (modexlab-wad " + wad.label() + " --list shows them all)");
        }
        Job job{flat ? WadKind::Flat : WadKind::Texture, r.name, file_name_for(r.name)};
        auto [it, added] = by_file.emplace(job.file, jobs.size());
        if (!added) {
            const Job& earlier = jobs[it->second];
            if (earlier.kind == job.kind) continue;  // asked twice
            throw HarnessError("the flat and the wall texture " + r.name + " would both be written to " + job.file +
                               "; extract them into different directories");
        }
        jobs.push_back(std::move(job));
    }
    std::vector<WadImage> images;
    for (const Job& j : jobs) images.push_back(j.kind == WadKind::Flat ? wad.flat(j.name) : wad.texture(j.name));

    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    if (ec) throw HarnessError(out_dir + ": cannot create the directory (" + ec.message() + ")");
    for (size_t k = 0; k < jobs.size(); ++k) {
        const std::string path = (std::filesystem::path(out_dir) / jobs[k].file).string();
        write_bmp8(path, images[k]);
        std::printf("%s %s %dx%d\n", path.c_str(), wad_kind_name(jobs[k].kind), images[k].width, images[k].height);
    }
    return 0;
}

int wad_tool(const std::vector<std::string>& words) {
    const CommandLine args = parse_command_line(words, {}, {"--list"});
    if (args.help()) return show_usage(USAGE);
    const bool list_mode = args.has("--list");
    const std::vector<std::string>& positional = args.positionals();
    for (const std::string& p : positional)
        if (p.empty()) throw UsageError("an empty argument");
    if (positional.empty()) throw UsageError("no WAD");
    if (list_mode && positional.size() != 1) throw UsageError("--list takes only the WAD");
    if (!list_mode && positional.size() < 3) throw UsageError(positional.size() == 1 ? "no OUTDIR and no NAME" : "no NAME to extract");
    std::vector<Request> requests;
    for (size_t k = 2; k < positional.size(); ++k) requests.push_back(parse_request(positional[k]));
    const Wad wad = Wad::load(positional[0]);
    return list_mode ? list(wad) : extract(wad, positional[1], requests);
}

}  // namespace

int main(int argc, char** argv) {
    return run_cli("modexlab-wad", USAGE, argc, argv, wad_tool);
}
