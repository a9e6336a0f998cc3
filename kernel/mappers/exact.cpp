// The exact mapper's inner loop, the specification of asm/exact.asm.
#include "kernel/mappers/loops.h"
#include "kernel/core/setup.h"
#include "kernel/core/texture.h"

namespace raster {

static_assert(sizeof(Plane) == 3 * sizeof(double), "ExactArgs copies planes as three doubles");

void exact_loop(const void* raw) {
    const auto& a = *static_cast<const ExactArgs*>(raw);
    const Plane q{a.q[0], a.q[1], a.q[2]}, pu{a.pu[0], a.pu[1], a.pu[2]}, pv{a.pv[0], a.pv[1], a.pv[2]};
    const Texture tex{a.texels, a.width, a.height, a.clamp ? Wrap::Clamp : Wrap::Repeat};
    uint8_t* dst = a.dst;
    double x = a.x, y = a.y;
    for (int32_t n = 0; n < a.count; ++n) {
        int32_t tu, tv;
        perspective_texel(q, pu, pv, x, y, &tu, &tv);
        *dst = texel(tex, tu, tv);
        dst += a.stride;
        x += a.step_x;  // exact: integers below 2^53, and adding 0 changes nothing
        y += a.step_y;
    }
}

}  // namespace raster
