// auto's candidate lists for the host's drawings (Budget::lists, kernel/mappers/auto/choice.h): one
// set for the program, built as its budgets and textures need them, as the kernel keeps its one.
#pragma once

#include "kernel/mappers/auto/choice.h"

namespace harness {

inline raster::ChoiceLists* host_choice_lists() {
    static raster::ChoiceLists* const lists = new raster::ChoiceLists();
    return lists;
}

}  // namespace harness
