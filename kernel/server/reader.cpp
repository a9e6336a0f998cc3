// The line reader on COM1 and dispatch: a line's first word picks the command's row, whose
// argument counts are checked here so that no handler has to. One LineAssembler takes every byte
// that is not an upload's: the reader's, and those a long command finds waiting (line_arrived).
#include "drivers/serial.h"
#include "kernel/present/file_table.h"
#include "kernel/lib/protocol.h"
#include "kernel/server/commands.h"
#include "kernel/server/reply.h"

namespace server {

namespace {

using Result = lib::LineAssembler::Result;

constexpr size_t MAX_WORDS = MAX_ARGS + 1;
constexpr uint8_t ESCAPE = 0x1B;

lib::LineAssembler g_lines;
// What feeding the byte that stopped a long command gave, for the reader to handle next.
bool g_pending = false;
Result g_pending_result = Result::More;

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

// A line refused whole (too long, a control character) is answered; where it is an upload header
// its payload is dropped first, as a refused header's (file_table::discard), and the reply says how much.
void refuse_line(Result r) {
    lib::Fmt m;
    if (r == Result::TooLong) {
        m.s("line too long (at most ").u(uint32_t(lib::LineAssembler::MAX_LINE)).s(" characters)");
    } else {
        const char digits[] = "0123456789abcdef", byte[3] = {digits[g_lines.control() >> 4], digits[g_lines.control() & 15], 0};
        m.s("control character 0x").s(byte).s(" at column ").u(uint32_t(g_lines.column()));
        if (g_lines.control() == ESCAPE) m.s(" (an arrow or function key? line editing is not supported)");
        m.s(": the line is not run");
    }
    const size_t announced = lib::refused_upload_bytes(g_lines, r);
    if (!announced) {
        reply::error("?", m.c_str());
        return;
    }
    const size_t dropped = file_table::discard(announced, header_ended_by_cr());
    reply::begin(false).str("cmd", "?").str("error", m.c_str()).u32("discarded", uint32_t(dropped)).end();
}

}  // namespace

bool line_arrived() {
    while (!g_pending && serial::byte_ready()) {
        const Result r = g_lines.feed(char(serial::read_byte()));
        if (r == Result::More && !g_lines.in_line()) continue;  // the LF of a CR LF: the line before's
        g_pending = true;
        g_pending_result = r;
    }
    return g_pending;
}

bool header_ended_by_cr() {
    const bool cr = g_lines.ended_by_cr();
    g_lines.forget_cr();
    return cr;
}

void run(Context& ctx) {
    for (;;) {
        const Result r = g_pending ? g_pending_result : g_lines.feed(char(serial::read_byte()));
        g_pending = false;
        if (r == Result::More || r == Result::Cancelled) continue;
        serial::end_lines_with_crlf(g_lines.ended_by_cr());  // replies in the style of the client's lines
        if (r == Result::Line) dispatch(ctx, g_lines.line());
        else refuse_line(r);
    }
}

}  // namespace server
