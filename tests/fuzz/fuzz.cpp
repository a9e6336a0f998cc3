// What every fuzz target shares: the registry the replay program runs, and fail().
#include "tests/fuzz/fuzz.h"

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "tests/fuzz/registry.h"

namespace fuzz {

std::vector<Entry>& targets() {
    static std::vector<Entry> all;
    return all;
}

std::string& current_input() {
    static std::string name;
    return name;
}

Registration::Registration(const char* name, Target target) { targets().push_back(Entry{name, target}); }

void fail(const std::string& what) {
    std::fprintf(stderr, "fuzz: broken promise: %s%s%s\n", what.c_str(), current_input().empty() ? "" : "; input ",
                 current_input().c_str());
    std::fflush(stderr);
    std::abort();
}

}  // namespace fuzz
