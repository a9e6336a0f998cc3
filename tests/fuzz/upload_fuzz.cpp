// Fuzz target `upload`: an upload as a client sends it, the header line (ended by LF, CR or CR LF)
// and then the bytes (`scene BYTES CRC32` or `file NAME BYTES CRC32`), through the kernel's own
// checks: the header (kernel/lib/protocol.h), the CRC-32 of the bytes, and, for a scene or a
// `file` named *.scene that arrives whole and intact, the scene parsers as `scene` and `load` run
// them. Promises: a
// header is taken only within the limits; bytes are taken only when as many came as it said and
// their CRC-32 is the header's; a scene refused by its parser names a line of its text.
#include <algorithm>
#include <memory>
#include <string>

#include "kernel/lib/encode.h"
#include "kernel/lib/protocol.h"
#include "kernel/scene/scene.h"
#include "kernel/scene/world.h"
#include "tests/fuzz/fuzz.h"

namespace {
constexpr size_t MAX_UPLOAD = 4 << 20, MAX_NAME = 64;
}

MODEXLAB_FUZZ_TARGET(upload) {
    const uint8_t* end = data + size;
    lib::LineAssembler lines;
    lib::LineAssembler::Result r = lib::LineAssembler::Result::More;
    const uint8_t* p = data;
    while (p < end && (r == lib::LineAssembler::Result::More || r == lib::LineAssembler::Result::Cancelled)) r = lines.feed(char(*p++));
    if (r != lib::LineAssembler::Result::Line) return 0;  // no line, or the line itself refused: `command` covers it
    // the header ended by CR: an LF right after it is its line end's, not the payload's (files::receive)
    if (lines.ended_by_cr() && p < end && *p == '\n') ++p;
    lib::StrView words[128];
    const size_t n = lib::split_words(lines.line(), words, 128);
    if (n == 0 || n > 128) return 0;
    const bool scene = words[0].equals("scene");
    if (!scene && !words[0].equals("file")) return 0;
    lib::UploadHeader h;
    if (lib::check_upload_header(words + 1, n - 1, scene ? 0 : 1, lib::StrView{"upload.scene", 12}, MAX_UPLOAD, MAX_NAME, &h) !=
        lib::HeaderProblem::None)
        return 0;
    if (h.length == 0 || h.length > MAX_UPLOAD || h.name.size == 0 || h.name.size >= MAX_NAME) fuzz::fail("a header taken out of its limits");
    const uint8_t* bytes = p;
    if (size_t(end - bytes) < h.length) return 0;  // the rest never comes: the kernel's stall timeout
    if (lib::crc32(0, bytes, h.length) != h.crc32) return 0;  // "checksum mismatch"
    const bool scene_file = scene || (h.name.size > 6 && std::string(h.name.data + h.name.size - 6, 6) == ".scene");
    if (!scene_file) return 0;
    const char* text = reinterpret_cast<const char*>(bytes);
    raster::ParseError e;
    static auto screen = std::make_unique<raster::Scene>();
    static auto world = std::make_unique<raster::HostWorld>();
    const int version = raster::scene_version(text, h.length, &e);
    const bool ok = version == 1   ? raster::parse_scene(text, h.length, screen.get(), &e)
                    : version == 2 ? raster::parse_world(text, h.length, raster::FileResolver{}, world.get(), &e)
                                   : false;
    const int32_t text_lines = int32_t(std::count(bytes, bytes + h.length, uint8_t('\n'))) + 1;
    if (!ok && (!e.message[0] || e.line < 0 || e.line > text_lines)) fuzz::fail("a refused upload's error names no line of it");
    return 0;
}
