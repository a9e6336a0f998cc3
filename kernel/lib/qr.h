// QR codes (ISO/IEC 18004, Model 2) in byte mode at error correction level L or M: the on-screen
// bench's way to hand its CSV to a phone's camera without a cable. Our own encoder: Reed-Solomon
// over GF(256), the function patterns, the data's zigzag, the mask of least penalty. Portable and
// freestanding (no allocation: the caller keeps the QrCode, some 62 KB).
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace lib {

enum class QrLevel : uint8_t { L, M };  // about 7% and 15% of the codewords recoverable

struct QrCode {
    static constexpr int MAX_VERSION = 40;
    static constexpr int MAX_SIZE = 17 + 4 * MAX_VERSION;  // 177 modules a side
    int version = 0;  // 1..40; 0: nothing encoded
    int size = 0;     // 17 + 4 version modules a side (the quiet zone around it not included)
    int mask = -1;    // 0..7, the one of least penalty
    uint8_t dark[MAX_SIZE * MAX_SIZE];      // row-major, `size` a row: 1 where the module is dark
    uint8_t function[MAX_SIZE * MAX_SIZE];  // 1: a finder, timing, alignment, format or version module
    bool at(int x, int y) const { return dark[y * size + x] != 0; }
};

// The most bytes a version holds in byte mode at the level.
size_t qr_capacity(int version, QrLevel level);

// Encodes `length` bytes in the smallest version that holds them; false (and version 0) when even
// version 40 does not (qr_capacity(40, level): 2953 bytes at L, 2331 at M).
bool qr_encode(const uint8_t* data, size_t length, QrLevel level, QrCode* out);

}  // namespace lib
