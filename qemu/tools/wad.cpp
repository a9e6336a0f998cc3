// Reading Doom WADs (directory, PLAYPAL, flats, PNAMES/TEXTUREx and column pictures) and writing 8-bit BMPs.
#include "qemu/tools/wad.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "qemu/lib/error.h"

namespace harness {

namespace {

constexpr size_t WAD_HEADER_BYTES = 12;
constexpr size_t WAD_DIRENTRY_BYTES = 16;
constexpr size_t MAPTEXTURE_BYTES = 22;  // before its mappatch entries
constexpr size_t MAPPATCH_BYTES = 10;
constexpr size_t PICTURE_HEADER_BYTES = 8;
constexpr uint8_t POST_END = 0xFF;
constexpr size_t BMP_FILE_HEADER_BYTES = 14;
constexpr size_t BMP_INFO_HEADER_BYTES = 40;
constexpr size_t BMP_COLOUR_TABLE_BYTES = 256 * 4;

// Callers check bounds first; these only assemble little-endian bytes without unaligned loads.
uint8_t byte_at(std::string_view b, size_t at) { return uint8_t(b[at]); }
uint16_t u16_at(std::string_view b, size_t at) { return uint16_t(byte_at(b, at) | (byte_at(b, at + 1) << 8)); }
int16_t i16_at(std::string_view b, size_t at) { return int16_t(u16_at(b, at)); }
uint32_t u32_at(std::string_view b, size_t at) {
    return uint32_t(byte_at(b, at)) | (uint32_t(byte_at(b, at + 1)) << 8) | (uint32_t(byte_at(b, at + 2)) << 16) |
           (uint32_t(byte_at(b, at + 3)) << 24);
}
int32_t i32_at(std::string_view b, size_t at) { return int32_t(u32_at(b, at)); }

void put_u16(std::string& b, size_t at, uint32_t v) {
    b[at] = char(v & 0xFF);
    b[at + 1] = char((v >> 8) & 0xFF);
}
void put_u32(std::string& b, size_t at, uint32_t v) {
    put_u16(b, at, v & 0xFFFF);
    put_u16(b, at + 2, v >> 16);
}

// Names and magics come from untrusted bytes; keep messages readable whatever they hold.
std::string printable(std::string_view s) {
    std::string out;
    for (char c : s) {
        unsigned char u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u < 0x7F) out += c;
        else {
            static const char HEX[] = "0123456789abcdef";
            out += "\\x";
            out += HEX[u >> 4];
            out += HEX[u & 0xF];
        }
    }
    return out;
}

// A lump name field: up to 8 bytes, ending at the first NUL (what follows a NUL is padding, which
// some tools fill with garbage).
std::string name_at(std::string_view b, size_t at) {
    std::string_view field = b.substr(at, WAD_NAME_LENGTH);
    size_t nul = field.find('\0');
    return wad_upper(field.substr(0, nul));
}

bool is_flat_start(const std::string& n) { return n == "F_START" || n == "FF_START"; }
bool is_flat_end(const std::string& n) { return n == "F_END" || n == "FF_END"; }
bool is_patch_start(const std::string& n) { return n == "P_START" || n == "PP_START"; }
bool is_patch_end(const std::string& n) { return n == "P_END" || n == "PP_END"; }

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace

std::string wad_upper(std::string_view name) {
    std::string out(name);
    for (char& c : out)
        if (c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
    return out;
}

const char* wad_kind_name(WadKind kind) { return kind == WadKind::Flat ? "flat" : "texture"; }

DoomPicture decode_doom_picture(std::string_view bytes, const std::string& what) {
    const size_t size = bytes.size();
    if (size < PICTURE_HEADER_BYTES)
        throw HarnessError(what + ": " + std::to_string(size) + " bytes, shorter than the 8-byte picture header");
    DoomPicture pic;
    pic.width = u16_at(bytes, 0);
    pic.height = u16_at(bytes, 2);
    pic.left_offset = i16_at(bytes, 4);
    pic.top_offset = i16_at(bytes, 6);
    const size_t table_end = PICTURE_HEADER_BYTES + 4 * size_t(pic.width);
    if (table_end > size)
        throw HarnessError(what + ": the column offsets of a " + std::to_string(pic.width) + "-column picture need " +
                           std::to_string(table_end) + " bytes, the lump has " + std::to_string(size));
    pic.columns.resize(size_t(pic.width));
    for (int c = 0; c < pic.width; ++c) {
        const uint32_t start = u32_at(bytes, PICTURE_HEADER_BYTES + 4 * size_t(c));
        auto fail = [&](const std::string& why) -> HarnessError {
            return HarnessError(what + ": column " + std::to_string(c) + " (data at offset " + std::to_string(start) +
                                "): " + why + " (the lump has " + std::to_string(size) + " bytes)");
        };
        if (start >= size) throw fail("starts past the end of the lump");
        size_t at = start;
        int64_t top = -1;
        // Every post moves `at` forward by at least 4 bytes, so this ends within the lump.
        for (;;) {
            if (at >= size) throw fail("runs past the end of the lump without its 0xFF end marker");
            const uint8_t delta = byte_at(bytes, at);
            if (delta == POST_END) break;
            if (at + 3 > size) throw fail("a post header at offset " + std::to_string(at) + " runs past the end of the lump");
            const size_t length = byte_at(bytes, at + 1);
            if (at + 3 + length + 1 > size)
                throw fail("a post of " + std::to_string(length) + " pixels at offset " + std::to_string(at) +
                           " runs past the end of the lump");
            if (int64_t(delta) <= top) {
                top += delta;
                pic.tall = true;
            } else {
                top = delta;
            }
            DoomPost post;
            post.top = top;
            post.pixels.assign(bytes.begin() + std::ptrdiff_t(at + 3), bytes.begin() + std::ptrdiff_t(at + 3 + length));
            pic.columns[size_t(c)].push_back(std::move(post));
            at += 3 + length + 1;
        }
    }
    return pic;
}

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

std::vector<std::string> Wad::patch_names() const {
    const int index = find_lump("PNAMES");
    if (index < 0) return {};
    const std::string_view data = lump_data(index);
    const std::string what = label_ + ": " + lump_label(index);
    if (data.size() < 4) throw HarnessError(what + " has " + std::to_string(data.size()) + " bytes, too few for its count");
    const int32_t count = i32_at(data, 0);
    if (count < 0) throw HarnessError(what + " has a negative count (" + std::to_string(count) + ")");
    if (4 + uint64_t(count) * WAD_NAME_LENGTH > data.size())
        throw HarnessError(what + ": " + std::to_string(count) + " names need " + std::to_string(4 + uint64_t(count) * 8) +
                           " bytes, the lump has " + std::to_string(data.size()));
    std::vector<std::string> names;
    names.reserve(size_t(count));
    for (int32_t i = 0; i < count; ++i) names.push_back(name_at(data, 4 + size_t(i) * WAD_NAME_LENGTH));
    return names;
}

std::vector<WadTextureDef> Wad::parse_texture_lump(int index) const {
    const std::string_view data = lump_data(index);
    const std::string what = label_ + ": " + lump_label(index);
    const uint64_t size = data.size();
    if (size < 4) throw HarnessError(what + " has " + std::to_string(size) + " bytes, too few for its count");
    const int32_t count = i32_at(data, 0);
    if (count < 0) throw HarnessError(what + " has a negative count (" + std::to_string(count) + ")");
    if (4 + uint64_t(count) * 4 > size)
        throw HarnessError(what + ": the offsets of " + std::to_string(count) + " textures run past the end of the lump (" +
                           std::to_string(size) + " bytes)");
    std::vector<WadTextureDef> defs;
    defs.reserve(size_t(count));
    for (int32_t t = 0; t < count; ++t) {
        const int32_t off = i32_at(data, 4 + size_t(t) * 4);
        const std::string entry = "entry " + std::to_string(t);
        if (off < 0 || uint64_t(off) + MAPTEXTURE_BYTES > size)
            throw HarnessError(what + ": " + entry + " at offset " + std::to_string(off) + " runs past the end of the lump (" +
                               std::to_string(size) + " bytes)");
        const size_t at = size_t(off);
        WadTextureDef def;
        def.name = name_at(data, at);
        def.width = i16_at(data, at + 12);
        def.height = i16_at(data, at + 14);
        def.source = lumps_[size_t(index)].name + " " + entry;
        const int16_t patch_count = i16_at(data, at + 20);
        if (patch_count < 0)
            throw HarnessError(what + ": texture " + printable(def.name) + " (" + entry + ") has a negative patch count (" +
                               std::to_string(patch_count) + ")");
        if (at + MAPTEXTURE_BYTES + uint64_t(patch_count) * MAPPATCH_BYTES > size)
            throw HarnessError(what + ": texture " + printable(def.name) + " (" + entry + ", offset " + std::to_string(off) +
                               ") with " + std::to_string(patch_count) + " patches runs past the end of the lump (" +
                               std::to_string(size) + " bytes)");
        for (int p = 0; p < patch_count; ++p) {
            const size_t pat = at + MAPTEXTURE_BYTES + size_t(p) * MAPPATCH_BYTES;
            def.patches.push_back({i16_at(data, pat), i16_at(data, pat + 2), i16_at(data, pat + 4)});
        }
        defs.push_back(std::move(def));
    }
    return defs;
}

std::vector<WadTextureDef> Wad::texture_defs() const {
    std::vector<WadTextureDef> defs;
    for (const char* lump : {"TEXTURE1", "TEXTURE2"}) {
        const int index = find_lump(lump);
        if (index < 0) continue;
        std::vector<WadTextureDef> more = parse_texture_lump(index);
        defs.insert(defs.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
    }
    return defs;
}

const WadTextureDef* Wad::find_texture_def(const std::vector<WadTextureDef>& defs, std::string_view name) const {
    const std::string wanted = wad_upper(name);
    for (const WadTextureDef& d : defs)
        if (d.name == wanted) return &d;
    return nullptr;
}

bool Wad::has_texture(std::string_view name) const { return find_texture_def(texture_defs(), name) != nullptr; }

// Vanilla Doom takes the last lump with the name anywhere; a lump between P_START and P_END wins
// here, so that a flat or sprite sharing a patch's name cannot stand in for it.
int Wad::find_patch_lump(const std::string& name) const {
    int in_patches = -1, elsewhere = -1;
    bool patches_open = false, flats_open = false;
    for (int i = 0; i < int(lumps_.size()); ++i) {
        const std::string& n = lumps_[size_t(i)].name;
        if (is_patch_start(n)) patches_open = true;
        else if (is_patch_end(n)) patches_open = false;
        else if (is_flat_start(n)) flats_open = true;
        else if (is_flat_end(n)) flats_open = false;
        else if (n == name) {
            if (patches_open) in_patches = i;
            else if (!flats_open) elsewhere = i;
        }
    }
    return in_patches >= 0 ? in_patches : elsewhere;
}

WadImage Wad::texture(std::string_view name) const {
    const std::vector<WadTextureDef> defs = texture_defs();
    const WadTextureDef* def = find_texture_def(defs, name);
    if (!def) throw HarnessError(label_ + ": no wall texture named '" + printable(wad_upper(name)) + "'");
    const std::string what = label_ + ": texture " + printable(def->name) + " (" + def->source + ")";
    if (def->width <= 0 || def->height <= 0) throw HarnessError(what + " has no pixels: it is " + size_text(def->width, def->height));
    if (find_lump("PNAMES") < 0) throw HarnessError(what + ": the WAD has no PNAMES lump to name its patches");
    const std::vector<std::string> pnames = patch_names();
    WadImage img;
    img.width = def->width;
    img.height = def->height;
    img.indices.assign(size_t(img.width) * size_t(img.height), 0);
    img.palette = palette();
    for (size_t k = 0; k < def->patches.size(); ++k) {
        const WadPatchPlacement& place = def->patches[k];
        const std::string which = what + ", patch " + std::to_string(k + 1) + " of " + std::to_string(def->patches.size());
        if (place.patch < 0 || size_t(place.patch) >= pnames.size())
            throw HarnessError(which + ": PNAMES index " + std::to_string(place.patch) + " is out of range (PNAMES has " +
                               std::to_string(pnames.size()) + " names)");
        const std::string& patch_name = pnames[size_t(place.patch)];
        const int lump = find_patch_lump(patch_name);
        if (lump < 0)
            throw HarnessError(which + ": patch " + printable(patch_name) + " (PNAMES index " + std::to_string(place.patch) +
                               ") is not in the WAD");
        const DoomPicture pic = decode_doom_picture(lump_data(lump), label_ + ": patch " + lump_label(lump));
        for (int c = 0; c < pic.width; ++c) {
            const int64_t x = int64_t(place.origin_x) + c;
            if (x < 0 || x >= img.width) continue;
            for (const DoomPost& post : pic.columns[size_t(c)]) {
                const int64_t y0 = int64_t(place.origin_y) + post.top;
                for (size_t i = 0; i < post.pixels.size(); ++i) {
                    const int64_t y = y0 + int64_t(i);
                    if (y >= 0 && y < img.height) img.indices[size_t(y) * size_t(img.width) + size_t(x)] = post.pixels[i];
                }
            }
        }
    }
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
        if (d.width > 0 && d.height > 0) e.width = d.width, e.height = d.height;
        else e.problem = "defined as " + size_text(d.width, d.height);
        out.push_back(std::move(e));
    }
    return out;
}

void write_bmp8(const std::string& path, int width, int height, const uint8_t* indices, const uint8_t* palette_rgb768) {
    if (width <= 0 || height <= 0) throw HarnessError(path + ": cannot write a " + size_text(width, height) + " BMP");
    if (!indices || !palette_rgb768) throw HarnessError(path + ": no pixels or no palette to write");
    const uint64_t stride = (uint64_t(width) + 3) & ~uint64_t(3);
    const uint64_t pixel_bytes = stride * uint64_t(height);
    const uint64_t data_offset = BMP_FILE_HEADER_BYTES + BMP_INFO_HEADER_BYTES + BMP_COLOUR_TABLE_BYTES;
    const uint64_t file_bytes = data_offset + pixel_bytes;
    if (file_bytes > 0x7FFFFFFF) throw HarnessError(path + ": a " + size_text(width, height) + " BMP would be too large");

    std::string out(size_t(file_bytes), '\0');
    out[0] = 'B';
    out[1] = 'M';
    put_u32(out, 2, uint32_t(file_bytes));
    put_u32(out, 10, uint32_t(data_offset));
    const size_t info = BMP_FILE_HEADER_BYTES;
    put_u32(out, info + 0, BMP_INFO_HEADER_BYTES);
    put_u32(out, info + 4, uint32_t(width));
    put_u32(out, info + 8, uint32_t(height));  // positive: rows stored bottom-up
    put_u16(out, info + 12, 1);                // planes
    put_u16(out, info + 14, 8);                // bits a pixel
    put_u32(out, info + 16, 0);                // BI_RGB, uncompressed
    put_u32(out, info + 20, uint32_t(pixel_bytes));
    put_u32(out, info + 32, 256);              // colours used
    const size_t table = info + BMP_INFO_HEADER_BYTES;
    for (size_t i = 0; i < 256; ++i) {
        out[table + 4 * i + 0] = char(palette_rgb768[3 * i + 2]);
        out[table + 4 * i + 1] = char(palette_rgb768[3 * i + 1]);
        out[table + 4 * i + 2] = char(palette_rgb768[3 * i + 0]);
    }
    for (int y = 0; y < height; ++y) {
        const uint8_t* src = indices + size_t(y) * size_t(width);
        const size_t dst = size_t(data_offset) + size_t(height - 1 - y) * size_t(stride);
        std::memcpy(&out[dst], src, size_t(width));
    }

    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) throw HarnessError(path + ": cannot write (" + std::strerror(errno) + ")");
    file.write(out.data(), std::streamsize(out.size()));
    file.close();
    if (!file) throw HarnessError(path + ": writing failed (" + std::strerror(errno) + ")");
}

void write_bmp8(const std::string& path, const WadImage& image) {
    if (image.width > 0 && image.height > 0 && image.indices.size() != size_t(image.width) * size_t(image.height))
        throw HarnessError(path + ": the image claims " + size_text(image.width, image.height) + " but holds " +
                           std::to_string(image.indices.size()) + " pixels");
    write_bmp8(path, image.width, image.height, image.indices.data(), image.palette.data());
}

}  // namespace harness
