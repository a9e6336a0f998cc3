// Fixed-buffer formatting.
#include "kernel/lib/fmt.h"

namespace lib {

void Fmt::put(char c) {
    if (len_ < CAPACITY) buf_[len_++] = c;
    buf_[len_] = 0;
}

Fmt& Fmt::s(const char* text) {
    while (*text) put(*text++);
    return *this;
}

Fmt& Fmt::s(StrView text) {
    for (size_t i = 0; i < text.size; ++i) put(text.data[i]);
    return *this;
}

Fmt& Fmt::u(uint32_t value) {
    char digits[10];
    int n = 0;
    do {
        digits[n++] = char('0' + value % 10);
        value /= 10;
    } while (value);
    while (n) put(digits[--n]);
    return *this;
}

Fmt& Fmt::hex(uint32_t value) {
    static constexpr char HEX[] = "0123456789abcdef";
    put('0');
    put('x');
    for (int i = 0; i < 8; ++i) put(HEX[(value >> (28 - 4 * i)) & 15]);
    return *this;
}

}  // namespace lib
