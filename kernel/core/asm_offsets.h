// For the NASM loops' argument blocks: a mapper's NAME.cpp lists the offsets and sizes its loop
// reads in a function compiled only with MODEXLAB_OFFSETS (to assembly, never linked); the Makefile
// turns the marked lines into build/kernel/gen/NAME.inc, which asm/NAME.asm includes. The numbers
// are the compiler's own, so the C++ and NASM layouts cannot drift apart.
#pragma once

#include <stddef.h>

#define ASM_CONSTANT(symbol, value) asm volatile("\n.ascii \"@@@ " #symbol " %c0\"" : : "i"(value))
#define ASM_OFFSET(symbol, type, member) ASM_CONSTANT(symbol, offsetof(type, member))
#define ASM_SIZE(symbol, type) ASM_CONSTANT(symbol, sizeof(type))
