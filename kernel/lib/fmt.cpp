// Fixed-buffer formatting.
#include "kernel/lib/fmt.h"

namespace lib {

void Fmt::put(char c) {
    if (cut_) return;
    if (len_ < CAPACITY) {
        buf_[len_++] = c;
        buf_[len_] = 0;
        return;
    }
    cut_ = true;  // full: the text's end says so
    const size_t n = c_length(CUT);
    for (size_t i = 0; i < n; ++i) buf_[CAPACITY - n + i] = CUT[i];
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
    char digits[DECIMAL_MAX_CHARS];
    size_t n = format_decimal(value, digits);
    for (size_t i = 0; i < n; ++i) put(digits[i]);
    return *this;
}

Fmt& Fmt::hex(uint32_t value) {
    char digits[HEX32_CHARS];
    format_hex32(value, digits);
    for (char c : digits) put(c);
    return *this;
}

Fmt& Fmt::tenths(uint64_t value) {
    char digits[DECIMAL_MAX_CHARS];
    const size_t n = format_decimal(value / 10, digits);
    for (size_t i = 0; i < n; ++i) put(digits[i]);
    put('.');
    put(char('0' + value % 10));
    return *this;
}

Fmt& Fmt::decimal(double v) {
    if (!(v >= 0)) return s("?");
    if (v >= 10) return u(v < 4e9 ? uint32_t(v + 0.5) : 0xFFFFFFFFu);
    const uint32_t hundredths = uint32_t(v * 100 + 0.5);
    u(hundredths / 100);
    if (hundredths % 100) {
        put('.');
        put(char('0' + hundredths % 100 / 10));
        if (hundredths % 10) put(char('0' + hundredths % 10));
    }
    return *this;
}

size_t format_decimal(uint64_t value, char* out) {
    char reversed[DECIMAL_MAX_CHARS];
    size_t n = 0;
    do {
        reversed[n++] = char('0' + value % 10);
        value /= 10;
    } while (value);
    for (size_t i = 0; i < n; ++i) out[i] = reversed[n - 1 - i];
    return n;
}

void format_hex32(uint32_t value, char* out) {
    static constexpr char HEX[] = "0123456789abcdef";
    out[0] = '0';
    out[1] = 'x';
    for (int i = 0; i < 8; ++i) out[2 + i] = HEX[(value >> (28 - 4 * i)) & 15];
}

}  // namespace lib
