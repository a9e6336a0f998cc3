// The files the kernel knows: built into its image (the demo scenes and their textures), loaded
// by the boot loader as Multiboot modules, and uploaded over COM1. Scenes and the texture files
// they name are found here by name (uploads first, then modules, then built-ins).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/lib/fmt.h"
#include "kernel/lib/words.h"
#include "kernel/platform/multiboot.h"
#include "kernel/scene/world.h"

namespace file_table {

enum class Origin : uint8_t { Builtin, Module, Upload };
const char* origin_name(Origin o);

constexpr int MAX_FILES = 96;
// The name a `scene` upload is kept under; its place in the file table is kept for it (a full table
// refuses new `file` uploads first).
constexpr const char* SCENE_UPLOAD = "upload.scene";
// Bytes for all uploads of a boot: a quarter of the pool, at most MOST_UPLOAD_SPACE (the rest
// is the scenes' room).
constexpr size_t MOST_UPLOAD_SPACE = 6 << 20;
size_t upload_space();
constexpr size_t MAX_UPLOAD = 4 << 20;     // one upload

struct File {
    char name[raster::MAX_FILE_NAME];
    const uint8_t* data;
    size_t size;
    Origin origin;
};

// Registers the built-in files and the boot loader's modules (a module's name is the last word of
// its string: GRUB's `module /boot/x.bmp textures/x.bmp` and QEMU's -initrd "path name" both name
// it). Modules that overlap the kernel or run past memory are skipped and counted.
void init(const multiboot::Info* info, uint32_t* skipped_modules);

int count();
const File& at(int i);
const File* find(lib::StrView name);

// Whether an upload of `length` bytes under `name` would be taken: room in the upload space, and a
// place in the file table (a name already uploaded is replaced; the last place is SCENE_UPLOAD's
// until it has one). False with `error` otherwise.
bool upload_fits(lib::StrView name, size_t length, lib::Fmt* error);
// The bytes after an upload's header. `lead_lf`: the header ended with a CR, so an LF that comes
// first is the rest of its line end (CR LF), not a byte of the payload: dropped, not counted.

// Receives `length` bytes from COM1 (a stall of 5 s between bytes ends it) and checks their CRC-32;
// on success the file named `name` is (re)placed in the upload space. False with `error` otherwise
// (upload_fits' refusals before reading a byte).
bool upload(lib::StrView name, size_t length, uint32_t crc32, bool lead_lf, lib::Fmt* error);
// Reads and drops up to `length` bytes from COM1 (SIZE_MAX: all that come), stopping where none
// comes for 250 ms: the bytes that follow a refused upload's header, so that they are never taken
// for commands. How many it dropped.
size_t discard(size_t length, bool lead_lf);
size_t upload_space_used();

// Receives bytes from COM1 into `out` with the same rules (for callers with their own buffer).
bool receive(uint8_t* out, size_t length, uint32_t crc32, bool lead_lf, lib::Fmt* error);

// For parse_world: finds files here.
raster::FileResolver resolver();

}  // namespace file_table
