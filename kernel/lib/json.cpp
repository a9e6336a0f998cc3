// JSON line writer: comma bookkeeping per nesting level, string escaping, numbers without libc.
#include "kernel/lib/json.h"

#include "kernel/lib/fmt.h"

namespace lib {

JsonLine::JsonLine(Sink out) : out_(out) {
    first_[0] = true;
    out_.put('{');
}

void JsonLine::separator() {
    if (!first_[depth_]) out_.put(',');
    first_[depth_] = false;
}

void JsonLine::key(const char* k) {
    separator();
    out_.put('"');
    out_.write(k, c_length(k));
    out_.write("\":", 2);
}

void JsonLine::escaped(const char* s, size_t n) {
    static constexpr char HEX[] = "0123456789abcdef";
    out_.put('"');
    for (size_t i = 0; i < n; ++i) {
        auto c = static_cast<unsigned char>(s[i]);
        if (c == '"' || c == '\\') {
            char pair[2] = {'\\', char(c)};
            out_.write(pair, 2);
        } else if (c < 0x20 || c >= 0x7F) {
            char esc[6] = {'\\', 'u', '0', '0', HEX[c >> 4], HEX[c & 15]};
            out_.write(esc, 6);
        } else {
            out_.put(char(c));
        }
    }
    out_.put('"');
}

void JsonLine::decimal(uint64_t v) {
    char digits[DECIMAL_MAX_CHARS];
    out_.write(digits, format_decimal(v, digits));
}

JsonLine& JsonLine::str(const char* k, const char* value) {
    key(k);
    escaped(value, c_length(value));
    return *this;
}

JsonLine& JsonLine::str(const char* k, StrView value) {
    key(k);
    escaped(value.data, value.size);
    return *this;
}

JsonLine& JsonLine::u32(const char* k, uint32_t value) { return u64(k, value); }

JsonLine& JsonLine::u64(const char* k, uint64_t value) {
    key(k);
    decimal(value);
    return *this;
}

JsonLine& JsonLine::i32(const char* k, int32_t value) {
    key(k);
    if (value < 0) out_.put('-');
    decimal(value < 0 ? uint64_t(-int64_t(value)) : uint64_t(value));
    return *this;
}

JsonLine& JsonLine::fixed(const char* k, double value, int places) {
    key(k);
    uint64_t scale = 1;
    for (int i = 0; i < places; ++i) scale *= 10;
    bool negative = value < 0;
    double scaled = (negative ? -value : value) * double(scale) + 0.5;
    uint64_t units = uint64_t(scaled);
    while (places > 0 && units % 10 == 0) units /= 10, scale /= 10, --places;  // no trailing zeros
    if (negative && units) out_.put('-');
    decimal(units / scale);
    if (places > 0) {
        out_.put('.');
        for (uint64_t digit = scale / 10; digit; digit /= 10) out_.put(char('0' + (units / digit) % 10));
    }
    return *this;
}

JsonLine& JsonLine::boolean(const char* k, bool value) {
    key(k);
    if (value) out_.write("true", 4);
    else out_.write("false", 5);
    return *this;
}

JsonLine& JsonLine::hex32(const char* k, uint32_t value) {
    key(k);
    char text[HEX32_CHARS + 2] = {'"'};
    format_hex32(value, text + 1);
    text[HEX32_CHARS + 1] = '"';
    out_.write(text, sizeof text);
    return *this;
}

JsonLine& JsonLine::begin_object(const char* k) {
    key(k);
    out_.put('{');
    if (depth_ < MAX_DEPTH) first_[++depth_] = true;
    return *this;
}

JsonLine& JsonLine::end_object() {
    out_.put('}');
    if (depth_ > 0) --depth_;
    return *this;
}

JsonLine& JsonLine::begin_array(const char* k) {
    key(k);
    out_.put('[');
    if (depth_ < MAX_DEPTH) first_[++depth_] = true;
    return *this;
}

JsonLine& JsonLine::end_array() {
    out_.put(']');
    if (depth_ > 0) --depth_;
    return *this;
}

JsonLine& JsonLine::begin_item_object() {
    separator();
    out_.put('{');
    if (depth_ < MAX_DEPTH) first_[++depth_] = true;
    return *this;
}

JsonLine& JsonLine::item_str(const char* value) {
    separator();
    escaped(value, c_length(value));
    return *this;
}

JsonLine& JsonLine::item_u32(uint32_t value) {
    separator();
    decimal(value);
    return *this;
}

JsonLine& JsonLine::begin_raw_string(const char* k) {
    key(k);
    out_.put('"');
    return *this;
}

JsonLine& JsonLine::end_raw_string() {
    out_.put('"');
    return *this;
}

void JsonLine::end() { out_.write("}\n", 2); }

}  // namespace lib
