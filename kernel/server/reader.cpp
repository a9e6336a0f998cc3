// The line reader on COM1 and dispatch: a line's first word picks the command's row, whose
// argument counts are checked here so that no handler has to.
#include "drivers/serial.h"
#include "kernel/server/commands.h"
#include "kernel/server/reply.h"

namespace server {

namespace {

constexpr size_t MAX_LINE = 255;  // characters, without the line end
constexpr size_t MAX_WORDS = MAX_ARGS + 1;

void dispatch(Context& ctx, const char* line) {
    StrView words[MAX_WORDS];
    size_t n = lib::split_words(line, words, MAX_WORDS);
    if (n == 0) return;  // blank line: nothing to answer
    const Command* c = find_command(words[0]);
    if (!c) {
        lib::Fmt m;
        m.s("unknown command '").s(words[0]).s("' (try 'help')");
        reply::error("?", m.c_str());
        return;
    }
    size_t nargs = n - 1;
    if (nargs < c->min_args || nargs > c->max_args) usage_error(c->name);
    else c->handler(ctx, words + 1, nargs);
}

// The line's first control character other than a tab (a NUL included: every byte of the line
// counts; backspace and DEL have edited it already), or -1.
int first_control(const char* line, size_t len, size_t* at) {
    for (size_t i = 0; i < len; ++i)
        if (uint8_t(line[i]) < 0x20 && line[i] != '\t') {
            *at = i;
            return uint8_t(line[i]);
        }
    return -1;
}

}  // namespace

void run(Context& ctx) {
    char line[MAX_LINE + 1];
    size_t len = 0;
    bool too_long = false, after_cr = false;
    for (;;) {
        const char c = char(serial::read_byte());
        const bool lf_after_cr = after_cr && c == '\n';  // CR LF ends one line
        after_cr = c == '\r';
        if (lf_after_cr) continue;
        if (c == '\r' || c == '\n') {  // CR, LF or CR LF
            line[len] = 0;
            size_t at = 0;
            const int control = too_long ? -1 : first_control(line, len, &at);
            if (too_long) {
                reply::error("?", lib::Fmt().s("line too long (at most ").u(uint32_t(MAX_LINE)).s(" characters)").c_str());
            } else if (control >= 0) {
                const char digits[] = "0123456789abcdef", byte[3] = {digits[control >> 4], digits[control & 15], 0};
                lib::Fmt m;
                m.s("control character 0x").s(byte).s(" at column ").u(uint32_t(at + 1)).s(": the line is not run");
                reply::error("?", m.c_str());
            } else {
                dispatch(ctx, line);
            }
            len = 0;
            too_long = false;
        } else if (c == '\b' || c == 0x7F) {  // a person at a terminal
            if (len) --len;
        } else if (len < MAX_LINE) {
            line[len++] = c;
        } else {
            too_long = true;
        }
    }
}

}  // namespace server
