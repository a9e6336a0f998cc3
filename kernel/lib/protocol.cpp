// The command server's front end: line assembly and upload headers (protocol.h).
#include "kernel/lib/protocol.h"

namespace lib {

LineAssembler::Result LineAssembler::feed(char c) {
    if (finished_) {  // the last call ended a line: this byte starts the next
        length_ = 0;
        too_long_ = false;
        control_ = 0;
        column_ = 0;
        finished_ = false;
    }
    const bool lf_after_cr = after_cr_ && c == '\n';  // CR LF ends one line
    after_cr_ = c == '\r';
    if (lf_after_cr) return Result::More;
    if (c == '\r' || c == '\n') {
        finished_ = true;
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
    if (c == '\b' || c == 0x7F) {
        if (length_) --length_;
    } else if (length_ < MAX_LINE) {
        line_[length_++] = c;
    } else {
        too_long_ = true;
    }
    return Result::More;
}

size_t announced_length(StrView word) {
    uint32_t n;
    if (parse_u32(word, &n)) return n;
    // digits all the same: a number too large for 32 bits
    const bool hex = word.size > 2 && word.data[0] == '0' && (word.data[1] == 'x' || word.data[1] == 'X');
    bool digits = word.size > (hex ? 2u : 0u);
    for (size_t i = hex ? 2 : 0; i < word.size && digits; ++i) {
        const char c = word.data[i];
        digits = (c >= '0' && c <= '9') || (hex && ((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')));
    }
    return digits ? SIZE_MAX : 0;
}

HeaderProblem check_upload_header(const StrView* args, size_t nargs, size_t name_args, StrView fixed_name, size_t max_upload,
                                  size_t max_name, UploadHeader* header) {
    *header = UploadHeader{};
    const StrView announced = name_args == 0 ? (nargs ? args[0] : StrView{}) : nargs >= 3 ? args[nargs - 2] : nargs == 2 ? args[1] : StrView{};
    header->announced = announced_length(announced);
    if (nargs != name_args + 2) return HeaderProblem::Usage;
    header->name = name_args ? args[0] : fixed_name;
    const StrView bytes = args[name_args], crc = args[name_args + 1];
    header->announced = announced_length(bytes);
    if (!parse_u32(bytes, &header->length) || header->length == 0 || header->length > max_upload || !parse_u32(crc, &header->crc32))
        return HeaderProblem::LengthOrChecksum;
    if (header->name.size == 0 || header->name.size >= max_name) return HeaderProblem::Name;
    return HeaderProblem::None;
}

}  // namespace lib
