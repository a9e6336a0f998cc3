// What make bench measured on the host that the kernel shows: the largest footprint error of each
// mapper on each demo scene (kernel/mappers/errors.cpp, generated), beside the timings the
// on-screen bench takes on the machine itself (the pictures are the same on every machine).
#pragma once

namespace raster {

struct MeasuredError {
    const char* scene;   // the demo scene's name, without ".scene"
    const char* mapper;
    float max_footprint;  // footprints; -1: the mapper drew nothing
};
extern const MeasuredError MEASURED_ERRORS[];
extern const int MEASURED_ERROR_COUNT;

// The error measured for the scene (its file name: "ball.scene" or "ball") and mapper; false
// where make bench has no such row (a scene that is not a demo scene, or one it did not run).
bool measured_error(const char* scene, const char* mapper, double* out);

}  // namespace raster
