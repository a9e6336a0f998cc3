// Not linked: compiled to assembly (-S) so the Makefile can turn these lines into offsets.inc,
// the argument-block layouts of kernel/raster/loops.h for the NASM loops.
#include <stddef.h>

#include "kernel/mappers/loops.h"

#define OFFSET(symbol, type, member) asm volatile("\n.ascii \"@@@ " #symbol " %c0\"" : : "i"(offsetof(type, member)))
#define SIZE(symbol, type) asm volatile("\n.ascii \"@@@ " #symbol " %c0\"" : : "i"(sizeof(type)))

void offsets() {
    OFFSET(EXACT_DST, raster::ExactArgs, dst);
    OFFSET(EXACT_STRIDE, raster::ExactArgs, stride);
    OFFSET(EXACT_COUNT, raster::ExactArgs, count);
    OFFSET(EXACT_TEXELS, raster::ExactArgs, texels);
    OFFSET(EXACT_WIDTH, raster::ExactArgs, width);
    OFFSET(EXACT_HEIGHT, raster::ExactArgs, height);
    OFFSET(EXACT_CLAMP, raster::ExactArgs, clamp);
    OFFSET(EXACT_X, raster::ExactArgs, x);
    OFFSET(EXACT_Y, raster::ExactArgs, y);
    OFFSET(EXACT_STEP_X, raster::ExactArgs, step_x);
    OFFSET(EXACT_STEP_Y, raster::ExactArgs, step_y);
    OFFSET(EXACT_Q, raster::ExactArgs, q);
    OFFSET(EXACT_PU, raster::ExactArgs, pu);
    OFFSET(EXACT_PV, raster::ExactArgs, pv);
    SIZE(EXACT_ARGS_SIZE, raster::ExactArgs);

    OFFSET(XROW_DST, raster::XSharpRowArgs, dst);
    OFFSET(XROW_COUNT, raster::XSharpRowArgs, count);
    OFFSET(XROW_MASK, raster::XSharpRowArgs, mask);
    OFFSET(XROW_TEXEL, raster::XSharpRowArgs, texel);
    OFFSET(XROW_X_FRAC, raster::XSharpRowArgs, x_frac);
    OFFSET(XROW_Y_FRAC, raster::XSharpRowArgs, y_frac);
    OFFSET(XROW_X_STEP, raster::XSharpRowArgs, x_step);
    OFFSET(XROW_Y_STEP, raster::XSharpRowArgs, y_step);
    OFFSET(XROW_X_BASE, raster::XSharpRowArgs, x_base);
    OFFSET(XROW_X_CARRY, raster::XSharpRowArgs, x_carry);
    OFFSET(XROW_Y_BASE, raster::XSharpRowArgs, y_base);
    OFFSET(XROW_Y_CARRY, raster::XSharpRowArgs, y_carry);
    SIZE(XROW_ARGS_SIZE, raster::XSharpRowArgs);

    OFFSET(XCOL_DST, raster::XSharpColumnArgs, dst);
    OFFSET(XCOL_COUNT, raster::XSharpColumnArgs, count);
    OFFSET(XCOL_TEXEL, raster::XSharpColumnArgs, texel);
    OFFSET(XCOL_FRACTIONS, raster::XSharpColumnArgs, fractions);
    OFFSET(XCOL_STEPS, raster::XSharpColumnArgs, steps);
    OFFSET(XCOL_BASE, raster::XSharpColumnArgs, base);
    OFFSET(XCOL_ROW, raster::XSharpColumnArgs, row);
    OFFSET(XCOL_BACKWARDS, raster::XSharpColumnArgs, backwards);
    asm volatile("\n.ascii \"@@@ XSHARP_SCANWIDTH %c0\"" : : "i"(raster::XSHARP_SCANWIDTH));

    OFFSET(HECKER_DST, raster::HeckerArgs, dst);
    OFFSET(HECKER_COUNT, raster::HeckerArgs, count);
    OFFSET(HECKER_TEXEL, raster::HeckerArgs, texel);
    OFFSET(HECKER_U_FRAC, raster::HeckerArgs, u_frac);
    OFFSET(HECKER_V_FRAC, raster::HeckerArgs, v_frac);
    OFFSET(HECKER_DU_FRAC, raster::HeckerArgs, du_frac);
    OFFSET(HECKER_DV_FRAC, raster::HeckerArgs, dv_frac);
    OFFSET(HECKER_STEP_CARRY, raster::HeckerArgs, step_carry);
    OFFSET(HECKER_STEP_NO_CARRY, raster::HeckerArgs, step_no_carry);

    OFFSET(FATMAP_DST, raster::FatmapArgs, dst);
    OFFSET(FATMAP_COUNT, raster::FatmapArgs, count);
    OFFSET(FATMAP_TEXTURE, raster::FatmapArgs, texture);
    OFFSET(FATMAP_U, raster::FatmapArgs, u);
    OFFSET(FATMAP_V, raster::FatmapArgs, v);
    OFFSET(FATMAP_DU, raster::FatmapArgs, du);
    OFFSET(FATMAP_DV, raster::FatmapArgs, dv);

    OFFSET(LUT_DST, raster::FatmapLutArgs, dst);
    OFFSET(LUT_COUNT, raster::FatmapLutArgs, count);
    OFFSET(LUT_SOURCE, raster::FatmapLutArgs, source);
    OFFSET(LUT_TABLE, raster::FatmapLutArgs, table);

    OFFSET(FCOL_DST, raster::FastColumnArgs, dst);
    OFFSET(FCOL_COUNT, raster::FastColumnArgs, count);
    OFFSET(FCOL_TEXTURE, raster::FastColumnArgs, texture);
    OFFSET(FCOL_U, raster::FastColumnArgs, u);
    OFFSET(FCOL_V, raster::FastColumnArgs, v);
    OFFSET(FCOL_DU, raster::FastColumnArgs, du);
    OFFSET(FCOL_DV, raster::FastColumnArgs, dv);
    asm volatile("\n.ascii \"@@@ MODEX_ROW_BYTES %c0\"" : : "i"(raster::MODEX_ROW_BYTES));

    OFFSET(QUAKE_DST, raster::QuakeArgs, dst);
    OFFSET(QUAKE_COUNT, raster::QuakeArgs, count);
    OFFSET(QUAKE_X, raster::QuakeArgs, x);
    OFFSET(QUAKE_Y, raster::QuakeArgs, y);
    OFFSET(QUAKE_TEXELS, raster::QuakeArgs, texels);
    OFFSET(QUAKE_PITCH, raster::QuakeArgs, pitch);
    OFFSET(QUAKE_SADJUST, raster::QuakeArgs, sadjust);
    OFFSET(QUAKE_TADJUST, raster::QuakeArgs, tadjust);
    OFFSET(QUAKE_BBEXTENTS, raster::QuakeArgs, bbextents);
    OFFSET(QUAKE_BBEXTENTT, raster::QuakeArgs, bbextentt);
    OFFSET(QUAKE_SHIFT, raster::QuakeArgs, shift);
    OFFSET(QUAKE_S_ORIGIN, raster::QuakeArgs, s_origin);
    OFFSET(QUAKE_S_STEPU, raster::QuakeArgs, s_stepu);
    OFFSET(QUAKE_S_STEPV, raster::QuakeArgs, s_stepv);
    OFFSET(QUAKE_T_ORIGIN, raster::QuakeArgs, t_origin);
    OFFSET(QUAKE_T_STEPU, raster::QuakeArgs, t_stepu);
    OFFSET(QUAKE_T_STEPV, raster::QuakeArgs, t_stepv);
    OFFSET(QUAKE_Z_ORIGIN, raster::QuakeArgs, z_origin);
    OFFSET(QUAKE_Z_STEPU, raster::QuakeArgs, z_stepu);
    OFFSET(QUAKE_Z_STEPV, raster::QuakeArgs, z_stepv);
    OFFSET(QUAKE_S_STEPU_N, raster::QuakeArgs, s_stepu_n);
    OFFSET(QUAKE_T_STEPU_N, raster::QuakeArgs, t_stepu_n);
    OFFSET(QUAKE_Z_STEPU_N, raster::QuakeArgs, z_stepu_n);

    OFFSET(RUN_ROW, raster::FastRunArgs, row);
    OFFSET(RUN_PITCH, raster::FastRunArgs, pitch);
    OFFSET(RUN_LINES, raster::FastRunArgs, lines);
    OFFSET(RUN_CLIP_LO, raster::FastRunArgs, clip_lo);
    OFFSET(RUN_CLIP_HI, raster::FastRunArgs, clip_hi);
    OFFSET(RUN_LOWER, raster::FastRunArgs, lower);
    OFFSET(RUN_UPPER, raster::FastRunArgs, upper);
    OFFSET(RUN_TEXTURE, raster::FastRunArgs, texture);
    OFFSET(RUN_U, raster::FastRunArgs, u);
    OFFSET(RUN_V, raster::FastRunArgs, v);
    OFFSET(RUN_U_ROW, raster::FastRunArgs, u_row);
    OFFSET(RUN_V_ROW, raster::FastRunArgs, v_row);
    OFFSET(RUN_DU, raster::FastRunArgs, du);
    OFFSET(RUN_DV, raster::FastRunArgs, dv);
    OFFSET(RUN_TALLY, raster::FastRunArgs, tally);
    OFFSET(BOUND_Q, raster::EdgeBound, q);
    OFFSET(BOUND_DQ, raster::EdgeBound, dq);
    OFFSET(BOUND_R, raster::EdgeBound, r);
    OFFSET(BOUND_DR, raster::EdgeBound, dr);
    OFFSET(BOUND_D, raster::EdgeBound, d);
}
