// persp-subdiv-N: our subdividing perspective mapper (docs/mappers.md).
#include "kernel/mappers/subdiv.h"

namespace raster {

// persp-subdiv-N: exact u, v (the reference's perspective divide, unfloored) at the span's first
// pixel centre, every N pixels after it and at its last pixel; 16.16 steps between them, rounded
// to nearest (the divisor is the pixel count between the exact points, so the last pixel of each
// piece lands on the exact value). Repeat: both ends of a piece reduced by the same whole number of
// periods, so the piece never straddles a wrap. Every texel read goes through texel().
template <int N>
void subdiv_span(const SpanContext& c, const Span& s, uint8_t* dst, int32_t stride) {
    const PolygonSetup& setup = c.setup;
    const bool rows = c.axis == Axis::Rows;
    double x = centre_x(setup, s.x), y = centre_y(setup, s.y);
    auto exact_at = [&](int32_t k, double* u, double* v) {
        double px = rows ? x + double(k) * SUBPIXEL_ONE : x, py = rows ? y : y + double(k) * SUBPIXEL_ONE;
        double q = setup.q.at(px, py);
        *u = setup.pu.at(px, py) / q;
        *v = setup.pv.at(px, py) / q;
    };
    auto period = [&](double t, int32_t size) {  // whole periods below t (repeat), else none
        return c.tex.wrap == Wrap::Repeat ? double(size) * double(floor_i64(t / double(size))) : 0.0;
    };
    double u0, v0;
    exact_at(0, &u0, &v0);
    for (int32_t k = 0; k < s.count;) {
        int32_t len = s.count - k > N ? N : s.count - k;  // pixels in this piece
        int32_t end = k + len < s.count ? k + len : s.count - 1;  // the next exact point
        double u1, v1;
        if (end != k) exact_at(end, &u1, &v1);
        else u1 = u0, v1 = v0;
        double pu = period(u0, c.tex.width), pv = period(v0, c.tex.height);
        Fixed16_16 u = Fixed16_16::from_double(u0 - pu), v = Fixed16_16::from_double(v0 - pv);
        int32_t divisor = end - k;
        Fixed16_16 du{}, dv{};
        if (divisor > 0) {
            du = Fixed16_16::from_double(((u1 - pu) - (u0 - pu)) / divisor);
            dv = Fixed16_16::from_double(((v1 - pv) - (v0 - pv)) / divisor);
        }
        for (int32_t n = 0; n < len; ++n) {
            *dst = texel(c.tex, u.floor_int(), v.floor_int());
            dst += stride;
            u = u + du;
            v = v + dv;
        }
        k += len;
        u0 = u1, v0 = v1;
    }
}

template void subdiv_span<4>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void subdiv_span<8>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void subdiv_span<16>(const SpanContext&, const Span&, uint8_t*, int32_t);
template void subdiv_span<32>(const SpanContext&, const Span&, uint8_t*, int32_t);

}  // namespace raster
