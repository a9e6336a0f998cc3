// Under test: kernel/lib/encode.h.
// The readback wire format pieces: CRC-32, base64 and PackBits, against known vectors and round trips.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "kernel/lib/encode.h"

namespace {

std::string base64(const std::vector<uint8_t>& bytes) {
    std::string out;
    lib::Sink sink{[](void* ctx, const char* d, size_t n) { static_cast<std::string*>(ctx)->append(d, n); }, &out};
    lib::Base64Encoder enc(sink);
    for (uint8_t b : bytes) enc.put(b);
    enc.finish();
    EXPECT_EQ(enc.chars_written(), out.size());
    return out;
}

std::vector<uint8_t> packbits(const std::vector<uint8_t>& in) {
    std::vector<uint8_t> out;
    size_t n = lib::packbits_encode(in.data(), in.size(), [](void* ctx, uint8_t b) { static_cast<std::vector<uint8_t>*>(ctx)->push_back(b); }, &out);
    EXPECT_EQ(n, out.size());
    return out;
}

std::vector<uint8_t> bytes_of(const std::string& s) { return {s.begin(), s.end()}; }

TEST(Crc32, MatchesTheStandardCheckValue) {
    auto data = bytes_of("123456789");
    EXPECT_EQ(lib::crc32(0, data.data(), data.size()), 0xCBF43926u);
    EXPECT_EQ(lib::crc32(0, nullptr, 0), 0u);
}

TEST(Crc32, ContinuesAcrossPieces) {
    auto data = bytes_of("The quick brown fox jumps over the lazy dog");
    uint32_t whole = lib::crc32(0, data.data(), data.size());
    EXPECT_EQ(whole, 0x414FA339u);
    uint32_t part = lib::crc32(0, data.data(), 10);
    EXPECT_EQ(lib::crc32(part, data.data() + 10, data.size() - 10), whole);
}

TEST(Base64, Rfc4648Vectors) {
    const std::pair<const char*, const char*> vectors[] = {
        {"", ""}, {"f", "Zg=="}, {"fo", "Zm8="}, {"foo", "Zm9v"}, {"foob", "Zm9vYg=="}, {"fooba", "Zm9vYmE="}, {"foobar", "Zm9vYmFy"},
    };
    for (auto [plain, encoded] : vectors) {
        EXPECT_EQ(base64(bytes_of(plain)), encoded);
        std::vector<uint8_t> out(16);
        size_t n = 99;
        ASSERT_TRUE(lib::base64_decode(encoded, strlen(encoded), out.data(), out.size(), &n)) << encoded;
        EXPECT_EQ(std::string(out.begin(), out.begin() + long(n)), plain);
    }
}

TEST(Base64, RejectsMalformedInput) {
    std::vector<uint8_t> out(64);
    size_t n;
    for (const char* bad : {"Zg=", "Zg", "Z===", "Zm9v!A==", "Zg==Zg==", "Zm=v", "Zm9v\n"})
        EXPECT_FALSE(lib::base64_decode(bad, strlen(bad), out.data(), out.size(), &n)) << bad;
    EXPECT_FALSE(lib::base64_decode("Zm9vYmFy", 8, out.data(), 5, &n)) << "capacity exceeded";
}

TEST(PackBits, EncodesRunsAndLiterals) {
    // the classic Apple example
    std::vector<uint8_t> in = {0xAA, 0xAA, 0xAA, 0x80, 0x00, 0x2A, 0xAA, 0xAA, 0xAA, 0xAA, 0x80, 0x00, 0x2A, 0x22,
                               0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA};
    std::vector<uint8_t> want = {0xFE, 0xAA, 0x02, 0x80, 0x00, 0x2A, 0xFD, 0xAA, 0x03, 0x80, 0x00, 0x2A, 0x22, 0xF7, 0xAA};
    EXPECT_EQ(packbits(in), want);
}

TEST(PackBits, LongRunsSplitAt128) {
    std::vector<uint8_t> in(300, 7);
    std::vector<uint8_t> want = {0x81, 7, 0x81, 7, 0xD5, 7};  // 128 + 128 + 44
    EXPECT_EQ(packbits(in), want);
}

TEST(PackBits, RoundTripsRandomData) {
    std::mt19937 rng(1234);
    for (int trial = 0; trial < 500; ++trial) {
        size_t n = rng() % 2000;
        std::vector<uint8_t> in(n);
        int alphabet = 1 + int(rng() % 4 == 0 ? 256 : rng() % 4);  // some runs, some noise
        for (auto& b : in) b = uint8_t(rng() % unsigned(alphabet));
        auto packed = packbits(in);
        EXPECT_LE(packed.size(), n + (n + 127) / 128);  // worst case: one header per 128 literals
        std::vector<uint8_t> out(n);
        size_t produced = 0;
        ASSERT_TRUE(lib::packbits_decode(packed.data(), packed.size(), out.data(), out.size(), &produced));
        ASSERT_EQ(produced, n);
        EXPECT_EQ(out, in);
    }
}

TEST(PackBits, DecoderRejectsBadStreams) {
    std::vector<uint8_t> out(16);
    size_t n;
    const std::vector<std::vector<uint8_t>> bad = {
        {0x02, 1, 2},        // literal packet cut short
        {0xFE},              // repeat without its byte
        {0x80},              // 128 is never written
        {0xF0, 1},           // 17 bytes into a 16-byte buffer
    };
    for (const auto& b : bad) EXPECT_FALSE(lib::packbits_decode(b.data(), b.size(), out.data(), out.size(), &n));
}

}  // namespace
