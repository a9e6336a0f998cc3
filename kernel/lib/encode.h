// Readback encoding: CRC-32 of the raw bytes, PackBits run-length coding, base64. Portable.
// Wire format (docs/protocol.md): base64(packbits(indices)), crc32 over the unencoded indices.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "kernel/lib/sink.h"

namespace lib {

// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320, init and final xor 0xFFFFFFFF), as zlib's crc32.
// Pass the previous result as `crc` to continue over more data; start with 0.
uint32_t crc32(uint32_t crc, const uint8_t* data, size_t n);

// Base64 (RFC 4648 alphabet, '=' padding), streamed: bytes in, characters out to a Sink.
class Base64Encoder {
public:
    explicit Base64Encoder(Sink out) : out_(out) {}
    void put(uint8_t byte);
    void finish();  // flushes the last group with padding
    size_t chars_written() const { return chars_; }

private:
    Sink out_;
    uint32_t group_ = 0;
    int pending_ = 0;
    size_t chars_ = 0;
};

// Decodes base64 (padding required, no whitespace) into out; false on a bad character,
// bad length or padding, or when the result would exceed `capacity`.
bool base64_decode(const char* in, size_t n, uint8_t* out, size_t capacity, size_t* produced);

// PackBits (Apple/TIFF): header h in 0..127 means h+1 literal bytes follow; h in 129..255 means
// the next byte repeats 257-h times; 128 is never written. Runs of 3 or more become repeats.
// Each packet byte goes to `put(ctx, byte)`; returns the number of encoded bytes.
size_t packbits_encode(const uint8_t* in, size_t n, void (*put)(void* ctx, uint8_t byte), void* ctx);

// Strict decoder: false on a truncated packet, a 128 header, or output beyond `capacity`.
bool packbits_decode(const uint8_t* in, size_t n, uint8_t* out, size_t capacity, size_t* produced);

}  // namespace lib
