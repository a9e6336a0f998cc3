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
    // floor(m / d) for d > 0, stepped exactly as m grows by a constant each line.
    struct FloorDda {
        int64_t q, r, d, dq, dr;
        void init(int64_t m, int64_t divisor, int64_t increment);
        void step() {
            q += dq;
            r += dr;
            if (r >= d) {
                r -= d;
                ++q;
            }
        }
    };
    enum class Kind : uint8_t { Lower, Upper, Constant };
    struct Bound {
        Kind kind;
        FloorDda dda;         // Lower: first inside pixel; Upper: last inside pixel
        int64_t value, step;  // Constant: the edge function on this line, and its change per line
        int32_t threshold;
    };

    Axis axis_;
    int32_t line_, last_line_;     // current and last major coordinate (row y, or column x)
    int32_t minor_lo_, minor_hi_;  // the clip rectangle across a line, inclusive
    int32_t bound_count_;
    Bound bounds_[MAX_POLYGON_VERTICES];
};

}  // namespace raster
