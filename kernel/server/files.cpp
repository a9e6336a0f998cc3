// The file commands: uploads (scene, file), the file list, and loading a scene file of either
// version, whose reply describes what was loaded.
#include "drivers/serial.h"
#include "kernel/present/file_table.h"
#include "kernel/lib/protocol.h"
#include "kernel/present/current_screen.h"
#include "kernel/server/commands.h"
#include "kernel/server/reply.h"
#include "kernel/platform/guard.h"
#include "kernel/present/current_world.h"

namespace server {

namespace {

// The name an upload by `scene` is stored under, so that it is also a file like any other.
const StrView UPLOADED_SCENE{file_table::SCENE_UPLOAD, lib::c_length(file_table::SCENE_UPLOAD)};

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
    const raster::Scene& sc = current_screen::scene();
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
    const raster::World& w = current_world::world();
    r.u32("version", 2)
        .u32("textures", uint32_t(w.texture_count))
        .u32("meshes", uint32_t(w.mesh_count))
        .u32("objects", uint32_t(w.object_count))
        .u32("faces", uint32_t(w.face_count))
        .u32("positions", uint32_t(w.position_count))
        .u32("frames", uint32_t(w.frames))
        .str("palette", w.palette_texture >= 0 ? w.textures[w.palette_texture].name : "default");
    write_budget(r, "budget", w.budget);
    r.boolean("doubled_copies", current_world::doubled_copies());
}

// Loads a scene file of either version as the current scene of its kind.
void load_and_reply(const char* cmd, const file_table::File& f) {
    raster::ParseError e;
    const char* text = reinterpret_cast<const char*>(f.data);
    int version = raster::scene_version(text, f.size, &e);
    bool ok = version == 1 ? current_screen::load(text, f.size, &e) : version == 2 ? current_world::load(f.name, f.data, f.size, &e) : false;
    if (!ok) {
        reply_parse_error(cmd, f.name, e);
        return;
    }
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", cmd).str("name", f.name).str("origin", file_table::origin_name(f.origin)).u32("bytes", uint32_t(f.size));
    if (version == 1) describe_screen_scene(r);
    else describe_world(r);
    // what its buffers take of the pool, and what is left
    r.u32("memory_kib", uint32_t(guard::transient_taken() >> 10)).u32("free_kib", uint32_t(guard::transient_room() >> 10));
    r.end();
}

// Refuses an upload: the bytes its header announced are read and dropped first (while they come,
// file_table::discard), so that none of them is taken for a command, then the error, with how many were
// dropped (a scene error carries "line" 0, as a parse error carries its line).
void refuse_upload(const char* cmd, size_t announced, bool lead_lf, const char* message) {
    const size_t dropped = file_table::discard(announced, lead_lf);
    lib::JsonLine r = reply::begin(false);
    r.str("cmd", cmd).str("error", message).u32("discarded", uint32_t(dropped));
    if (StrView{cmd, lib::c_length(cmd)}.equals("scene")) r.u32("line", 0);
    r.end();
}

// Checks an upload's header (lib::check_upload_header: BYTES CRC32 after `name_args` words of name)
// and says "ready" when the bytes may come; else refuses it. False when refused. `lead_lf`: whether
// an LF leading the bytes is the header's (header_ended_by_cr).
bool accept_upload(const char* cmd, const StrView* args, size_t nargs, size_t name_args, bool lead_lf, lib::UploadHeader* h) {
    const lib::HeaderProblem problem = lib::check_upload_header(args, nargs, name_args, UPLOADED_SCENE, file_table::MAX_UPLOAD,
                                                                 size_t(raster::MAX_FILE_NAME), h);
    lib::Fmt m;
    bool ok = false;
    switch (problem) {
    case lib::HeaderProblem::Usage: m.s("usage: ").s(find_command(StrView{cmd, lib::c_length(cmd)})->usage); break;
    case lib::HeaderProblem::LengthOrChecksum:
        m.s("bad length or checksum: BYTES 1..").u(uint32_t(file_table::MAX_UPLOAD)).s(", CRC32 decimal or 0x hex");
        break;
    case lib::HeaderProblem::Name: m.s("bad name: 1 to ").u(uint32_t(raster::MAX_FILE_NAME - 1)).s(" characters"); break;
    case lib::HeaderProblem::None: ok = file_table::upload_fits(h->name, h->length, &m); break;
    }
    if (!ok) {
        refuse_upload(cmd, h->announced, lead_lf, m.c_str());
        return false;
    }
    lib::JsonLine(serial::sink()).str("event", "ready").str("cmd", cmd).u32("bytes", h->length).end();
    return true;
}

}  // namespace

void cmd_scene(Context&, const StrView* args, size_t nargs) {
    lib::UploadHeader h;
    const bool lead_lf = header_ended_by_cr();
    if (!accept_upload("scene", args, nargs, 0, lead_lf, &h)) return;
    lib::Fmt error;
    if (!file_table::upload(UPLOADED_SCENE, h.length, h.crc32, lead_lf, &error)) {
        // every scene error carries "line", as a parse error does: 0, no line
        reply::begin(false).str("cmd", "scene").str("error", error.c_str()).u32("line", 0).end();
        return;
    }
    load_and_reply("scene", *file_table::find(UPLOADED_SCENE));
}

void cmd_file(Context&, const StrView* args, size_t nargs) {
    lib::UploadHeader h;
    const bool lead_lf = header_ended_by_cr();
    if (!accept_upload("file", args, nargs, 1, lead_lf, &h)) return;
    lib::Fmt error;
    if (!file_table::upload(h.name, h.length, h.crc32, lead_lf, &error)) {
        reply::error("file", error.c_str());
        return;
    }
    const file_table::File* f = file_table::find(args[0]);
    reply::begin(true).str("cmd", "file").str("name", f->name).u32("bytes", uint32_t(f->size)).u64("upload_space_used", file_table::upload_space_used()).end();
}

void cmd_files(Context&, const StrView*, size_t) {
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "files").begin_array("files");
    for (int i = 0; i < file_table::count(); ++i) {
        const file_table::File& f = file_table::at(i);
        r.begin_item_object().str("name", f.name).str("origin", file_table::origin_name(f.origin)).u32("bytes", uint32_t(f.size)).end_object();
    }
    r.end_array().u64("upload_space_used", file_table::upload_space_used()).u64("upload_space", file_table::upload_space()).end();
}

void cmd_load(Context&, const StrView* args, size_t) {
    const file_table::File* f = file_table::find(args[0]);
    if (!f) {
        lib::Fmt m;
        m.s("no file '").s(args[0]).s("' (see 'files')");
        reply::error("load", m.c_str());
        return;
    }
    load_and_reply("load", *f);
}

}  // namespace server
