// Fuzz target `command`: any bytes a client sends to the command server, through the server's own
// front end (kernel/lib/protocol.h): bytes into lines, lines into words, the numbers in them, and
// the upload headers among them. Promises: one outcome a line end (LF, CR, CR LF: counted here on
// the side) and one a Ctrl-C; a line has begun (in_line) exactly after a byte that is neither a
// line end, nor the LF of a CR LF, nor Ctrl-C; a line handed on is at most 255 characters with no
// control character but tab; a control character is reported at its column; words are non-empty
// and blank-free; a number parses back to its text's value; an upload header is taken only with a
// length of 1..4 MiB and a name of 1..63 characters, and a refused one drops no more than its
// words announce (all that come where none can be read), a refused line too (of a line too long,
// what its last words announce).
#include <stdint.h>

#include <string>

#include "kernel/lib/protocol.h"
#include "tests/fuzz/fuzz.h"

namespace {

constexpr size_t MAX_UPLOAD = 4 << 20, MAX_NAME = 64;

// What parse_u32 must say of a word, worked out another way.
bool reference_u32(lib::StrView w, uint32_t* out) {
    const bool hex = w.size > 2 && w.data[0] == '0' && (w.data[1] == 'x' || w.data[1] == 'X');
    const size_t from = hex ? 2 : 0;
    if (w.size == from) return false;
    unsigned long long v = 0;
    for (size_t i = from; i < w.size; ++i) {
        const std::string digits = hex ? "0123456789abcdef" : "0123456789";
        const char c = char(w.data[i] >= 'A' && w.data[i] <= 'F' && hex ? w.data[i] - 'A' + 'a' : w.data[i]);
        const size_t d = digits.find(c);
        if (d == std::string::npos) return false;
        v = v * (hex ? 16 : 10) + d;
        if (v > 0xFFFFFFFFull) return false;
    }
    *out = uint32_t(v);
    return true;
}

void check_line(const char* line, size_t length) {
    if (length > lib::LineAssembler::MAX_LINE || lib::c_length(line) != length) fuzz::fail("a line of the wrong length");
    for (size_t i = 0; i < length; ++i)
        if (uint8_t(line[i]) < 0x20 && line[i] != '\t') fuzz::fail("a control character in a line handed on");
    lib::StrView words[128];
    const size_t n = lib::split_words(line, words, 128);
    if (n > 128) fuzz::fail("more than 128 words in a line of 255 characters");
    for (size_t i = 0; i < n; ++i) {
        const lib::StrView w = words[i];
        if (w.empty() || w.data < line || w.data + w.size > line + length) fuzz::fail("a word outside its line");
        for (size_t k = 0; k < w.size; ++k)
            if (w.data[k] == ' ' || w.data[k] == '\t') fuzz::fail("a blank inside a word");
        uint32_t got = 0, want = 0;
        const bool ok = lib::parse_u32(w, &got), want_ok = reference_u32(w, &want);
        if (ok != want_ok || (ok && got != want)) fuzz::fail("parse_u32 of '" + std::string(w.data, w.size) + "'");
    }
    if (n == 0) return;
    const size_t name_args = words[0].equals("scene") ? 0 : words[0].equals("file") ? 1 : 2;
    if (name_args == 2) return;
    lib::UploadHeader h;
    const lib::HeaderProblem p = lib::check_upload_header(words + 1, n - 1, name_args, lib::StrView{"upload.scene", 12}, MAX_UPLOAD, MAX_NAME, &h);
    if (p == lib::HeaderProblem::None) {
        if (h.length == 0 || h.length > MAX_UPLOAD || h.name.size == 0 || h.name.size >= MAX_NAME || h.announced != h.length)
            fuzz::fail("a header taken with length " + std::to_string(h.length) + ", name of " + std::to_string(h.name.size));
        return;
    }
    // a refusal drops what one of its words announces (all that come: none can be read)
    bool announced_by_a_word = h.announced == SIZE_MAX;
    for (size_t i = 1; i < n && !announced_by_a_word; ++i) announced_by_a_word = lib::announced_length(words[i]) == h.announced;
    if (!announced_by_a_word) fuzz::fail("a refusal drops " + std::to_string(h.announced) + " bytes no word announced");
}

// A refused line's upload bytes, against its words: 0 unless its first word is scene or file;
// else what one of its words announces, or all that come.
void check_refused(const lib::LineAssembler& lines, lib::LineAssembler::Result r) {
    const size_t drop = lib::refused_upload_bytes(lines, r);
    lib::StrView words[128];
    const size_t n = lib::split_words(lines.line(), words, 128);
    const bool header = n > 0 && (words[0].equals("scene") || words[0].equals("file"));
    if (!header) {
        if (drop) fuzz::fail("a refused line that is no upload header drops bytes");
        return;
    }
    bool announced = drop == SIZE_MAX;
    for (size_t i = 1; i < n && i < 128 && !announced; ++i) announced = lib::announced_length(words[i]) == drop;
    lib::StrView last[32];
    const size_t t = r == lib::LineAssembler::Result::TooLong ? lib::split_words(lines.tail(), last, 32) : 0;
    for (size_t i = 0; i < t && i < 32 && !announced; ++i) announced = lib::announced_length(last[i]) == drop;
    if (!announced) fuzz::fail("a refused upload header drops " + std::to_string(drop) + " bytes no word announced");
}

}  // namespace

MODEXLAB_FUZZ_TARGET(command) {
    lib::LineAssembler lines;
    size_t ends = 0, outcomes = 0;
    bool after_cr = false;
    for (size_t i = 0; i < size; ++i) {
        const char c = char(data[i]);
        const bool line_end = c == '\r' || (c == '\n' && !after_cr), begins = !line_end && !(c == '\n' && after_cr) && c != 0x03;
        ends += line_end || c == 0x03;
        after_cr = c == '\r';
        const lib::LineAssembler::Result r = lines.feed(c);
        switch (r) {
        case lib::LineAssembler::Result::More: break;
        case lib::LineAssembler::Result::Cancelled: ++outcomes; break;
        case lib::LineAssembler::Result::Line:
            ++outcomes;
            check_line(lines.line(), lines.length());
            break;
        case lib::LineAssembler::Result::TooLong:
            ++outcomes;
            check_refused(lines, r);
            break;
        case lib::LineAssembler::Result::Control: {
            ++outcomes;
            const size_t col = lines.column();
            if (col < 1 || col > lines.length() || uint8_t(lines.line()[col - 1]) != lines.control() || lines.control() >= 0x20 ||
                lines.control() == '\t')
                fuzz::fail("a control character reported at the wrong column");
            check_refused(lines, r);
            break;
        }
        }
        if (outcomes != ends) fuzz::fail("line ends and outcomes differ: " + std::to_string(ends) + " against " + std::to_string(outcomes));
        if (begins != lines.in_line()) fuzz::fail(begins ? "a byte of a line did not begin one" : "a line end, the LF of a CR LF or Ctrl-C left a line begun");
    }
    return 0;
}
