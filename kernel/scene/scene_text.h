// The text of scene files, shared by the version 1 and version 2 parsers: lines (comments, blanks,
// \r and tabs handled), the header, exact decimals, integers, errors with their line.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/lib/words.h"
#include "kernel/scene/scene.h"

namespace raster::scene_text {

constexpr size_t MAX_LINE = 2048;  // characters, without the newline

// A decimal: optional sign, digits, optional '.' and at most MAX_DECIMALS digits after it, at most
// 15 digits, no exponent. The value is mantissa / 10^decimals, one correctly rounded division: the
// same double everywhere.
bool parse_decimal(lib::StrView w, double* out);
// A decimal integer within [lo, hi], lo >= 0.
bool parse_int(lib::StrView w, int32_t lo, int32_t hi, int32_t* out);

// Sets the error (line 0: about the whole file) and returns false.
bool fail(ParseError* error, int32_t line, const char* message);

// The lines of a text, one at a time.
class Lines {
public:
    Lines(const char* text, size_t length) : text_(text), length_(length) {}
    // The next line that is not blank, comment stripped, tabs as spaces, into buf (MAX_LINE + 1
    // chars). False at the end, or on a NUL byte or a line too long (then *bad says which).
    bool next(char* buf, const char** bad);
    int32_t line = 0;  // of the last line read, from 1

private:
    const char* text_;
    size_t length_, pos_ = 0;
};

// Reads the header line 'modexlab-scene N'; returns N (1 or 2), or 0 with the error set.
int read_header(Lines& lines, char* buf, ParseError* error);

// Calls on_line(buf) for every line after the header, lines.line telling its number; stops at
// the first false. False when on_line failed (it set the error) or a line was bad (set here).
template <typename OnLine>
bool each_line(Lines& lines, char* buf, ParseError* error, OnLine&& on_line) {
    for (;;) {
        const char* bad = nullptr;
        if (!lines.next(buf, &bad)) return bad ? fail(error, lines.line, bad) : true;
        if (!on_line(buf)) return false;
    }
}

}  // namespace raster::scene_text
