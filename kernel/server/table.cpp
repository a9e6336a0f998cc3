// The command table, the protocol's index: one row per command (docs/protocol.md), in the order
// `help` lists them.
#include "kernel/server/commands.h"
#include "kernel/server/reply.h"

namespace server {

namespace {

constexpr Command COMMANDS[] = {
    {"hello", "hello", 0, 0, cmd_hello},
    {"help", "help", 0, 0, cmd_help},
    {"mode", "mode 13h|modex", 1, 1, cmd_mode},
    {"pattern", "pattern ramp|planes|grid|border PAGE", 2, 2, cmd_pattern},
    {"clear", "clear PAGE [COLOUR]", 1, 2, cmd_clear},
    {"palette", "palette default|gray", 1, 1, cmd_palette},
    {"flip", "flip PAGE", 1, 1, cmd_flip},
    {"readback", "readback PAGE [crc]", 1, 2, cmd_readback},
    {"fault", "fault [ud|de|gp|triple|hang|texture-read|surface-write]", 0, 1, cmd_fault},
    // uploads check their own argument counts: a refused header's bytes are dropped (files.cpp)
    {"scene", "scene BYTES CRC32 (then, after the ready event, BYTES bytes of scene text, either version)", 0, MAX_ARGS, cmd_scene},
    {"file", "file NAME BYTES CRC32 (then, after the ready event, BYTES bytes: a texture or scene file)", 0, MAX_ARGS, cmd_file},
    {"files", "files", 0, 0, cmd_files},
    {"load", "load NAME (a scene file: built in, a module or uploaded)", 1, 1, cmd_load},
    {"render", "render MAPPER PAGE [linear|planar|vga] [asm|twin] (the screen-space scene)", 2, 4, cmd_render},
    {"frame", "frame N MAPPER PAGE [linear|planar|vga] [asm|twin] (frame N of the 3D scene)", 3, 5, cmd_frame},
    {"play", "play FRAMES MAPPER [linear|planar|vga] [asm|twin] (the 3D scene, page-flipped)", 2, 4, cmd_play},
    {"bench", "bench FRAMES MAPPER [linear|planar|vga] [asm|twin] (the 3D scene: timings per frame)", 2, 4, cmd_bench},
    {"mappers", "mappers", 0, 0, cmd_mappers},
    {"budget", "budget [scene|MAX-ERROR|any [exact|any [icount|486|pentium]]] (what auto draws the 3D scene to, and for which machine)", 0, 3, cmd_budget},
    {"selftest", "selftest [CASES]", 0, 1, cmd_selftest},
    {"fuzz", "fuzz N MAPPER [SEED] (N random extreme polygons, drawn between guard pages)", 2, 3, cmd_fuzz},
    {"vbe", "vbe on", 1, 1, cmd_vbe},
    {"exit", "exit CODE", 1, 1, cmd_exit},
};

}  // namespace

const Command* find_command(StrView name) {
    for (const Command& c : COMMANDS)
        if (name.equals(c.name)) return &c;
    return nullptr;
}

void cmd_help(Context&, const StrView*, size_t) {
    lib::JsonLine r = reply::begin(true);
    r.str("cmd", "help").begin_array("commands");
    for (const Command& c : COMMANDS) r.item_str(c.usage);
    r.end_array().end();
}

}  // namespace server
