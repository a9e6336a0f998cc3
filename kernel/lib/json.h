// A streaming writer of one JSON object per line (the command server's replies). Portable.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/lib/sink.h"
#include "kernel/lib/words.h"

namespace lib {

// Writes '{' on construction; end() writes "}\n". Keys are trusted literals; string values are escaped.
// Nesting (objects, arrays) is limited to MAX_DEPTH levels.
class JsonLine {
public:
    static constexpr int MAX_DEPTH = 8;

    explicit JsonLine(Sink out);

    JsonLine& str(const char* key, const char* value);
    JsonLine& str(const char* key, StrView value);
    JsonLine& u32(const char* key, uint32_t value);
    JsonLine& u64(const char* key, uint64_t value);
    JsonLine& i32(const char* key, int32_t value);
    // value rounded to `places` decimals (0..6, half away from zero; |value| < 2^53 / 10^places),
    // written without trailing zeros: 0.5, 2, -1.25
    JsonLine& fixed(const char* key, double value, int places);
    JsonLine& boolean(const char* key, bool value);
    JsonLine& hex32(const char* key, uint32_t value);  // as a string "0x0010002a"

    JsonLine& begin_object(const char* key);
    JsonLine& end_object();
    JsonLine& begin_array(const char* key);
    JsonLine& end_array();
    JsonLine& begin_item_object();                     // an object as an array element
    JsonLine& item_str(const char* value);             // an array element
    JsonLine& item_u32(uint32_t value);

    // A string value written in pieces (e.g. a long base64 payload): raw chars, not escaped.
    JsonLine& begin_raw_string(const char* key);
    Sink raw_sink() const { return out_; }
    JsonLine& end_raw_string();

    void end();

private:
    void key(const char* k);
    void separator();
    void escaped(const char* s, size_t n);
    void decimal(uint64_t v);

    Sink out_;
    bool first_[MAX_DEPTH + 1];
    int depth_ = 0;
};

}  // namespace lib
