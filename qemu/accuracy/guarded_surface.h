// A RAM surface for drawing at the extremes: 320 x 240, linear or planar, filled with FUZZ_FILL,
// guard bytes around it and the clip rectangle FUZZ_CLIP inside it, so that everything a mapper
// must not touch is a byte that must still hold the fill (the extremes report, the stability tests).
#pragma once

#include <stdint.h>

#include <vector>

#include "kernel/core/mapper.h"

namespace harness {

class GuardedSurface {
public:
    static constexpr int32_t GUARD_PIXELS = 8;    // around a linear surface, each side
    static constexpr size_t GUARD_BYTES = 256;    // before and after the four planes

    explicit GuardedSurface(bool planar);
    void reset();  // every byte FUZZ_FILL again
    bool planar() const { return planar_; }
    const raster::Target& target() const { return target_; }
    raster::Target& target() { return target_; }

    // One pass over every byte: those outside the clip rectangle (guards included) that no longer
    // hold the fill, and the pixels inside it that hold `marker`.
    struct Scan {
        uint64_t written_outside = 0, inside_marked = 0;
    };
    Scan scan(uint8_t marker) const;

private:
    uint8_t at(int32_t x, int32_t y) const;  // -GUARD_PIXELS <= x, y < size + GUARD_PIXELS when linear

    bool planar_;
    int32_t pitch_;
    std::vector<uint8_t> bytes_;
    raster::Target target_;
};

}  // namespace harness
