// Edge walkers: the spans (rows) or columns of a set-up polygon inside a clip rectangle, with
// all-integer stepping. Both walkers cover exactly the pixels covers() accepts.
#pragma once

#include <stdint.h>

#include "kernel/raster/setup.h"

namespace raster {

enum class Axis : uint8_t { Rows, Columns };

// Rows: pixels (x .. x+count-1, y). Columns: pixels (x, y .. y+count-1). count >= 1.
struct Span {
    int32_t x, y, count;
};

class EdgeWalker {
public:
    EdgeWalker(const PolygonSetup& setup, Axis axis, const ClipRect& clip);

    // The next non-empty span, in increasing row (or column) order; false when done.
    bool next(Span* out);

private:
    // floor(m / d) for d > 0, stepped exactly as m grows by a constant each line. The quotient
    // may be far off screen (64 bits); the remainder stays below d < 2^32 (32 bits).
    struct FloorDda {
        int64_t q;
        int32_t dq;
        uint32_t r, dr, d;
        void init(int64_t m, int64_t divisor, int64_t increment);
        void step() {
            q += dq;
            r += dr;  // r < d and dr < d, so no wrap below 2^32
            if (r >= d) {
                r -= d;
                ++q;
            }
        }
    };
    struct Constant {
        int64_t value, step;  // the edge function on this line, and its change per line
        int32_t threshold;
    };

    Axis axis_;
    int32_t line_, last_line_;     // current and last major coordinate (row y, or column x)
    int32_t minor_lo_, minor_hi_;  // the clip rectangle across a line, inclusive
    int32_t lower_count_ = 0, upper_count_ = 0, constant_count_ = 0;
    FloorDda lower_[MAX_POLYGON_VERTICES];  // first inside pixel: a lower bound on the line
    FloorDda upper_[MAX_POLYGON_VERTICES];  // last inside pixel: an upper bound
    Constant constant_[MAX_POLYGON_VERTICES];  // edges along the line: all of it in, or none
};

}  // namespace raster
