// A byte sink: where streamed output (JSON lines, encoders) goes. Portable.
#pragma once

#include <stddef.h>

namespace lib {

struct Sink {
    void (*write_fn)(void* ctx, const char* data, size_t n) = nullptr;
    void* ctx = nullptr;

    void write(const char* data, size_t n) const { write_fn(ctx, data, n); }
    void put(char c) const { write_fn(ctx, &c, 1); }
};

}  // namespace lib
