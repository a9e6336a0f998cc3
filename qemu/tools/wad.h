// Doom WADs on the host: the lump directory, the palette, flats and composed wall textures, and 8-bit BMP output.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace harness {

// Lump names are at most 8 characters; the WAD pads them with NULs and ignores case, so we keep
// them in upper case and compare upper case.
inline constexpr size_t WAD_NAME_LENGTH = 8;
inline constexpr int FLAT_SIZE = 64;
inline constexpr size_t FLAT_BYTES = size_t(FLAT_SIZE) * FLAT_SIZE;
inline constexpr size_t PALETTE_BYTES = 768;  // 256 RGB triplets, 8 bits a component

using WadPalette = std::array<uint8_t, PALETTE_BYTES>;

struct WadLump {
    std::string name;  // upper case, without the NUL padding
    uint32_t offset = 0, size = 0;
};

enum class WadKind { Flat, Texture };
const char* wad_kind_name(WadKind kind);  // "flat", "texture"

// A picture in the WAD's palette: what a flat or a composed wall texture becomes.
struct WadImage {
    int width = 0, height = 0;
    std::vector<uint8_t> indices;  // row-major palette indices
    WadPalette palette{};
    uint8_t at(int x, int y) const { return indices[size_t(y) * size_t(width) + size_t(x)]; }
};

struct WadListEntry {
    WadKind kind = WadKind::Flat;
    std::string name;
    int width = 0, height = 0;
    std::string problem;  // empty when the graphic can be extracted; else why not (sizes then 0)
};

// One patch of a wall texture, as TEXTURE1/TEXTURE2 place it.
struct WadPatchPlacement {
    int origin_x = 0, origin_y = 0;
    int patch = 0;  // index into PNAMES, not checked until the texture is composed
};

struct WadTextureDef {
    std::string name;
    int width = 0, height = 0;
    std::vector<WadPatchPlacement> patches;
    std::string source;  // "TEXTURE1 entry 12": where it is defined, for messages
};

// A picture in Doom's column format (patches, sprites), decoded but not drawn. Post rows are
// absolute: tall-patch relative offsets are already resolved.
struct DoomPost {
    int64_t top = 0;  // row in the picture; 64 bits because tall patches can chain offsets far down
    std::vector<uint8_t> pixels;
};

struct DoomPicture {
    int width = 0, height = 0;
    int left_offset = 0, top_offset = 0;
    bool tall = false;  // some post used the DeePsea relative topdelta
    std::vector<std::vector<DoomPost>> columns;
};

// Decodes a picture lump. `what` names it in error messages. A post whose topdelta is at most the
// previous post's top row is relative to that row (the DeePsea "tall patch" convention, which lets
// pictures exceed 254 rows); in ordinary pictures topdeltas only grow, so this changes nothing there.
DoomPicture decode_doom_picture(std::string_view bytes, const std::string& what);

// A WAD held in memory. Construction checks the header and the directory, including that every lump
// with data lies inside the file (empty marker lumps may point anywhere); the graphics accessors
// check the structures they read. Every failure is a HarnessError naming the WAD, the lump and the
// problem.
class Wad {
public:
    // `label` names the WAD in messages, usually its file name.
    Wad(std::string bytes, std::string label);
    static Wad load(const std::string& path);

    const std::string& label() const { return label_; }
    bool is_iwad() const { return iwad_; }
    const std::vector<WadLump>& lumps() const { return lumps_; }
    // As Doom looks lumps up: the last one with the name wins. -1 when there is none.
    int find_lump(std::string_view name) const;
    std::string_view lump_data(int index) const;

    // The first 768 bytes of PLAYPAL (Doom's palette 0; the other 13 are damage/pickup tints).
    WadPalette palette() const;

    // Flats: the lumps between F_START (or FF_START) and F_END (or FF_END), nested F1_START-style
    // markers and other empty lumps skipped; a later flat with the same name replaces an earlier
    // one. Indices of the winning lumps, in WAD order.
    std::vector<int> flat_lumps() const;
    bool has_flat(std::string_view name) const;
    WadImage flat(std::string_view name) const;  // 64x64; throws unless the lump is 4096 bytes

    std::vector<std::string> patch_names() const;       // PNAMES, upper case; empty without PNAMES
    std::vector<WadTextureDef> texture_defs() const;    // TEXTURE1 then TEXTURE2, all entries
    bool has_texture(std::string_view name) const;
    // Composes the first definition with the name (as Doom does): patches drawn in order, later over
    // earlier, clipped to the texture. Pixels no patch covers are palette index 0, since a BMP has
    // no transparency and index 0 is black in Doom's palette.
    WadImage texture(std::string_view name) const;

    // Every flat (WAD order) and then every wall texture (definition order, duplicates omitted).
    std::vector<WadListEntry> list() const;

private:
    std::string bytes_;
    std::string label_;
    bool iwad_ = false;
    std::vector<WadLump> lumps_;

    std::string lump_label(int index) const;  // "lump PNAMES (index 123)"
    int find_patch_lump(const std::string& name) const;
    std::vector<WadTextureDef> parse_texture_lump(int index) const;
    const WadTextureDef* find_texture_def(const std::vector<WadTextureDef>& defs, std::string_view name) const;
    int find_flat_lump(std::string_view name) const;
};

// Upper-cases ASCII letters (lump names are ASCII).
std::string wad_upper(std::string_view name);

// Writes the image as an 8-bit BMP, through the generic write_bmp8 in qemu/lib/host_image.h; throws if its
// pixel count does not match its size.
void write_bmp8(const std::string& path, const WadImage& image);

}  // namespace harness
