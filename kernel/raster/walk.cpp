// Edge walking. On line L (row y, or column x) each edge's function is linear in the minor
// coordinate m: E = A*m + B(L), with B(L+1) = B(L) + C. Inside is E >= t, so an edge with A > 0
// bounds m from below by ceil((t - B)/A), one with A < 0 from above by floor((B - t)/-A), and one
// with A = 0 keeps or drops the whole line. Each bound is a floor division stepped exactly.
#include "kernel/raster/walk.h"

namespace raster {

namespace {

int64_t ceil_div_pos(int64_t n, int64_t d) { return -floor_div(-n, d); }

}  // namespace

void EdgeWalker::FloorDda::init(int64_t m, int64_t divisor, int64_t increment) {
    d = uint32_t(divisor);
    q = floor_div(m, divisor);
    r = uint32_t(m - q * divisor);
    int64_t step_q = floor_div(increment, divisor);
    dq = int32_t(step_q);
    dr = uint32_t(increment - step_q * divisor);
}

EdgeWalker::EdgeWalker(const PolygonSetup& s, Axis axis, const ClipRect& clip) : axis_(axis) {
    const bool rows = axis == Axis::Rows;
    // lines whose centre lies within the bounding box, inside the clip rectangle
    int64_t lo = rows ? s.min_y : s.min_x, hi = rows ? s.max_y : s.max_x;
    int64_t first = ceil_div_pos(lo - SUBPIXEL_HALF, SUBPIXEL_ONE);
    int64_t last = floor_div(hi - SUBPIXEL_HALF, SUBPIXEL_ONE);
    int32_t clip_lo = rows ? clip.y0 : clip.x0, clip_hi = (rows ? clip.y1 : clip.x1) - 1;
    if (first < clip_lo) first = clip_lo;
    if (last > clip_hi) last = clip_hi;
    line_ = int32_t(first);
    last_line_ = first > last ? int32_t(first) - 1 : int32_t(last);
    minor_lo_ = rows ? clip.x0 : clip.y0;
    minor_hi_ = (rows ? clip.x1 : clip.y1) - 1;
    if (line_ > last_line_) return;

    const int64_t centre_major = int64_t(line_) * SUBPIXEL_ONE + SUBPIXEL_HALF;
    for (int i = 0; i < s.edge_count; ++i) {
        const Edge& e = s.edges[i];
        // E = dx*(Py - py) - dy*(Px - px) with P = (256*m + 128, centre) for rows, (centre, 256*m + 128) for columns
        int64_t a, b, c;
        if (rows) {
            a = -e.dy * SUBPIXEL_ONE;
            b = e.dx * (centre_major - e.py) - e.dy * (SUBPIXEL_HALF - e.px);
            c = e.dx * SUBPIXEL_ONE;
        } else {
            a = e.dx * SUBPIXEL_ONE;
            b = e.dx * (SUBPIXEL_HALF - e.py) - e.dy * (centre_major - e.px);
            c = -e.dy * SUBPIXEL_ONE;
        }
        if (a > 0) {
            // m >= ceil((t - B)/A) = floor((t - B + A - 1)/A); the numerator falls by C each line
            lower_[lower_count_++].init(e.threshold - b + a - 1, a, -c);
        } else if (a < 0) {
            // m <= floor((B - t)/-A); the numerator grows by C each line
            upper_[upper_count_++].init(b - e.threshold, -a, c);
        } else {
            constant_[constant_count_++] = Constant{b, c, e.threshold};
        }
    }
}

bool EdgeWalker::next(Span* out) {
    while (line_ <= last_line_) {
        int64_t lo = minor_lo_, hi = minor_hi_;
        bool open = true;
        for (int32_t i = 0; i < lower_count_; ++i) {
            if (lower_[i].q > lo) lo = lower_[i].q;
            lower_[i].step();
        }
        for (int32_t i = 0; i < upper_count_; ++i) {
            if (upper_[i].q < hi) hi = upper_[i].q;
            upper_[i].step();
        }
        for (int32_t i = 0; i < constant_count_; ++i) {
            if (constant_[i].value < constant_[i].threshold) open = false;
            constant_[i].value += constant_[i].step;
        }
        int32_t line = line_++;
        if (!open || lo > hi) continue;
        if (axis_ == Axis::Rows) *out = Span{int32_t(lo), line, int32_t(hi - lo + 1)};
        else *out = Span{line, int32_t(lo), int32_t(hi - lo + 1)};
        return true;
    }
    return false;
}

}  // namespace raster
