// The command server's front end: line assembly and upload headers (protocol.h).
#include "kernel/lib/protocol.h"

namespace lib {

namespace {

constexpr char CTRL_C = 0x03;

// The word check_upload_header reads the announced length from: scene's first, file's
// second-to-last (so that a name with a space in it still finds it), or its second where it has
// only two. nullptr: none.
const StrView* announcing_word(const StrView* args, size_t nargs, size_t name_args) {
    if (name_args == 0) return nargs ? &args[0] : nullptr;
    return nargs >= 3 ? &args[nargs - 2] : nargs == 2 ? &args[1] : nullptr;
}

}  // namespace

void LineAssembler::restart() {
    length_ = tail_length_ = 0;
    tail_[0] = 0;
    too_long_ = begun_ = false;
    control_ = 0;
    column_ = 0;
}

LineAssembler::Result LineAssembler::feed(char c) {
    if (finished_) {  // the last call ended a line: this byte starts the next
        restart();
        finished_ = false;
    }
    const bool lf_after_cr = after_cr_ && c == '\n';  // CR LF ends one line
    after_cr_ = c == '\r';
    if (lf_after_cr) return Result::More;
    if (c == CTRL_C) {
        restart();
        return Result::Cancelled;
    }
    if (c == '\r' || c == '\n') {
        finished_ = true;
        begun_ = false;
        line_[length_] = 0;
        if (too_long_) return Result::TooLong;
        for (size_t i = 0; i < length_; ++i)
            if (uint8_t(line_[i]) < 0x20 && line_[i] != '\t') {
                control_ = uint8_t(line_[i]);
                column_ = i + 1;
                return Result::Control;
            }
        return Result::Line;
    }
    begun_ = true;
    if (c == '\b' || c == 0x7F) {
        if (length_) --length_;
        if (tail_length_) tail_[--tail_length_] = 0;
        return Result::More;
    }
    if (length_ < MAX_LINE) line_[length_++] = c;
    else too_long_ = true;
    if (tail_length_ == TAIL) {
        for (size_t i = 1; i < TAIL; ++i) tail_[i - 1] = tail_[i];
        --tail_length_;
    }
    tail_[tail_length_++] = c;
    tail_[tail_length_] = 0;
    return Result::More;
}

size_t announced_length(StrView word) {
    uint32_t n;
    return parse_u32(word, &n) ? n : SIZE_MAX;
}

size_t announced_length(const StrView* word) { return word ? announced_length(*word) : SIZE_MAX; }

size_t refused_upload_bytes(const LineAssembler& lines, LineAssembler::Result refused) {
    constexpr size_t MAX_WORDS = LineAssembler::MAX_LINE / 2 + 1, MAX_TAIL_WORDS = LineAssembler::TAIL / 2 + 1;
    StrView words[MAX_WORDS];
    const size_t n = split_words(lines.line(), words, MAX_WORDS);
    if (n == 0 || (!words[0].equals("scene") && !words[0].equals("file"))) return 0;
    const size_t name_args = words[0].equals("scene") ? 0 : 1;
    if (refused != LineAssembler::Result::TooLong) return announced_length(announcing_word(words + 1, n - 1, name_args));
    // too long: the line's first characters may end inside a word, its last begin inside one
    if (name_args == 0) return announced_length(n >= 3 ? &words[1] : nullptr);
    StrView last[MAX_TAIL_WORDS];
    const size_t t = split_words(lines.tail(), last, MAX_TAIL_WORDS);
    return announced_length(t >= 3 && t <= MAX_TAIL_WORDS ? &last[t - 2] : nullptr);
}

HeaderProblem check_upload_header(const StrView* args, size_t nargs, size_t name_args, StrView fixed_name, size_t max_upload,
                                  size_t max_name, UploadHeader* header) {
    *header = UploadHeader{};
    header->announced = announced_length(announcing_word(args, nargs, name_args));
    if (nargs != name_args + 2) return HeaderProblem::Usage;
    header->name = name_args ? args[0] : fixed_name;
    const StrView bytes = args[name_args], crc = args[name_args + 1];
    if (!parse_u32(bytes, &header->length) || header->length == 0 || header->length > max_upload || !parse_u32(crc, &header->crc32))
        return HeaderProblem::LengthOrChecksum;
    if (header->name.size == 0 || header->name.size >= max_name) return HeaderProblem::Name;
    return HeaderProblem::None;
}

}  // namespace lib
