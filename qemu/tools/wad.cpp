// Reading Doom WADs: the header and directory, lumps by name, PLAYPAL, flats and the graphics list;
// pictures and wall textures are in wad_texture.cpp.
#include "qemu/tools/wad.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "kernel/core/texture.h"
#include "qemu/lib/error.h"
#include "qemu/lib/host_image.h"
#include "qemu/tools/wad_bytes.h"

namespace harness {

namespace {

constexpr size_t WAD_HEADER_BYTES = 12;
constexpr size_t WAD_DIRENTRY_BYTES = 16;

}  // namespace

std::string wad_upper(std::string_view name) {
    std::string out(name);
    for (char& c : out)
        if (c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
    return out;
}

const char* wad_kind_name(WadKind kind) { return kind == WadKind::Flat ? "flat" : "texture"; }

Wad::Wad(std::string bytes, std::string label) : bytes_(std::move(bytes)), label_(std::move(label)) {
    const std::string_view b = bytes_;
    const uint64_t file_size = b.size();
    if (file_size < WAD_HEADER_BYTES)
        throw HarnessError(label_ + ": " + std::to_string(file_size) + " bytes, shorter than the 12-byte WAD header");
    const std::string_view magic = b.substr(0, 4);
    if (magic == "IWAD") iwad_ = true;
    else if (magic != "PWAD")
        throw HarnessError(label_ + ": not a WAD: it starts with '" + printable(magic) + "', not IWAD or PWAD");
    const int32_t count = i32_at(b, 4);
    const int32_t dir = i32_at(b, 8);
    if (count < 0) throw HarnessError(label_ + ": the header's lump count is negative (" + std::to_string(count) + ")");
    if (dir < 0) throw HarnessError(label_ + ": the header's directory offset is negative (" + std::to_string(dir) + ")");
    const uint64_t dir_end = uint64_t(dir) + uint64_t(count) * WAD_DIRENTRY_BYTES;
    if (dir_end > file_size)
        throw HarnessError(label_ + ": the directory (" + std::to_string(count) + " entries of 16 bytes at offset " +
                           std::to_string(dir) + ") runs past the end of the file (" + std::to_string(dir) + " + " +
                           std::to_string(uint64_t(count) * WAD_DIRENTRY_BYTES) + " > " + std::to_string(file_size) + ")");
    lumps_.reserve(size_t(count));
    for (int32_t i = 0; i < count; ++i) {
        const size_t at = size_t(dir) + size_t(i) * WAD_DIRENTRY_BYTES;
        const int32_t offset = i32_at(b, at);
        const int32_t size = i32_at(b, at + 4);
        WadLump lump;
        lump.name = name_at(b, at + 8);
        const std::string where = "lump " + printable(lump.name) + " (index " + std::to_string(i) + ")";
        if (size < 0) throw HarnessError(label_ + ": " + where + " has a negative size (" + std::to_string(size) + ")");
        // Markers carry no data, and tools write all sorts of offsets for them.
        if (size > 0) {
            if (offset < 0)
                throw HarnessError(label_ + ": " + where + " has a negative offset (" + std::to_string(offset) + ")");
            if (uint64_t(offset) + uint64_t(size) > file_size)
                throw HarnessError(label_ + ": " + where + " runs past the end of the file (offset " + std::to_string(offset) +
                                   " + size " + std::to_string(size) + " > " + std::to_string(file_size) + ")");
            lump.offset = uint32_t(offset);
            lump.size = uint32_t(size);
        }
        lumps_.push_back(std::move(lump));
    }
}

Wad Wad::load(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw HarnessError(path + ": is a directory, not a WAD");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw HarnessError(path + ": cannot open (" + std::strerror(errno) + ")");
    std::string bytes;
    char chunk[65536];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) bytes.append(chunk, size_t(in.gcount()));
    if (in.bad()) throw HarnessError(path + ": read error");
    return Wad(std::move(bytes), std::filesystem::path(path).filename().string());
}

std::string Wad::lump_label(int index) const {
    return "lump " + printable(lumps_[size_t(index)].name) + " (index " + std::to_string(index) + ")";
}

int Wad::find_lump(std::string_view name) const {
    const std::string wanted = wad_upper(name);
    for (int i = int(lumps_.size()) - 1; i >= 0; --i)
        if (lumps_[size_t(i)].name == wanted) return i;
    return -1;
}

std::string_view Wad::lump_data(int index) const {
    if (index < 0 || size_t(index) >= lumps_.size())
        throw HarnessError(label_ + ": no lump with index " + std::to_string(index) + " (the WAD has " +
                           std::to_string(lumps_.size()) + ")");
    const WadLump& l = lumps_[size_t(index)];
    return std::string_view(bytes_).substr(l.offset, l.size);
}

WadPalette Wad::palette() const {
    const int index = find_lump("PLAYPAL");
    if (index < 0) throw HarnessError(label_ + ": no PLAYPAL lump (the palette)");
    const std::string_view data = lump_data(index);
    if (data.size() < PALETTE_BYTES)
        throw HarnessError(label_ + ": " + lump_label(index) + " has " + std::to_string(data.size()) +
                           " bytes; a palette needs 768");
    WadPalette pal;
    for (size_t i = 0; i < PALETTE_BYTES; ++i) pal[i] = byte_at(data, i);
    return pal;
}

std::vector<int> Wad::flat_lumps() const {
    std::vector<int> flats;
    std::map<std::string, size_t> slot;  // name -> position in `flats`
    int open = -1;
    for (int i = 0; i < int(lumps_.size()); ++i) {
        const WadLump& l = lumps_[size_t(i)];
        if (is_flat_start(l.name)) {
            // A second start inside an open section (FF_START after F_START) just continues it.
            if (open < 0) open = i;
            continue;
        }
        if (is_flat_end(l.name)) {
            if (open < 0) throw HarnessError(label_ + ": " + lump_label(i) + " ends a flat section that never started");
            open = -1;
            continue;
        }
        if (open < 0 || l.size == 0) continue;
        auto [it, added] = slot.emplace(l.name, flats.size());
        if (added) flats.push_back(i);
        else flats[it->second] = i;
    }
    if (open >= 0) throw HarnessError(label_ + ": " + lump_label(open) + " starts a flat section that never ends (no F_END)");
    return flats;
}

int Wad::find_flat_lump(std::string_view name) const {
    const std::string wanted = wad_upper(name);
    for (int i : flat_lumps())
        if (lumps_[size_t(i)].name == wanted) return i;
    return -1;
}

bool Wad::has_flat(std::string_view name) const { return find_flat_lump(name) >= 0; }

WadImage Wad::flat(std::string_view name) const {
    const int index = find_flat_lump(name);
    if (index < 0) throw HarnessError(label_ + ": no flat named '" + printable(wad_upper(name)) + "'");
    const std::string_view data = lump_data(index);
    if (data.size() != FLAT_BYTES)
        throw HarnessError(label_ + ": flat " + printable(lumps_[size_t(index)].name) + " (" + lump_label(index) + ") has " +
                           std::to_string(data.size()) + " bytes; a flat is 4096 (64x64)");
    WadImage img;
    img.width = FLAT_SIZE;
    img.height = FLAT_SIZE;
    img.indices.assign(data.begin(), data.end());
    img.palette = palette();
    return img;
}

std::vector<WadListEntry> Wad::list() const {
    std::vector<WadListEntry> out;
    for (int i : flat_lumps()) {
        WadListEntry e;
        e.kind = WadKind::Flat;
        e.name = lumps_[size_t(i)].name;
        if (lumps_[size_t(i)].size == FLAT_BYTES) e.width = e.height = FLAT_SIZE;
        else e.problem = "lump is " + std::to_string(lumps_[size_t(i)].size) + " bytes; a flat is 4096";
        out.push_back(std::move(e));
    }
    std::set<std::string> seen;
    for (const WadTextureDef& d : texture_defs()) {
        if (!seen.insert(d.name).second) continue;
        WadListEntry e;
        e.kind = WadKind::Texture;
        e.name = d.name;
        if (d.width <= 0 || d.height <= 0) e.problem = "defined as " + size_text(d.width, d.height);
        else if (d.width > raster::MAX_TEXTURE_SIZE || d.height > raster::MAX_TEXTURE_SIZE)
            e.problem = size_text(d.width, d.height) + ", above " + std::to_string(raster::MAX_TEXTURE_SIZE) + " a side: no scene can use it";
        else e.width = d.width, e.height = d.height;
        out.push_back(std::move(e));
    }
    return out;
}

void write_bmp8(const std::string& path, const WadImage& image) {
    if (image.width > 0 && image.height > 0 && image.indices.size() != size_t(image.width) * size_t(image.height))
        throw HarnessError(path + ": the image claims " + size_text(image.width, image.height) + " but holds " +
                           std::to_string(image.indices.size()) + " pixels");
    write_bmp8(path, image.width, image.height, image.indices.data(), image.palette.data());
}

}  // namespace harness
