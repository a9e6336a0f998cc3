// Pattern names.
#include "kernel/scene/pattern.h"

namespace raster {

namespace {
constexpr const char* NAMES[PATTERN_COUNT] = {"ramp", "planes", "grid", "border"};
}

const char* pattern_name(Pattern p) { return NAMES[int(p)]; }

bool pattern_from_name(lib::StrView name, Pattern* out) {
    int i = lib::find_name(name, NAMES, PATTERN_COUNT);
    if (i >= 0) *out = Pattern(i);
    return i >= 0;
}

}  // namespace raster
