// Where the pool goes: the largest stretch of RAM the loader reports (multiboot::usable, above 1 MiB
// and below 4 GiB) that holds none of what must stay: the kernel's image and buffers, the loader's
// structures (the information, command line, memory map, module list, names) and the modules.
#pragma once

#include <stdint.h>

#include "kernel/platform/multiboot.h"

namespace memory {

struct Range {
    uint64_t start = 0, end = 0;  // [start, end)
    uint64_t bytes() const { return end > start ? end - start : 0; }
};

// The image, five of the loader's structures, and each module and its name, up to MODULES_APART
// of them (a loader may put one far from the others: GRUB does)
constexpr int MODULES_APART = 128;
constexpr int MAX_KEPT = 6 + 2 * MODULES_APART + 2;

// What must stay, the kernel's image [image_start, image_end) first; returns the count. Each of
// the first MODULES_APART modules and its name is a range of its own; the modules after them count
// as one range from the lowest start to the highest end, their names as another.
// Without `modules`, the modules themselves are not kept (their list and names are).
int kept(const multiboot::Info* info, uint64_t image_start, uint64_t image_end, Range* out, bool modules = true);
// The largest stretch of RAM holding none of `kept`; empty when there is none.
Range largest_free(const multiboot::Info* info, const Range* kept, int count);

// Moves the modules lying in `pool` (a stretch that holds none of what stays but them) to its top,
// each at a page boundary, and updates the module list; returns the pool below them. Empty, with
// nothing moved, where a module lies partly in it. Without `move`, only what it would return.
// (A loader may scatter its modules: GRUB puts some megabytes apart, and the largest stretch
// between them is then far smaller than the RAM left.)
Range gather_modules(const multiboot::Info* info, Range pool, bool move);

}  // namespace memory
