// The lookup of make bench's measured errors (measured.h).
#include "kernel/core/measured.h"

namespace raster {

namespace {

// "ball.scene" against "ball": equal up to the first '.' of the file name.
bool same_scene(const char* file, const char* scene) {
    for (; *scene; ++file, ++scene)
        if (*file != *scene) return false;
    return *file == 0 || *file == '.';
}

bool same(const char* a, const char* b) {
    for (; *a && *a == *b; ++a, ++b) {
    }
    return *a == *b;
}

}  // namespace

bool measured_error(const char* scene, const char* mapper, double* out) {
    for (int i = 0; i < MEASURED_ERROR_COUNT; ++i)
        if (MEASURED_ERRORS[i].scene[0] && same_scene(scene, MEASURED_ERRORS[i].scene) && same(mapper, MEASURED_ERRORS[i].mapper)) {
            *out = MEASURED_ERRORS[i].max_footprint;
            return true;
        }
    return false;
}

}  // namespace raster
