// One pass over both pictures; the means and percentiles from every compared pixel's errors.
#include "qemu/accuracy/metrics.h"

#include <algorithm>

namespace raster {

namespace {

// The nearest-rank 99.9th percentile: the smallest value that at least 99.9 % of the samples do not
// exceed (the sample of rank ceil(0.999 n)).
template <typename T>
T percentile_999(std::vector<T> samples) {
    if (samples.empty()) return T(0);
    size_t rank = (samples.size() * 999 + 999) / 1000;  // ceil(0.999 n), 1-based
    auto nth = samples.begin() + std::ptrdiff_t(rank - 1);
    std::nth_element(samples.begin(), nth, samples.end());
    return *nth;
}

}  // namespace

uint32_t texel_distance(int32_t a, int32_t b, int32_t size, Wrap wrap) {
    uint32_t d = uint32_t(a > b ? a - b : b - a);
    if (wrap == Wrap::Repeat && d > uint32_t(size) - d) d = uint32_t(size) - d;
    return d;
}

uint32_t texel_error(int32_t ru, int32_t rv, int32_t tu, int32_t tv, int32_t tex_width, int32_t tex_height, Wrap wrap, bool* folded) {
    uint32_t du = texel_distance(ru, tu, tex_width, wrap), dv = texel_distance(rv, tv, tex_height, wrap);
    *folded = wrap == Wrap::Repeat && ((du > 0 && du == uint32_t(tex_width) / 2) || (dv > 0 && dv == uint32_t(tex_height) / 2));
    return du > dv ? du : dv;
}

void add_texel_error(AccuracyMetrics& m, uint32_t e, double footprint, bool folded) {
    ++m.compared;
    if (e > m.max_texel_error) m.max_texel_error = e;
    double fe = footprint_error(e, footprint);
    if (fe > m.max_footprint_error) m.max_footprint_error = fe;
    m.texel_errors.push_back(e);
    m.footprint_errors.push_back(float(fe));
    if (folded) ++m.folded;
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

void finish_metrics(AccuracyMetrics& m) {
    double texel_sum = 0, footprint_sum = 0;
    for (uint32_t e : m.texel_errors) texel_sum += e;
    for (float e : m.footprint_errors) footprint_sum += e;
    size_t n = m.texel_errors.size();
    m.mean_texel_error = n ? texel_sum / double(n) : 0.0;
    m.mean_footprint_error = n ? footprint_sum / double(n) : 0.0;
    m.p999_texel_error = percentile_999(m.texel_errors);
    m.p999_footprint_error = percentile_999(m.footprint_errors);
}

void merge(AccuracyMetrics& total, const AccuracyMetrics& m) {
    total.reference_pixels += m.reference_pixels;
    total.drawn_pixels += m.drawn_pixels;
    total.overdraw += m.overdraw;
    total.gaps += m.gaps;
    total.overlaps += m.overlaps;
    total.compared += m.compared;
    total.max_texel_error = std::max(total.max_texel_error, m.max_texel_error);
    total.max_footprint_error = std::max(total.max_footprint_error, m.max_footprint_error);
    total.folded += m.folded;
    total.exact += m.exact;
    total.within_one += m.within_one;
    total.index_differs += m.index_differs;
    total.union_pixels += m.union_pixels;
    total.texel_errors.insert(total.texel_errors.end(), m.texel_errors.begin(), m.texel_errors.end());
    total.footprint_errors.insert(total.footprint_errors.end(), m.footprint_errors.begin(), m.footprint_errors.end());
}

void accumulate(AccuracyMetrics& total, const AccuracyMetrics& m) {
    merge(total, m);
    finish_metrics(total);
}

AccuracyMetrics compare_to_reference(const PixelImage& ref, const PixelImage& drawn, int32_t tex_width, int32_t tex_height,
                                     Wrap wrap) {
    AccuracyMetrics m;
    int32_t n = ref.width * ref.height;
    for (int32_t i = 0; i < n; ++i) {
        uint8_t rc = ref.coverage[i], dc = drawn.coverage[i];
        add_coverage(m, rc, dc);
        if (rc || dc) {
            ++m.union_pixels;
            if (ref.index[i] != drawn.index[i]) ++m.index_differs;
        }
        if (!rc || !dc) continue;
        bool folded;
        uint32_t e = texel_error(ref.tu[i], ref.tv[i], drawn.tu[i], drawn.tv[i], tex_width, tex_height, wrap, &folded);
        add_texel_error(m, e, ref.footprint ? double(ref.footprint[i]) : 1.0, folded);
    }
    finish_metrics(m);
    return m;
}

}  // namespace raster
