// The targets linked into the replay program, and the input it is running (for fail()'s message).
#pragma once

#include <string>
#include <vector>

#include "tests/fuzz/fuzz.h"

namespace fuzz {

struct Entry {
    std::string name;
    Target target;
};

std::vector<Entry>& targets();
std::string& current_input();

}  // namespace fuzz
