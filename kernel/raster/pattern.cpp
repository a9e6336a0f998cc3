// Pattern names.
#include "kernel/raster/pattern.h"

namespace raster {

namespace {
constexpr const char* NAMES[PATTERN_COUNT] = {"ramp", "planes", "grid", "border"};
}

const char* pattern_name(Pattern p) { return NAMES[int(p)]; }

bool pattern_from_name(lib::StrView name, Pattern* out) {
    for (int i = 0; i < PATTERN_COUNT; ++i) {
        if (name.equals(NAMES[i])) {
            *out = Pattern(i);
            return true;
        }
    }
    return false;
}

}  // namespace raster
