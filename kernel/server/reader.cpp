// The line reader on COM1 and dispatch: a line's first word picks the command's row, whose
// argument counts are checked here so that no handler has to.
#include "drivers/serial.h"
#include "kernel/lib/protocol.h"
#include "kernel/server/commands.h"
#include "kernel/server/reply.h"

namespace server {

namespace {

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

}  // namespace

void run(Context& ctx) {
    lib::LineAssembler lines;
    for (;;) {
        switch (lines.feed(char(serial::read_byte()))) {
        case lib::LineAssembler::Result::More: break;
        case lib::LineAssembler::Result::Line: dispatch(ctx, lines.line()); break;
        case lib::LineAssembler::Result::TooLong:
            reply::error("?", lib::Fmt().s("line too long (at most ").u(uint32_t(lib::LineAssembler::MAX_LINE)).s(" characters)").c_str());
            break;
        case lib::LineAssembler::Result::Control: {
            const char digits[] = "0123456789abcdef", byte[3] = {digits[lines.control() >> 4], digits[lines.control() & 15], 0};
            lib::Fmt m;
            m.s("control character 0x").s(byte).s(" at column ").u(uint32_t(lines.column())).s(": the line is not run");
            reply::error("?", m.c_str());
            break;
        }
        }
    }
}

}  // namespace server
