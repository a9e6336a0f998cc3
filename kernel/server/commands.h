// The server's commands in the manner of xv6's system-call table: the Command row (table.cpp
// lists them all), the handlers by subject, and the argument helpers they share (args.cpp).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/core/budget.h"
#include "kernel/core/mapper.h"
#include "kernel/core/policy.h"
#include "kernel/core/render.h"
#include "kernel/lib/fmt.h"
#include "kernel/lib/json.h"
#include "kernel/lib/words.h"
#include "kernel/server/server.h"

namespace server {

using lib::StrView;

// A handler gets the words after the command's name, their count already checked against the row.
using Handler = void (*)(Context& ctx, const StrView* args, size_t nargs);

// The most words after a command's name: a line of 255 characters holds at most 128 words.
constexpr size_t MAX_ARGS = 127;

struct Command {
    const char* name;
    const char* usage;  // what `help` lists and a usage error quotes
    size_t min_args, max_args;
    Handler handler;
};

// The row named `name`, or nullptr (table.cpp).
const Command* find_command(StrView name);

// table.cpp
void cmd_help(Context& ctx, const StrView* args, size_t nargs);
// video.cpp: the mode, test patterns, palettes, pages and their pixels
void cmd_hello(Context& ctx, const StrView* args, size_t nargs);
void cmd_mode(Context& ctx, const StrView* args, size_t nargs);
void cmd_pattern(Context& ctx, const StrView* args, size_t nargs);
void cmd_clear(Context& ctx, const StrView* args, size_t nargs);
void cmd_palette(Context& ctx, const StrView* args, size_t nargs);
void cmd_flip(Context& ctx, const StrView* args, size_t nargs);
void cmd_readback(Context& ctx, const StrView* args, size_t nargs);
void cmd_vbe(Context& ctx, const StrView* args, size_t nargs);
// files.cpp: uploads, the file list and loading scenes
void cmd_scene(Context& ctx, const StrView* args, size_t nargs);
void cmd_file(Context& ctx, const StrView* args, size_t nargs);
void cmd_files(Context& ctx, const StrView* args, size_t nargs);
void cmd_load(Context& ctx, const StrView* args, size_t nargs);
// drawing.cpp: the mappers at work
void cmd_render(Context& ctx, const StrView* args, size_t nargs);
void cmd_frame(Context& ctx, const StrView* args, size_t nargs);
void cmd_play(Context& ctx, const StrView* args, size_t nargs);
void cmd_bench(Context& ctx, const StrView* args, size_t nargs);
void cmd_mappers(Context& ctx, const StrView* args, size_t nargs);
void cmd_budget(Context& ctx, const StrView* args, size_t nargs);
// A budget as a JSON object {given, max_error (footprints, or "any"), exact_coverage} (drawing.cpp).
void write_budget(lib::JsonLine& r, const char* key, const raster::Budget& b);
// diagnostics.cpp: faults on purpose, the NASM loops' self-test, leaving QEMU
void cmd_fault(Context& ctx, const StrView* args, size_t nargs);
void cmd_selftest(Context& ctx, const StrView* args, size_t nargs);
void cmd_fuzz(Context& ctx, const StrView* args, size_t nargs);
void cmd_exit(Context& ctx, const StrView* args, size_t nargs);

// --- argument helpers (args.cpp): each replies with the error itself and returns false ---------

// Whether a long command stops before its step `step` (a frame, a loop checked): the next line has
// begun on COM1 (or Ctrl-C came), and at least one step is done. The reply then says
// `interrupted` and how far it got.
bool interrupted(uint32_t step);

// reader.cpp: whether the header line just read ended with a CR, so that an LF leading its payload belongs to
// the line's end (file_table::upload, file_table::discard drop it); once: the reader forgets that CR.
bool header_ended_by_cr();

// A drawing watched (core/render.h): a line arriving on COM1 stops it between polygons, and where
// `interval` is set (TSC ticks) a `progress` event goes out that often, so that a scene that takes
// minutes shows it is alive. The watch also tells the page-fault handler what is drawn.
struct Progress {
    const char* cmd;
    uint64_t interval, next;
    raster::Watch watch();
    static bool keep_going(void* ctx, uint32_t done, uint32_t total);
};
// A second's worth of the clock's ticks (timer::hz).
Progress progress(const char* cmd, const Context& ctx);

// "usage: " and the usage of the command's row.
void usage_error(const char* cmd);

// The i-th of `count` names in the table a parser reads (for the choices an error lists).
using NameAt = const char* (*)(int i);
// "unknown KIND 'WORD' (KINDs: a, b, c)", the choices from the parser's own name table.
void unknown_name_error(const char* cmd, const char* kind, StrView word, NameAt name_at, int count);

// Checks that a graphics mode is on and `word` names one of its pages.
bool parse_page(const char* cmd, StrView word, int* page);

// MAPPER PAGE [SURFACE [asm|twin]] (PAGE absent for play and bench): what every drawing command takes.
struct DrawArgs {
    const raster::Mapper* mapper = nullptr;
    int page = 0;
    raster::Surface surface = raster::Surface::Linear;
    raster::Variant variant = raster::Variant::Asm;
    raster::Axis axis = raster::Axis::Rows;
};
bool parse_draw_args(const char* cmd, const StrView* args, size_t nargs, bool with_page, DrawArgs* d);

// The arguments of play and bench: FRAMES (1..most) then the draw arguments, and a 3D scene loaded.
// `count_note` follows the range in the error for a bad FRAMES.
bool parse_animation_args(const char* cmd, const StrView* args, size_t nargs, uint32_t most, const char* count_note,
                          uint32_t* frames, DrawArgs* d);

// Whether a 3D scene is loaded (else the error).
bool need_world(const char* cmd);

// The walkers by name, as replies and errors give them.
constexpr raster::Axis WALKERS[] = {raster::Axis::Rows, raster::Axis::Columns};
inline const char* walker_name(raster::Axis axis) { return axis == raster::Axis::Rows ? "rows" : "columns"; }

}  // namespace server
