// The extremes report (`make extremes`, docs/accuracy.md "Stability at the extremes"): every mapper
// through named classes of extreme input, each generated from a seed, measured against the exact
// reference polygon by polygon, with texture reads and surface writes checked, each mapper and
// class in a child process of its own so that a fault or a hang is reported, not fatal.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "kernel/core/mapper.h"

namespace harness {

struct ExtremeRow {
    std::string mapper, cls;
    uint32_t tried = 0, drawn = 0;
    uint32_t refused[7] = {};  // by SetupStatus (index 0 unused)
    double max_footprint = 0, sum_footprint = 0;
    uint64_t compared = 0, gaps = 0, overdraw = 0;
    uint64_t reads_outside = 0;   // pixels drawn from outside the texture and its copies (poison)
    uint64_t writes_outside = 0;  // bytes written outside the clip rectangle
    uint32_t bound_exceeded = 0;  // polygons measured above the mapper's own bound (core/bound.h)
    uint32_t coverage_broken = 0; // polygons whose bound promised exact coverage, drawn otherwise
    std::string fault;            // the signal that ended its child, or empty
    bool hang = false;            // its child ran past the time limit
    // the rotation sweep only (else negative): the largest distance between the centroids of the
    // drawn and the reference pixels (pixels), and the spread of the largest footprint error
    // over the angles (largest minus smallest)
    double centroid_shift = -1, error_spread = -1;

    double mean_footprint() const { return compared ? sum_footprint / double(compared) : 0; }
    uint32_t refused_total() const;
    // what the registry and the bound promise that this row breaks, or empty
    std::string broken_promise() const;
};

struct ExtremesOptions {
    int polygons = 300;  // a class of random polygons (the sweeps have their own counts)
    uint32_t seed = 2026;
    std::vector<std::string> mappers, classes;  // empty: all
    int timeout_seconds = 600;                  // a child, before it counts as a hang
    int rotation_step = 1;                      // degrees between the rotation sweep's angles
};

// near-plane, convex, sliver, tiny, huge, degenerate, perspective, anywhere, beyond,
// texture-limits, rotation
const std::vector<std::string>& extreme_classes();

// One mapper through one class, in this process.
ExtremeRow run_extreme_class(const raster::Mapper& mapper, const std::string& cls, const ExtremesOptions& o);

// Every mapper (of o.mappers) through every class (of o.classes), two children at a time; `done`
// hears of each row as it comes.
std::vector<ExtremeRow> run_extremes(const ExtremesOptions& o, const std::function<void(const ExtremeRow&, size_t, size_t)>& done);

// build/report/extremes.md and extremes.csv.
void write_extremes_report(const std::vector<ExtremeRow>& rows, const ExtremesOptions& o, const std::string& dir);

}  // namespace harness
