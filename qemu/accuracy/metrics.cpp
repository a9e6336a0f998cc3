// One pass over both pictures.
#include "qemu/accuracy/metrics.h"

namespace raster {

uint32_t texel_distance(int32_t a, int32_t b, int32_t size, Wrap wrap) {
    uint32_t d = uint32_t(a > b ? a - b : b - a);
    if (wrap == Wrap::Repeat && d > uint32_t(size) - d) d = uint32_t(size) - d;
    return d;
}

void add_texel_error(AccuracyMetrics& m, uint32_t e, uint64_t* error_sum) {
    ++m.compared;
    if (e > m.max_texel_error) m.max_texel_error = e;
    *error_sum += e;
    if (e == 0) ++m.exact;
    if (e <= 1) ++m.within_one;
}

void add_coverage(AccuracyMetrics& m, uint32_t rc, uint32_t dc) {
    if (rc) ++m.reference_pixels;
    if (dc) ++m.drawn_pixels;
    if (dc && !rc) ++m.overdraw;
    if (rc && !dc) ++m.gaps;
    if (dc > (rc ? rc : 1)) ++m.overlaps;
}

void accumulate(AccuracyMetrics& total, const AccuracyMetrics& m) {
    double errors = total.mean_texel_error * total.compared + m.mean_texel_error * m.compared;
    total.reference_pixels += m.reference_pixels;
    total.drawn_pixels += m.drawn_pixels;
    total.overdraw += m.overdraw;
    total.gaps += m.gaps;
    total.overlaps += m.overlaps;
    total.compared += m.compared;
    if (m.max_texel_error > total.max_texel_error) total.max_texel_error = m.max_texel_error;
    total.mean_texel_error = total.compared ? errors / total.compared : 0.0;
    total.exact += m.exact;
    total.within_one += m.within_one;
    total.index_differs += m.index_differs;
    total.union_pixels += m.union_pixels;
}

AccuracyMetrics compare_to_reference(const PixelImage& ref, const PixelImage& drawn, int32_t tex_width, int32_t tex_height,
                                     Wrap wrap) {
    AccuracyMetrics m;
    uint64_t error_sum = 0;
    int32_t n = ref.width * ref.height;
    for (int32_t i = 0; i < n; ++i) {
        uint8_t rc = ref.coverage[i], dc = drawn.coverage[i];
        add_coverage(m, rc, dc);
        if (rc || dc) {
            ++m.union_pixels;
            if (ref.index[i] != drawn.index[i]) ++m.index_differs;
        }
        if (!rc || !dc) continue;
        uint32_t du = texel_distance(ref.tu[i], drawn.tu[i], tex_width, wrap);
        uint32_t dv = texel_distance(ref.tv[i], drawn.tv[i], tex_height, wrap);
        add_texel_error(m, du > dv ? du : dv, &error_sum);
    }
    m.mean_texel_error = m.compared ? double(error_sum) / double(m.compared) : 0.0;
    return m;
}

}  // namespace raster
