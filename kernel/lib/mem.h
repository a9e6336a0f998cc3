// The freestanding mem* and strlen the kernel provides (the compiler emits calls to the mem* ones).
#pragma once

#include <stddef.h>

extern "C" {
void* memset(void* dst, int value, size_t n);
void* memcpy(void* __restrict dst, const void* __restrict src, size_t n);
void* memmove(void* dst, const void* src, size_t n);
int memcmp(const void* a, const void* b, size_t n);
size_t strlen(const char* s);
}
