// The line reader on COM1 and dispatch: a line's first word picks the command's row, whose
// argument counts are checked here so that no handler has to.
#include "drivers/serial.h"
#include "kernel/server/commands.h"
#include "kernel/server/reply.h"

namespace server {

namespace {

constexpr size_t MAX_LINE = 255;  // characters, without the newline
constexpr size_t MAX_WORDS = 8;

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

}  // namespace

void run(Context& ctx) {
    char line[MAX_LINE + 1];
    size_t len = 0;
    bool too_long = false;
    for (;;) {
        char c = char(serial::read_byte());
        if (c == '\r') continue;
        if (c == '\n') {
            line[len] = 0;
            if (too_long) reply::error("?", lib::Fmt().s("line too long (at most ").u(uint32_t(MAX_LINE)).s(" characters)").c_str());
            else dispatch(ctx, line);
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
