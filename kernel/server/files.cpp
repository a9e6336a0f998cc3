// The file commands: uploads (scene, file), the file list, and loading a scene file of either
// version, whose reply describes what was loaded.
#include "drivers/serial.h"
#include "kernel/files.h"
#include "kernel/scenes.h"
#include "kernel/server/commands.h"
#include "kernel/server/reply.h"
#include "kernel/worlds.h"

namespace server {

namespace {

// The name an upload by `scene` is stored under, so that it is also a file like any other.
const StrView UPLOADED_SCENE{files::SCENE_UPLOAD, lib::c_length(files::SCENE_UPLOAD)};

void reply_parse_error(const char* cmd, const char* file, const raster::ParseError& e) {
    lib::Fmt m;
    if (file) m.s(file).s(": ");
    if (e.line) m.s("line ").u(uint32_t(e.line)).s(": ");
    m.s(e.message);
    lib::JsonLine r = reply::begin(false);
    r.str("cmd", cmd).str("error", m.c_str()).u32("line", uint32_t(e.line));
    if (file) r.str("file", file);
    r.end();
}

// The reply fields describing a loaded screen-space scene (version 1).
void describe_screen_scene(lib::JsonLine& r) {
    const raster::Scene& sc = scenes::scene();
    r.u32("version", 1)
        .u32("polygons", uint32_t(sc.polygon_count))
        .u32("vertices", uint32_t(sc.vertex_count))
        .str("texture", raster::texture_kind_name(sc.texture_kind))
        .u32("texture_width", uint32_t(sc.texture_width))
        .u32("texture_height", uint32_t(sc.texture_height))
        .str("wrap", raster::wrap_name(sc.wrap));
}

// The reply fields describing a loaded 3D scene (version 2).
void describe_world(lib::JsonLine& r) {
    const raster::World& w = worlds::world();
    r.u32("version", 2)
        .u32("textures", uint32_t(w.texture_count))
        .u32("meshes", uint32_t(w.mesh_count))
        .u32("objects", uint32_t(w.object_count))
        .u32("faces", uint32_t(w.face_count))
        .u32("positions", uint32_t(w.position_count))
        .u32("frames", uint32_t(w.frames))
        .str("palette", w.palette_texture >= 0 ? w.textures[w.palette_texture].name : "default");
    write_budget(r, "budget", w.budget);
}

// Loads a scene file of either version as the current scene of its kind.
void load_and_reply(const char* cmd, const files::File& f) {
    raster::ParseError e;
    const char* text = reinterpret_cast<const char*>(f.data);
    int version = raster::scene_version(text, f.size, &e);
    bool ok = version == 1 ? scenes::load(text, f.size, &e) : version == 2 ? worlds::load(f.name, f.data, f.size, &e) : false;
    if (!ok) {
        reply_parse_error(cmd, f.name, e);
        return;
    }
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", cmd).str("name", f.name).str("origin", files::origin_name(f.origin)).u32("bytes", uint32_t(f.size));
    if (version == 1) describe_screen_scene(r);
    else describe_world(r);
    r.end();
}

// The length an upload's header gives, where one can be read, for a refusal (the word
// `announced`, below); decimal or 0x hex, a number beyond 32 bits meaning every byte that comes
// (while they come). 0 where there is none.
size_t announced_length(StrView word) {
    uint32_t n;
    if (lib::parse_u32(word, &n)) return n;
    // digits all the same: a number too large for 32 bits
    const bool hex = word.size > 2 && word.data[0] == '0' && (word.data[1] == 'x' || word.data[1] == 'X');
    bool digits = word.size > (hex ? 2u : 0u);
    for (size_t i = hex ? 2 : 0; i < word.size && digits; ++i) {
        const char c = word.data[i];
        digits = (c >= '0' && c <= '9') || (hex && ((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')));
    }
    return digits ? SIZE_MAX : 0;
}

// Refuses an upload: the bytes its header announced are read and dropped first (while they come,
// files::discard), so that none of them is taken for a command, then the error, with how many were
// dropped (a scene error carries "line" 0, as a parse error carries its line).
void refuse_upload(const char* cmd, StrView announced, const char* message) {
    const size_t dropped = files::discard(announced_length(announced));
    lib::JsonLine r = reply::begin(false);
    r.str("cmd", cmd).str("error", message).u32("discarded", uint32_t(dropped));
    if (StrView{cmd, lib::c_length(cmd)}.equals("scene")) r.u32("line", 0);
    r.end();
}

// Checks an upload's header (BYTES CRC32 after `name_args` words; `name` the file's name) and
// says "ready" when the bytes may come; else refuses it. False when refused. The length a refusal
// drops is scene's first argument and file's second-to-last (a name with a space in it still ends
// the header with BYTES CRC32), or its second where it has only two.
bool accept_upload(const char* cmd, StrView name, const StrView* args, size_t nargs, size_t name_args, uint32_t* length, uint32_t* crc32) {
    const StrView announced = name_args == 0 ? (nargs ? args[0] : StrView{}) : nargs >= 3 ? args[nargs - 2] : nargs == 2 ? args[1] : StrView{};
    lib::Fmt m;
    if (nargs != name_args + 2) {
        const Command* c = find_command(StrView{cmd, lib::c_length(cmd)});
        refuse_upload(cmd, announced, m.s("usage: ").s(c->usage).c_str());
        return false;
    }
    const StrView bytes = args[name_args], crc = args[name_args + 1];
    if (!lib::parse_u32(bytes, length) || *length == 0 || *length > files::MAX_UPLOAD || !lib::parse_u32(crc, crc32)) {
        refuse_upload(cmd, bytes, m.s("bad length or checksum: BYTES 1..").u(uint32_t(files::MAX_UPLOAD)).s(", CRC32 decimal or 0x hex").c_str());
        return false;
    }
    if (name.size == 0 || name.size >= size_t(raster::MAX_FILE_NAME)) {
        refuse_upload(cmd, bytes, m.s("bad name: 1 to ").u(uint32_t(raster::MAX_FILE_NAME - 1)).s(" characters").c_str());
        return false;
    }
    if (!files::upload_fits(name, *length, &m)) {
        refuse_upload(cmd, bytes, m.c_str());
        return false;
    }
    lib::JsonLine(serial::sink()).str("event", "ready").str("cmd", cmd).u32("bytes", *length).end();
    return true;
}

}  // namespace

void cmd_scene(Context&, const StrView* args, size_t nargs) {
    uint32_t length, crc;
    if (!accept_upload("scene", UPLOADED_SCENE, args, nargs, 0, &length, &crc)) return;
    lib::Fmt error;
    if (!files::upload(UPLOADED_SCENE, length, crc, &error)) {
        // every scene error carries "line", as a parse error does: 0, no line
        reply::begin(false).str("cmd", "scene").str("error", error.c_str()).u32("line", 0).end();
        return;
    }
    load_and_reply("scene", *files::find(UPLOADED_SCENE));
}

void cmd_file(Context&, const StrView* args, size_t nargs) {
    uint32_t length, crc;
    if (!accept_upload("file", nargs == 3 ? args[0] : StrView{}, args, nargs, 1, &length, &crc)) return;
    lib::Fmt error;
    if (!files::upload(args[0], length, crc, &error)) {
        reply::error("file", error.c_str());
        return;
    }
    const files::File* f = files::find(args[0]);
    reply::begin(true).str("cmd", "file").str("name", f->name).u32("bytes", uint32_t(f->size)).u64("upload_space_used", files::upload_space_used()).end();
}

void cmd_files(Context&, const StrView*, size_t) {
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "files").begin_array("files");
    for (int i = 0; i < files::count(); ++i) {
        const files::File& f = files::at(i);
        r.begin_item_object().str("name", f.name).str("origin", files::origin_name(f.origin)).u32("bytes", uint32_t(f.size)).end_object();
    }
    r.end_array().u64("upload_space_used", files::upload_space_used()).u64("upload_space", files::UPLOAD_SPACE).end();
}

void cmd_load(Context&, const StrView* args, size_t) {
    const files::File* f = files::find(args[0]);
    if (!f) {
        lib::Fmt m;
        m.s("no file '").s(args[0]).s("' (see 'files')");
        reply::error("load", m.c_str());
        return;
    }
    load_and_reply("load", *f);
}

}  // namespace server
