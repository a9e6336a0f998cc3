// What wad.cpp and wad_texture.cpp both need to read WAD bytes: little-endian fields, lump name
// fields, section markers and message text. Internal to the WAD reader; not part of wad.h.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "qemu/tools/wad.h"

namespace harness {

// Callers check bounds first; these only assemble little-endian bytes without unaligned loads.
inline uint8_t byte_at(std::string_view b, size_t at) { return uint8_t(b[at]); }
inline uint16_t u16_at(std::string_view b, size_t at) { return uint16_t(byte_at(b, at) | (byte_at(b, at + 1) << 8)); }
inline int16_t i16_at(std::string_view b, size_t at) { return int16_t(u16_at(b, at)); }
inline uint32_t u32_at(std::string_view b, size_t at) {
    return uint32_t(byte_at(b, at)) | (uint32_t(byte_at(b, at + 1)) << 8) | (uint32_t(byte_at(b, at + 2)) << 16) |
           (uint32_t(byte_at(b, at + 3)) << 24);
}
inline int32_t i32_at(std::string_view b, size_t at) { return int32_t(u32_at(b, at)); }

// Names and magics come from untrusted bytes; keep messages readable whatever they hold.
inline std::string printable(std::string_view s) {
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
inline std::string name_at(std::string_view b, size_t at) {
    std::string_view field = b.substr(at, WAD_NAME_LENGTH);
    size_t nul = field.find('\0');
    return wad_upper(field.substr(0, nul));
}

inline bool is_flat_start(const std::string& n) { return n == "F_START" || n == "FF_START"; }
inline bool is_flat_end(const std::string& n) { return n == "F_END" || n == "FF_END"; }
inline bool is_patch_start(const std::string& n) { return n == "P_START" || n == "PP_START"; }
inline bool is_patch_end(const std::string& n) { return n == "P_END" || n == "PP_END"; }

inline std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace harness
