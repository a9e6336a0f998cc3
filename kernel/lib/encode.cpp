// CRC-32, base64 and PackBits for the readback wire format.
#include "kernel/lib/encode.h"

namespace lib {

namespace {

struct Crc32Table {
    uint32_t entry[256];
};

constexpr Crc32Table make_crc32_table() {
    Crc32Table t{};
    for (uint32_t i = 0; i < 256; ++i) {
        uint32_t c = i;
        for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        t.entry[i] = c;
    }
    return t;
}

constexpr Crc32Table CRC32_TABLE = make_crc32_table();

constexpr char BASE64_ALPHABET[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

int base64_value(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

}  // namespace

uint32_t crc32(uint32_t crc, const uint8_t* data, size_t n) {
    crc = ~crc;
    for (size_t i = 0; i < n; ++i) crc = CRC32_TABLE.entry[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
    return ~crc;
}

void Base64Encoder::put(uint8_t byte) {
    group_ = (group_ << 8) | byte;
    if (++pending_ < 3) return;
    char quad[4] = {
        BASE64_ALPHABET[(group_ >> 18) & 63], BASE64_ALPHABET[(group_ >> 12) & 63],
        BASE64_ALPHABET[(group_ >> 6) & 63], BASE64_ALPHABET[group_ & 63],
    };
    out_.write(quad, 4);
    chars_ += 4;
    group_ = 0;
    pending_ = 0;
}

void Base64Encoder::finish() {
    if (pending_ == 0) return;
    uint32_t g = group_ << (8 * (3 - pending_));
    char quad[4] = {
        BASE64_ALPHABET[(g >> 18) & 63], BASE64_ALPHABET[(g >> 12) & 63],
        pending_ == 2 ? BASE64_ALPHABET[(g >> 6) & 63] : '=', '=',
    };
    out_.write(quad, 4);
    chars_ += 4;
    group_ = 0;
    pending_ = 0;
}

bool base64_decode(const char* in, size_t n, uint8_t* out, size_t capacity, size_t* produced) {
    *produced = 0;
    if (n % 4 != 0) return false;
    size_t o = 0;
    for (size_t i = 0; i < n; i += 4) {
        bool last = i + 4 == n;
        int v[4];
        int pad = 0;
        for (int k = 0; k < 4; ++k) {
            char c = in[i + k];
            if (c == '=' && last && k >= 2) {
                v[k] = 0;
                ++pad;
            } else {
                if (pad) return false;  // data after padding
                v[k] = base64_value(c);
                if (v[k] < 0) return false;
            }
        }
        uint32_t g = (uint32_t(v[0]) << 18) | (uint32_t(v[1]) << 12) | (uint32_t(v[2]) << 6) | uint32_t(v[3]);
        int bytes = 3 - pad;
        if (o + size_t(bytes) > capacity) return false;
        for (int k = 0; k < bytes; ++k) out[o++] = uint8_t(g >> (16 - 8 * k));
    }
    *produced = o;
    return true;
}

size_t packbits_encode(const uint8_t* in, size_t n, void (*put)(void* ctx, uint8_t byte), void* ctx) {
    size_t written = 0;
    size_t i = 0;
    while (i < n) {
        size_t run = 1;
        while (i + run < n && run < 128 && in[i + run] == in[i]) ++run;
        if (run >= 3) {
            put(ctx, uint8_t(257 - run));
            put(ctx, in[i]);
            written += 2;
            i += run;
            continue;
        }
        // literals up to the next run of 3 or the 128-byte limit
        size_t lit = 0;
        while (i + lit < n && lit < 128) {
            if (i + lit + 2 < n && in[i + lit] == in[i + lit + 1] && in[i + lit] == in[i + lit + 2]) break;
            ++lit;
        }
        put(ctx, uint8_t(lit - 1));
        for (size_t k = 0; k < lit; ++k) put(ctx, in[i + k]);
        written += 1 + lit;
        i += lit;
    }
    return written;
}

bool packbits_decode(const uint8_t* in, size_t n, uint8_t* out, size_t capacity, size_t* produced) {
    size_t o = 0;
    size_t i = 0;
    *produced = 0;
    while (i < n) {
        uint8_t h = in[i++];
        if (h < 128) {
            size_t lit = size_t(h) + 1;
            if (i + lit > n || o + lit > capacity) return false;
            for (size_t k = 0; k < lit; ++k) out[o++] = in[i++];
        } else if (h > 128) {
            size_t rep = 257 - size_t(h);
            if (i >= n || o + rep > capacity) return false;
            uint8_t v = in[i++];
            for (size_t k = 0; k < rep; ++k) out[o++] = v;
        } else {
            return false;
        }
    }
    *produced = o;
    return true;
}

}  // namespace lib
