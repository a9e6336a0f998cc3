// For the NASM loops' argument blocks: a mapper's NAME.cpp lists the fields its loop reads in a
// function compiled only with MODEXLAB_OFFSETS (to assembly, never linked); the Makefile turns the
// marked lines into build/kernel/gen/NAME.inc, which asm/NAME.asm includes. The numbers are the
// compiler's own, so the C++ and NASM layouts cannot drift apart.
#pragma once

#include <stddef.h>

// %define SYMBOL value
#define ASM_CONSTANT(symbol, value) asm volatile("\n.ascii \"@@@ " #symbol " %c0\"" : : "i"(value))
#define ASM_SIZE(symbol, type) ASM_CONSTANT(symbol, sizeof(type))
// ASM_FIELDS(FATMAP, FatmapArgs, dst, count): %define FATMAP_dst and FATMAP_count as the members'
// offsets; the NASM name is the prefix and the member's own name, formats included (FATMAP_u_16_16).
#define ASM_FIELD_(prefix, type, member) ASM_CONSTANT(prefix##_##member, offsetof(type, member));
#define ASM_PARENS_ ()
#define ASM_EXPAND_(...) ASM_EXPAND1_(ASM_EXPAND1_(ASM_EXPAND1_(ASM_EXPAND1_(__VA_ARGS__))))
#define ASM_EXPAND1_(...) ASM_EXPAND2_(ASM_EXPAND2_(ASM_EXPAND2_(ASM_EXPAND2_(__VA_ARGS__))))
#define ASM_EXPAND2_(...) ASM_EXPAND3_(ASM_EXPAND3_(ASM_EXPAND3_(ASM_EXPAND3_(__VA_ARGS__))))
#define ASM_EXPAND3_(...) __VA_ARGS__  // 64 rescans: up to 64 members
#define ASM_FIELDS(prefix, type, ...) __VA_OPT__(ASM_EXPAND_(ASM_FIELDS_STEP_(prefix, type, __VA_ARGS__)))
#define ASM_FIELDS_STEP_(prefix, type, member, ...) \
    ASM_FIELD_(prefix, type, member) __VA_OPT__(ASM_FIELDS_AGAIN_ ASM_PARENS_(prefix, type, __VA_ARGS__))
#define ASM_FIELDS_AGAIN_() ASM_FIELDS_STEP_
