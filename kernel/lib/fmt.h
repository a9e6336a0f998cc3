// Formatting into a fixed buffer (error messages): strings, views and numbers, truncated, always NUL-terminated. Portable.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/lib/words.h"

namespace lib {

// Number text without libc, shared by Fmt and JsonLine. Not NUL-terminated.
constexpr size_t DECIMAL_MAX_CHARS = 20;  // 2^64 - 1
size_t format_decimal(uint64_t value, char* out);  // returns the number of chars written
constexpr size_t HEX32_CHARS = 10;
void format_hex32(uint32_t value, char* out);      // "0x" and 8 lower-case digits

class Fmt {
public:
    // Room for the longest list an error names (every mapper) and the word it could not find (a
    // unit test holds it). Text past it is dropped, and the text then ends with CUT: never cut
    // silently.
    static constexpr size_t CAPACITY = 1024;
    static constexpr const char* CUT = " [cut short]";

    Fmt& s(const char* text);
    Fmt& s(StrView text);
    Fmt& u(uint32_t value);
    Fmt& hex(uint32_t value);  // 0x-prefixed, 8 digits
    Fmt& tenths(uint64_t value);  // value / 10 with one decimal: 123 -> "12.3"
    // v >= 0 to two decimals, trailing zeros dropped ("0.5", "1", "2.25"); from 10 on, whole
    Fmt& decimal(double v);
    const char* c_str() const { return buf_; }
    bool cut() const { return cut_; }

private:
    void put(char c);
    char buf_[CAPACITY + 1] = {};
    size_t len_ = 0;
    bool cut_ = false;
};

}  // namespace lib
