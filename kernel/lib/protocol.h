// The command server's front end, the part that reads what a client sends before any command runs:
// bytes into lines, and an upload's header into what may come after it. Portable, so that the host
// fuzzes the code the kernel runs (tests/fuzz: `command`, `upload`); the kernel feeds it from COM1
// (kernel/server/reader.cpp, files.cpp). docs/protocol.md describes the rules.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/lib/words.h"

namespace lib {

// Bytes to lines. A line ends at CR, LF or CR LF: an LF right after a CR belongs to the line the
// CR ended (feed drops it; a reader that takes the next bytes itself, an upload's, asks
// ended_by_cr). Backspace and DEL remove the last character (a person at a terminal); Ctrl-C
// drops the line so far; a line of more than MAX_LINE characters, or one holding a control
// character other than tab (a NUL included), is refused whole.
class LineAssembler {
public:
    static constexpr size_t MAX_LINE = 255;  // characters, without the line end
    static constexpr size_t TAIL = 48;       // the last characters of a line too long, kept (tail())

    enum class Result : uint8_t {
        More,       // the line goes on; or the LF of a CR LF (in_line() says which)
        Line,       // line() is a whole line, NUL-terminated, without control characters but tab
        TooLong,    // a line of more than MAX_LINE characters ended
        Control,    // a line holding control() at column() (1-based) ended
        Cancelled,  // Ctrl-C: the line so far is dropped; nothing is run or answered
    };

    Result feed(char c);
    const char* line() const { return line_; }
    size_t length() const { return length_; }
    uint8_t control() const { return control_; }
    size_t column() const { return column_; }
    // Whether bytes of a line not ended yet have come: the next command has begun.
    bool in_line() const { return begun_; }
    // Whether the last line ended with a CR, whose LF may still come.
    bool ended_by_cr() const { return after_cr_; }
    // The bytes after that CR are taken by another reader (an upload's): it drops the LF itself.
    void forget_cr() { after_cr_ = false; }
    // Of a line refused as too long (TooLong): line() holds its first MAX_LINE characters, tail()
    // its last (up to TAIL, NUL-terminated), where an upload header's length is.
    const char* tail() const { return tail_; }

private:
    void restart();

    char line_[MAX_LINE + 1] = {};
    char tail_[TAIL + 1] = {};
    size_t length_ = 0;  // of the finished line, once feed() says so; of the line so far before
    size_t tail_length_ = 0;
    bool too_long_ = false, after_cr_ = false, finished_ = false, begun_ = false;
    uint8_t control_ = 0;
    size_t column_ = 0;
};

// An upload's header: `scene BYTES CRC32` or `file NAME BYTES CRC32`, the words after the command.
struct UploadHeader {
    StrView name;               // scene: the caller's fixed name; file: its first word
    uint32_t length = 0, crc32 = 0;
    size_t announced = 0;       // the bytes a refusal drops (refused headers); SIZE_MAX: all that come
};

enum class HeaderProblem : uint8_t {
    None,
    Usage,                // not NAME_ARGS + 2 words
    LengthOrChecksum,     // BYTES not 1..max_upload, or CRC32 not a 32-bit number
    Name,                 // a name of 0 or max_name or more characters
};

// Checks the words after an upload command: `name_args` words of name (0 for scene, whose name is
// `fixed_name`; 1 for file), then BYTES and CRC32. Sets `header` whatever it says (announced: the
// length a refusal drops, read from scene's first word, file's second-to-last, so that a name with
// a space in it still finds it, or its second where it has only two).
HeaderProblem check_upload_header(const StrView* args, size_t nargs, size_t name_args, StrView fixed_name, size_t max_upload,
                                  size_t max_name, UploadHeader* header);

// The number a refused header announces, for the bytes to drop: decimal or 0x hex. Where none can
// be read (no such word, not a number, beyond 32 bits): SIZE_MAX, every byte that comes until the
// line is quiet, so that no byte of a payload is ever run as a command.
size_t announced_length(StrView word);
size_t announced_length(const StrView* word);  // nullptr: no word

// A line the assembler refused (TooLong, Control) whose first word is `scene` or `file` is still
// an upload header, and its payload follows: the bytes to drop after it (announced_length of the
// word check_upload_header reads; of a line too long, its first word from line(), its last words
// from tail()). 0: not an upload header.
size_t refused_upload_bytes(const LineAssembler& lines, LineAssembler::Result refused);

}  // namespace lib
