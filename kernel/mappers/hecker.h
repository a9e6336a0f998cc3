// Chris Hecker's subdividing perspective mapper with the sbb/adc step-table loop (Game Developer
// 1995-96): the polygon driver, the loop's argument block, the twin and the NASM loop (asm/hecker.asm).
#pragma once

#include <stdint.h>

#include "kernel/core/mapper.h"

namespace raster {

// hecker-steptable (Hecker, Game Developer part V, listing 2): one pointer carries both texel
// coordinates; per pixel the v fraction's carry (sbb: 0 or -1) picks one of two table entries and
// the u fraction's carry goes in through adc. Any texture width; nothing wraps.
struct HeckerArgs {
    uint8_t* dst;            // count pixels left to right
    int32_t count;
    const uint8_t* texel;    // the first pixel's texel
    uint32_t u_frac, v_frac; // fractions in bits 31..16
    uint32_t du_frac, dv_frac;
    int32_t step_carry;      // whole du + whole dv times the pitch, plus the pitch: v carried
    int32_t step_no_carry;   // whole du + whole dv times the pitch
};
Loop hecker_loop;

Check check_hecker;

}  // namespace raster

extern "C" {
raster::Loop hecker_loop_asm;
}

namespace raster::hecker {

SetupStatus draw(const DrawContext& c, const Vertex* vertices, int count);
// Its error bound: his walk and divides run again, each affine piece's texel indices against the
// exact mapping.
ErrorBound bound(const BoundContext& c, const Vertex* vertices, int count);

}  // namespace raster::hecker
