// Words of a command line: splitting on blanks and parsing numbers. Portable (kernel and host).
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace lib {

// A view of chars that is not NUL-terminated.
struct StrView {
    const char* data = nullptr;
    size_t size = 0;

    bool empty() const { return size == 0; }
    bool equals(const char* s) const;
    bool starts_with(const char* prefix) const;
    StrView drop(size_t n) const { return n >= size ? StrView{data + size, 0} : StrView{data + n, size - n}; }
};

size_t c_length(const char* s);  // strlen, for code that also builds on the host
// Copies `src` into dst[size] (size > 0), cut to size - 1 characters, always NUL-terminated.
void copy_c_string(char* dst, size_t size, const char* src);

// Splits `line` (NUL-terminated) on spaces and tabs into `words`; returns how many there were,
// counting past `max_words` (only the first max_words are stored).
size_t split_words(const char* line, StrView* words, size_t max_words);

// The index of `word` in names[0..count), or -1: for enums named on command lines and in files.
int find_name(StrView word, const char* const* names, int count);

// Decimal, or hex after 0x. False on an empty word, any other character, or a value above 2^32-1.
bool parse_u32(StrView word, uint32_t* out);

}  // namespace lib
