// Not linked: compiled to assembly (-S) so the Makefile can turn these lines into offsets.inc,
// the argument-block layouts of kernel/raster/loops.h for the NASM loops.
#include <stddef.h>

#include "kernel/raster/loops.h"

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
}
