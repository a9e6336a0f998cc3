// Scene text: lines, header, numbers.
#include "kernel/scene/scene_text.h"

#include "kernel/lib/fmt.h"
#include "kernel/lib/words.h"

namespace raster::scene_text {

bool parse_decimal(lib::StrView w, double* out) {
    size_t i = 0;
    bool negative = false;
    if (i < w.size && (w.data[i] == '-' || w.data[i] == '+')) negative = w.data[i++] == '-';
    int64_t mantissa = 0;
    int digits = 0, decimals = 0;
    bool point = false;
    for (; i < w.size; ++i) {
        char c = w.data[i];
        if (c == '.' && !point) {
            point = true;
            continue;
        }
        if (c < '0' || c > '9') return false;
        if (point && ++decimals > MAX_DECIMALS) return false;
        if (++digits > 15) return false;  // keeps the mantissa below 2^53: exact in a double
        mantissa = mantissa * 10 + (c - '0');
    }
    if (digits == 0) return false;
    double scale = 1;
    for (int k = 0; k < decimals; ++k) scale *= 10;
    *out = double(negative ? -mantissa : mantissa) / scale;
    return true;
}

bool parse_int(lib::StrView w, int32_t lo, int32_t hi, int32_t* out) {
    uint32_t v;
    if (!lib::parse_u32(w, &v) || v < uint32_t(lo) || v > uint32_t(hi)) return false;
    *out = int32_t(v);
    return true;
}

bool fail(ParseError* error, int32_t line, const char* message) {
    error->line = line;
    lib::Fmt whole;  // (its room is the message's; a longer one ends with Fmt::CUT)
    lib::copy_c_string(error->message, sizeof error->message, whole.s(message).c_str());
    return false;
}

bool Lines::next(char* buf, const char** bad) {
    *bad = nullptr;
    while (pos_ < length_) {
        ++line;
        size_t len = 0;
        bool comment = false, blank = true;
        while (pos_ < length_ && text_[pos_] != '\n') {
            char c = text_[pos_++];
            if (c == '\0') {
                *bad = "binary data (a NUL byte): not a scene file";
                return false;
            }
            if (c == '#') comment = true;
            if (comment || c == '\r') continue;
            if (len == MAX_LINE) {
                *bad = "line too long (at most 2048 characters)";
                return false;
            }
            if (c != ' ' && c != '\t') blank = false;
            buf[len++] = c == '\t' ? ' ' : c;
        }
        ++pos_;  // the newline
        buf[len] = 0;
        if (!blank) return true;
    }
    return false;
}

int read_header(Lines& lines, char* buf, ParseError* error) {
    *error = ParseError{};
    const char* bad = nullptr;
    if (!lines.next(buf, &bad)) {
        if (bad) return fail(error, lines.line, bad), 0;
        return fail(error, 0, "empty file: the first line must be 'modexlab-scene 1' or 'modexlab-scene 2'"), 0;
    }
    lib::StrView w[3];
    size_t n = lib::split_words(buf, w, 3);
    if (n != 2 || !w[0].equals("modexlab-scene"))
        return fail(error, lines.line, "not a modexlab scene: the first line must be 'modexlab-scene 1' or 'modexlab-scene 2'"), 0;
    if (w[1].equals("1")) return 1;
    if (w[1].equals("2")) return 2;
    lib::Fmt m;
    m.s("scene version '").s(w[1]).s("' not supported (this build reads versions 1 and 2)");
    return fail(error, lines.line, m.c_str()), 0;
}

}  // namespace raster::scene_text

namespace raster {

int scene_version(const char* text, size_t length, ParseError* error) {
    scene_text::Lines lines(text, length);
    char buf[scene_text::MAX_LINE + 1];
    return scene_text::read_header(lines, buf, error);
}

}  // namespace raster
