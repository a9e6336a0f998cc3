// The kernel's current 3D scene (a version 2 scene file): loaded from the file table, its textures
// prepared once, its frames built and drawn into Mode X pages.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/scene/frame.h"
#include "kernel/present/present.h"

namespace current_world {

// Parses a version 2 scene text (its texture files found in the file table) and makes it the
// current one; loads its palette into the DAC when a graphics mode is on. Its buffers are taken
// sized to it (the screen-space scene's given back first: it is then not loaded); where they do
// not all fit, without the textures' doubled copies (doubled_copies()). On failure no 3D scene is
// loaded (the parser works in place) and `error` says why, a lack of memory included.
bool load(const char* name, const uint8_t* text, size_t length, raster::ParseError* error);
bool loaded();
// Whether the scene's textures have their doubled copies: false where the memory left had no room
// for them (docs/platform.md, "Memory").
bool doubled_copies();
// The scene_skipped event on COM1: a scene the show or the on-screen bench passes over, and why
// (load's error).
void say_skipped(const char* name, const raster::ParseError& error);
const raster::World& world();
const char* name();

struct FrameResult {
    raster::FrameStats frame;
    present::RenderResult render;
    uint64_t ticks_geometry;
};

// The budget auto draws the frames to: the scene's, or the one the `budget` command set, until it
// is cleared (nullptr) or another 3D scene is loaded.
void set_budget(const raster::Budget* override);
raster::Budget budget();
bool budget_overridden();

// Builds frame `n` and draws it with `mapper` into `page` through `surface`; with a probe, times
// the drawing's phases (the probe's clock must be set); with a watch, the drawing may stop early.
FrameResult render(int32_t n, const raster::Mapper& mapper, raster::Surface surface, int page, raster::Variant variant,
                   raster::Probe* probe = nullptr, const raster::Watch* watch = nullptr);

// The bench's figures for one frame (the `bench` command's and the show's on-screen bench's):
// ticks of the whole frame (geometry, clear, draw, blit), and of its parts; setup, inner loops and
// auto's choosing from a second drawing with the probe, walking the rest of the first's drawing time.
enum BenchField : uint32_t { B_TICKS, B_GEOMETRY, B_CLEAR, B_DRAW, B_SETUP, B_WALK, B_INNER, B_CHOOSE, B_BLIT, B_FLIP, B_FIELDS };
extern const char* const BENCH_FIELD_NAMES[B_FIELDS];  // "ticks", "ticks_geometry", ...
struct BenchFrame {
    int32_t frame;  // the scene's frame number
    int page;
    raster::RenderStats stats;  // the first drawing's
    bool used_asm, retrace;
    bool cut;  // the watch stopped a drawing: nothing shown, no figure measured
    uint64_t figures[B_FIELDS];
};
// The probe the bench's frames are timed with: the TSC its clock, its lap cost calibrated here, in
// one place (a lap compiled elsewhere may cost an instruction more or less: the `bench` command and
// the on-screen bench then give the same figures, identical under QEMU icount).
raster::Probe bench_probe();
// A bench row's start (the `bench` command's, each of the on-screen bench's): auto forgets the
// objects it keeps, so that each row pays its plans once, whatever was drawn before it.
void start_bench_row();

// Frame i of `count` spread evenly over the animation (frame i * length / count), drawn twice into
// the hidden page of pages 0 and 1 (plainly, then with a copy of the calibrated `probe`), then
// flipped. With a watch, a drawing may stop early: the frame is then `cut`, neither shown nor
// measured. A caption goes over the frame before it is shown (a text box at the top left, untimed).
BenchFrame bench_frame(uint32_t i, uint32_t count, const raster::Mapper& mapper, raster::Surface surface, raster::Variant variant,
                       const raster::Probe& probe, const raster::Watch* watch = nullptr, const char* caption = nullptr);

}  // namespace current_world
