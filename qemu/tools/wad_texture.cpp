// Doom's graphics built from patches: column pictures, PNAMES, TEXTURE1/TEXTURE2 definitions and
// wall textures composed from them.
#include "qemu/tools/wad.h"

#include <iterator>

#include "kernel/core/texture.h"
#include "qemu/lib/error.h"
#include "qemu/tools/wad_bytes.h"

namespace harness {

namespace {

constexpr size_t MAPTEXTURE_BYTES = 22;  // before its mappatch entries
constexpr size_t MAPPATCH_BYTES = 10;
constexpr size_t PICTURE_HEADER_BYTES = 8;
constexpr uint8_t POST_END = 0xFF;

}  // namespace

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
    // before a byte is allocated: a header of a few bytes may claim 32767 x 32767
    if (def->width > raster::MAX_TEXTURE_SIZE || def->height > raster::MAX_TEXTURE_SIZE)
        throw HarnessError(what + " is " + size_text(def->width, def->height) + ": no scene can use a texture above " +
                           std::to_string(raster::MAX_TEXTURE_SIZE) + " a side");
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

}  // namespace harness
