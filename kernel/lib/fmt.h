// Formatting into a fixed buffer (error messages): strings, views and numbers, truncated, always NUL-terminated. Portable.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/lib/words.h"

namespace lib {

class Fmt {
public:
    static constexpr size_t CAPACITY = 160;

    Fmt& s(const char* text);
    Fmt& s(StrView text);
    Fmt& u(uint32_t value);
    Fmt& hex(uint32_t value);  // 0x-prefixed, 8 digits
    const char* c_str() const { return buf_; }

private:
    void put(char c);
    char buf_[CAPACITY + 1] = {};
    size_t len_ = 0;
};

}  // namespace lib
