// Command-line words: blank-separated views and unsigned numbers.
#include "kernel/lib/words.h"

namespace lib {

size_t c_length(const char* s) {
    size_t n = 0;
    while (s[n]) ++n;
    return n;
}

void copy_c_string(char* dst, size_t size, const char* src) {
    size_t i = 0;
    for (; src[i] && i + 1 < size; ++i) dst[i] = src[i];
    dst[i] = 0;
}

bool StrView::starts_with(const char* prefix) const {
    size_t n = c_length(prefix);
    if (n > size) return false;
    for (size_t i = 0; i < n; ++i)
        if (data[i] != prefix[i]) return false;
    return true;
}

bool StrView::equals(const char* s) const { return c_length(s) == size && starts_with(s); }

int find_name(StrView word, const char* const* names, int count) {
    for (int i = 0; i < count; ++i)
        if (word.equals(names[i])) return i;
    return -1;
}

size_t split_words(const char* line, StrView* words, size_t max_words) {
    size_t count = 0;
    const char* p = line;
    for (;;) {
        while (*p == ' ' || *p == '\t') ++p;
        if (!*p) return count;
        const char* start = p;
        while (*p && *p != ' ' && *p != '\t') ++p;
        if (count < max_words) words[count] = StrView{start, static_cast<size_t>(p - start)};
        ++count;
    }
}

bool parse_u32(StrView word, uint32_t* out) {
    if (word.empty()) return false;
    uint32_t base = 10;
    size_t i = 0;
    if (word.size > 2 && word.data[0] == '0' && (word.data[1] == 'x' || word.data[1] == 'X')) {
        base = 16;
        i = 2;
    }
    uint64_t value = 0;
    for (; i < word.size; ++i) {
        char c = word.data[i];
        uint32_t digit;
        if (c >= '0' && c <= '9') digit = static_cast<uint32_t>(c - '0');
        else if (c >= 'a' && c <= 'f') digit = static_cast<uint32_t>(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F') digit = static_cast<uint32_t>(c - 'A' + 10);
        else return false;
        if (digit >= base) return false;
        value = value * base + digit;
        if (value > 0xFFFFFFFFull) return false;
    }
    *out = static_cast<uint32_t>(value);
    return true;
}

}  // namespace lib
