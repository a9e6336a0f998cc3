// The QR encoder (qr.h).
#include "kernel/lib/qr.h"

namespace lib {

namespace {

// From the standard's tables (ISO/IEC 18004, table 9): error correction codewords a block and the
// number of blocks, by version (index 0 unused), for levels L and M.
constexpr uint8_t ECC_PER_BLOCK[2][41] = {
    {0, 7, 10, 15, 20, 26, 18, 20, 24, 30, 18, 20, 24, 26, 30, 22, 24, 28, 30, 28, 28,
     28, 28, 30, 30, 26, 28, 30, 30, 30, 30, 30, 30, 30, 30, 30, 30, 30, 30, 30, 30},
    {0, 10, 16, 26, 18, 24, 16, 18, 22, 22, 26, 30, 22, 22, 24, 24, 28, 28, 26, 26, 26,
     26, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28},
};
constexpr uint8_t BLOCKS[2][41] = {
    {0, 1, 1, 1, 1, 1, 2, 2, 2, 2, 4, 4, 4, 4, 4, 6, 6, 6, 6, 7, 8,
     8, 9, 9, 10, 12, 12, 12, 13, 14, 15, 16, 17, 18, 19, 19, 20, 21, 22, 24, 25},
    {0, 1, 1, 1, 2, 2, 4, 4, 4, 5, 5, 5, 8, 9, 9, 10, 10, 11, 13, 14, 16,
     17, 17, 18, 20, 21, 23, 25, 26, 28, 29, 31, 33, 35, 37, 38, 40, 43, 45, 47, 49},
};
constexpr int MAX_CODEWORDS = 3706;  // version 40's
constexpr int MAX_ECC = 30, MAX_BLOCKS = 49;  // (the tables' largest)

// Modules left for data and error correction once the function patterns are placed.
int raw_modules(int v) {
    int n = (16 * v + 128) * v + 64;  // all minus the finders, separators, timing and format areas
    if (v >= 2) {
        const int align = v / 7 + 2;  // alignment patterns a side
        n -= (25 * align - 10) * align - 55;
        if (v >= 7) n -= 36;  // the two version blocks
    }
    return n;
}

int data_codewords(int v, QrLevel level) {
    const int l = int(level);
    return raw_modules(v) / 8 - ECC_PER_BLOCK[l][v] * BLOCKS[l][v];
}

// GF(256) with the QR code's polynomial x^8 + x^4 + x^3 + x^2 + 1.
uint8_t gf_mul(uint8_t a, uint8_t b) {
    uint32_t r = 0;
    for (int i = 7; i >= 0; --i) {
        r = (r << 1) ^ ((r >> 7) * 0x11D);
        r ^= ((b >> i) & 1) * a;
    }
    return uint8_t(r);
}

// The generator polynomial's coefficients (highest first, the leading 1 left out) of degree n:
// the product of (x - 2^i), i = 0..n-1.
void rs_generator(int n, uint8_t* g) {
    for (int i = 0; i < n; ++i) g[i] = 0;
    g[n - 1] = 1;
    uint8_t root = 1;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            g[j] = gf_mul(g[j], root);
            if (j + 1 < n) g[j] ^= g[j + 1];
        }
        root = gf_mul(root, 2);
    }
}

// The remainder of data(x) x^n divided by the generator: the block's error correction codewords.
void rs_remainder(const uint8_t* data, int length, const uint8_t* g, int n, uint8_t* out) {
    for (int i = 0; i < n; ++i) out[i] = 0;
    for (int k = 0; k < length; ++k) {
        const uint8_t factor = data[k] ^ out[0];
        for (int i = 0; i + 1 < n; ++i) out[i] = out[i + 1];
        out[n - 1] = 0;
        for (int i = 0; i < n; ++i) out[i] ^= gf_mul(g[i], factor);
    }
}

struct Bits {
    uint8_t* bytes;
    int count = 0;  // bits written
    void put(uint32_t value, int n) {
        for (int i = n - 1; i >= 0; --i, ++count) {
            if ((count & 7) == 0) bytes[count >> 3] = 0;
            bytes[count >> 3] = uint8_t(bytes[count >> 3] | (((value >> i) & 1) << (7 - (count & 7))));
        }
    }
};

class Grid {
public:
    explicit Grid(QrCode* q) : q_(q) {}
    void set(int x, int y, bool dark) { q_->dark[y * q_->size + x] = dark; }
    void fixed(int x, int y, bool dark) {
        set(x, y, dark);
        q_->function[y * q_->size + x] = 1;
    }
    bool dark(int x, int y) const { return q_->dark[y * q_->size + x]; }
    bool function(int x, int y) const { return q_->function[y * q_->size + x]; }
    int size() const { return q_->size; }

private:
    QrCode* q_;
};

int chebyshev(int dx, int dy) {
    dx = dx < 0 ? -dx : dx, dy = dy < 0 ? -dy : dy;
    return dx > dy ? dx : dy;
}

// Finders (with their light separators), timing, alignment patterns, the dark module, the version
// blocks; the format areas reserved (written per mask).
void draw_function_patterns(Grid& g, int version) {
    const int n = g.size();
    for (int i = 0; i < n; ++i) g.fixed(6, i, i % 2 == 0), g.fixed(i, 6, i % 2 == 0);
    const int centres[3][2] = {{3, 3}, {n - 4, 3}, {3, n - 4}};
    for (const auto& c : centres)
        for (int dy = -4; dy <= 4; ++dy)
            for (int dx = -4; dx <= 4; ++dx) {
                const int x = c[0] + dx, y = c[1] + dy, d = chebyshev(dx, dy);
                if (x >= 0 && x < n && y >= 0 && y < n) g.fixed(x, y, d != 2 && d != 4);
            }
    if (version >= 2) {
        const int count = version / 7 + 2;
        const int step = (version * 8 + count * 3 + 5) / (count * 4 - 4) * 2;
        int at[7];
        at[0] = 6;
        for (int i = count - 1, p = n - 7; i >= 1; --i, p -= step) at[i] = p;
        for (int i = 0; i < count; ++i)
            for (int j = 0; j < count; ++j) {
                if ((i == 0 && j == 0) || (i == 0 && j == count - 1) || (i == count - 1 && j == 0)) continue;  // the finders'
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) g.fixed(at[i] + dx, at[j] + dy, chebyshev(dx, dy) != 1);
            }
    }
    if (version >= 7) {
        uint32_t rem = uint32_t(version);
        for (int i = 0; i < 12; ++i) rem = (rem << 1) ^ ((rem >> 11) * 0x1F25);
        const uint32_t bits = uint32_t(version) << 12 | rem;
        for (int i = 0; i < 18; ++i) {
            const bool b = (bits >> i) & 1;
            const int a = n - 11 + i % 3, c = i / 3;
            g.fixed(a, c, b), g.fixed(c, a, b);
        }
    }
}

void draw_format(Grid& g, QrLevel level, int mask) {
    const uint32_t data = (level == QrLevel::L ? 1u : 0u) << 3 | uint32_t(mask);
    uint32_t rem = data;
    for (int i = 0; i < 10; ++i) rem = (rem << 1) ^ ((rem >> 9) * 0x537);
    const uint32_t bits = (data << 10 | rem) ^ 0x5412;
    auto bit = [&](int i) { return ((bits >> i) & 1) != 0; };
    const int n = g.size();
    for (int i = 0; i <= 5; ++i) g.fixed(8, i, bit(i));
    g.fixed(8, 7, bit(6)), g.fixed(8, 8, bit(7)), g.fixed(7, 8, bit(8));
    for (int i = 9; i < 15; ++i) g.fixed(14 - i, 8, bit(i));
    for (int i = 0; i < 8; ++i) g.fixed(n - 1 - i, 8, bit(i));
    for (int i = 8; i < 15; ++i) g.fixed(8, n - 15 + i, bit(i));
    g.fixed(8, n - 8, true);  // the dark module
}

// The codewords in the zigzag: column pairs from the right, up then down, skipping column 6.
void draw_codewords(Grid& g, const uint8_t* codewords, int count) {
    const int n = g.size();
    int i = 0;
    for (int right = n - 1; right >= 1; right -= 2) {
        if (right == 6) right = 5;
        const bool upward = ((right + 1) & 2) == 0;
        for (int v = 0; v < n; ++v)
            for (int j = 0; j < 2; ++j) {
                const int x = right - j, y = upward ? n - 1 - v : v;
                if (g.function(x, y)) continue;
                g.set(x, y, i < count * 8 && ((codewords[i >> 3] >> (7 - (i & 7))) & 1));  // (remainder bits: light)
                ++i;
            }
    }
}

bool masked(int mask, int x, int y) {
    switch (mask) {
    case 0: return (x + y) % 2 == 0;
    case 1: return y % 2 == 0;
    case 2: return x % 3 == 0;
    case 3: return (x + y) % 3 == 0;
    case 4: return (x / 3 + y / 2) % 2 == 0;
    case 5: return x * y % 2 + x * y % 3 == 0;
    case 6: return (x * y % 2 + x * y % 3) % 2 == 0;
    default: return ((x + y) % 2 + x * y % 3) % 2 == 0;
    }
}

void apply_mask(Grid& g, int mask) {
    for (int y = 0; y < g.size(); ++y)
        for (int x = 0; x < g.size(); ++x)
            if (!g.function(x, y) && masked(mask, x, y)) g.set(x, y, !g.dark(x, y));
}

// The standard's penalty (section 7.8.3): runs of five or more, 2x2 blocks, finder-like patterns
// with four light modules on a side, and the dark share's distance from half.
long penalty(const Grid& g) {
    const int n = g.size();
    long score = 0;
    for (int pass = 0; pass < 2; ++pass)  // rows, then columns
        for (int a = 0; a < n; ++a) {
            auto at = [&](int b) { return b < 0 || b >= n ? false : pass ? g.dark(a, b) : g.dark(b, a); };
            int run = 1;
            for (int b = 1; b <= n; ++b) {
                if (b < n && at(b) == at(b - 1)) {
                    ++run;
                    continue;
                }
                if (run >= 5) score += 3 + (run - 5);
                run = 1;
            }
            static constexpr bool FINDER[7] = {true, false, true, true, true, false, true};
            for (int b = 0; b + 7 <= n; ++b) {
                bool like = true;
                for (int k = 0; k < 7 && like; ++k) like = at(b + k) == FINDER[k];
                if (!like) continue;
                bool before = true, after = true;
                for (int k = 1; k <= 4; ++k) before = before && !at(b - k), after = after && !at(b + 6 + k);
                score += 40 * ((before ? 1 : 0) + (after ? 1 : 0));
            }
        }
    long dark = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            dark += g.dark(x, y);
            if (x + 1 < n && y + 1 < n && g.dark(x, y) == g.dark(x + 1, y) && g.dark(x, y) == g.dark(x, y + 1) && g.dark(x, y) == g.dark(x + 1, y + 1))
                score += 3;
        }
    const long total = long(n) * n, off = dark * 20 - total * 10;
    score += 10 * (((off < 0 ? -off : off) + total - 1) / total - 1);
    return score;
}

}  // namespace

size_t qr_capacity(int version, QrLevel level) {
    if (version < 1 || version > QrCode::MAX_VERSION) return 0;
    const int bits = data_codewords(version, level) * 8 - 4 - (version < 10 ? 8 : 16);
    return size_t(bits / 8);
}

bool qr_encode(const uint8_t* data, size_t length, QrLevel level, QrCode* out) {
    out->version = 0, out->size = 0, out->mask = -1;
    int v = 1;
    while (v <= QrCode::MAX_VERSION && qr_capacity(v, level) < length) ++v;
    if (v > QrCode::MAX_VERSION) return false;
    // the data codewords: mode, count, bytes, terminator, padding
    uint8_t stream[MAX_CODEWORDS], codewords[MAX_CODEWORDS];
    const int capacity = data_codewords(v, level);
    Bits b{stream};
    b.put(0x4, 4);
    b.put(uint32_t(length), v < 10 ? 8 : 16);
    for (size_t i = 0; i < length; ++i) b.put(data[i], 8);
    const int room = capacity * 8 - b.count;
    b.put(0, room < 4 ? room : 4);
    b.put(0, (8 - b.count % 8) % 8);
    for (uint32_t pad = 0xEC; b.count < capacity * 8; pad ^= 0xEC ^ 0x11) b.put(pad, 8);
    // the blocks, their error correction, interleaved
    const int l = int(level), blocks = BLOCKS[l][v], ecc = ECC_PER_BLOCK[l][v];
    const int total = raw_modules(v) / 8, short_blocks = blocks - total % blocks, short_data = total / blocks - ecc;
    uint8_t generator[MAX_ECC], remainders[MAX_BLOCKS][MAX_ECC];
    rs_generator(ecc, generator);
    int start[MAX_BLOCKS + 1];
    start[0] = 0;
    for (int k = 0; k < blocks; ++k) {
        const int len = short_data + (k < short_blocks ? 0 : 1);
        start[k + 1] = start[k] + len;
        rs_remainder(stream + start[k], len, generator, ecc, remainders[k]);
    }
    int at = 0;
    for (int i = 0; i <= short_data; ++i)
        for (int k = 0; k < blocks; ++k)
            if (i < start[k + 1] - start[k]) codewords[at++] = stream[start[k] + i];
    for (int i = 0; i < ecc; ++i)
        for (int k = 0; k < blocks; ++k) codewords[at++] = remainders[k][i];
    // the symbol: function patterns, codewords, then each mask tried and the least penalty kept
    out->version = v, out->size = 17 + 4 * v;
    for (int i = 0; i < out->size * out->size; ++i) out->dark[i] = 0, out->function[i] = 0;
    Grid g(out);
    draw_function_patterns(g, v);
    draw_format(g, level, 0);  // (reserves the format areas)
    draw_codewords(g, codewords, at);
    long best = -1;
    for (int mask = 0; mask < 8; ++mask) {
        apply_mask(g, mask);
        draw_format(g, level, mask);
        const long p = penalty(g);
        if (best < 0 || p < best) best = p, out->mask = mask;
        apply_mask(g, mask);  // (its own inverse)
    }
    apply_mask(g, out->mask);
    draw_format(g, level, out->mask);
    return true;
}

}  // namespace lib
