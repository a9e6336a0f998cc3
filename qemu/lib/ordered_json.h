// The harness's JSON type: nlohmann-json keeping key order, so lines print as the kernel wrote them.
#pragma once

#include <nlohmann/json.hpp>

namespace harness {
using json = nlohmann::ordered_json;
}
