// The guarded surface (guarded_surface.h).
#include "qemu/accuracy/guarded_surface.h"

#include "kernel/core/fuzz.h"

namespace harness {

using namespace raster;

GuardedSurface::GuardedSurface(bool planar) : planar_(planar), pitch_(SCREEN_WIDTH + 2 * GUARD_PIXELS) { reset(); }

void GuardedSurface::reset() {
    if (planar_) {
        bytes_.assign(4 * size_t(PLANE_BYTES) + 2 * GUARD_BYTES, FUZZ_FILL);
        target_ = planar_target(bytes_.data() + GUARD_BYTES);
    } else {
        bytes_.assign(size_t(pitch_) * size_t(SCREEN_HEIGHT + 2 * GUARD_PIXELS), FUZZ_FILL);
        target_ = linear_target(bytes_.data() + GUARD_PIXELS * pitch_ + GUARD_PIXELS, SCREEN_WIDTH, SCREEN_HEIGHT, pitch_);
    }
    target_.clip = FUZZ_CLIP;
}

uint8_t GuardedSurface::at(int32_t x, int32_t y) const {
    if (planar_) return bytes_[GUARD_BYTES + size_t(x & 3) * PLANE_BYTES + size_t(y) * PLANE_ROW_BYTES + size_t(x >> 2)];
    return bytes_[size_t(y + GUARD_PIXELS) * size_t(pitch_) + size_t(x + GUARD_PIXELS)];
}

GuardedSurface::Scan GuardedSurface::scan(uint8_t marker) const {
    Scan s;
    const ClipRect& c = target_.clip;
    const int32_t g = planar_ ? 0 : GUARD_PIXELS;
    if (planar_)
        for (size_t i = 0; i < GUARD_BYTES; ++i)
            s.written_outside += (bytes_[i] != FUZZ_FILL) + (bytes_[bytes_.size() - 1 - i] != FUZZ_FILL);
    for (int32_t y = -g; y < SCREEN_HEIGHT + g; ++y)
        for (int32_t x = -g; x < SCREEN_WIDTH + g; ++x) {
            const uint8_t b = at(x, y);
            if (x >= c.x0 && x < c.x1 && y >= c.y0 && y < c.y1) s.inside_marked += b == marker;
            else s.written_outside += b != FUZZ_FILL;
        }
    return s;
}

}  // namespace harness
