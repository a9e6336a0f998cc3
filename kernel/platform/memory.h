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

constexpr int MAX_KEPT = 8;  // the image, five of the loader's structures, the modules, their names

// What must stay, the kernel's image [image_start, image_end) first; returns the count. The modules
// count as one range from the lowest start to the highest end, their names as another.
int kept(const multiboot::Info* info, uint64_t image_start, uint64_t image_end, Range* out);
// The largest stretch of RAM holding none of `kept`; empty when there is none.
Range largest_free(const multiboot::Info* info, const Range* kept, int count);

}  // namespace memory
