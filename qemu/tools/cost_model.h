// The cost model auto chooses by (kernel/core/choice.h): per mapper, instructions to set up a
// polygon, per span and per pixel, fitted to the bench's own figures (docs/bench.md, "The cost
// model") and written as kernel/mappers/costs.cpp.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace harness {

struct FittedCost {
    double polygon = 0, span = 0, pixel = 0;
    int scenes = 0;  // the bench rows it was fitted to
};

// Fits every mapper of a trade.csv (read_csv's lines, header first): setup over polygons; the
// walking and inner loop per pixel as a line in spans per pixel (slope: per span, intercept: per
// pixel), least squares over the scenes, neither below zero.
std::map<std::string, FittedCost> fit_costs(const std::vector<std::vector<std::string>>& csv);

// The C++ source of kernel/mappers/costs.cpp: one row per registry row, in its order (-1: not
// measured; auto chooses such a mapper last). `source` names where the figures came from.
std::string cost_model_source(const std::map<std::string, FittedCost>& costs, const std::string& source);

// The C++ source of kernel/mappers/errors.cpp: per scene and mapper of a trade.csv (auto at the
// scene's own budget, not the auto@B rows), the largest footprint error the bench measured, which
// the kernel's on-screen bench shows beside its own timings (the kernel's pictures are the host's).
std::string measured_errors_source(const std::vector<std::vector<std::string>>& csv, const std::string& source);

}  // namespace harness
