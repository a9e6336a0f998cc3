// Under test: kernel/lib/words.h.
// Command-line words: splitting and number parsing as the command server uses them.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "kernel/core/mapper.h"
#include "kernel/lib/fmt.h"
#include "kernel/lib/protocol.h"
#include "kernel/lib/words.h"

namespace {

std::string str(lib::StrView v) { return std::string(v.data, v.size); }

TEST(Words, SplitsOnBlanks) {
    lib::StrView w[4];
    ASSERT_EQ(lib::split_words("  pattern\tramp  2 ", w, 4), 3u);
    EXPECT_EQ(str(w[0]), "pattern");
    EXPECT_EQ(str(w[1]), "ramp");
    EXPECT_EQ(str(w[2]), "2");
    EXPECT_EQ(lib::split_words("", w, 4), 0u);
    EXPECT_EQ(lib::split_words(" \t ", w, 4), 0u);
}

TEST(Words, CountsWordsBeyondTheLimit) {
    lib::StrView w[2];
    EXPECT_EQ(lib::split_words("a b c d e", w, 2), 5u);
    EXPECT_EQ(str(w[1]), "b");
}

TEST(Words, ParsesDecimalAndHex) {
    uint32_t v = 0;
    auto parse = [&](const char* s) { return lib::parse_u32(lib::StrView{s, strlen(s)}, &v); };
    EXPECT_TRUE(parse("0")); EXPECT_EQ(v, 0u);
    EXPECT_TRUE(parse("4294967295")); EXPECT_EQ(v, 4294967295u);
    EXPECT_TRUE(parse("0x4B00")); EXPECT_EQ(v, 0x4B00u);
    EXPECT_TRUE(parse("0xffffffff")); EXPECT_EQ(v, 0xFFFFFFFFu);
    for (const char* bad : {"", "-1", "4294967296", "0x100000000", "12a", "0x", "0xg", "1 "}) EXPECT_FALSE(parse(bad)) << bad;
}

TEST(Words, ViewHelpers) {
    const char* s = "interval=250";
    lib::StrView v{s, strlen(s)};
    EXPECT_TRUE(v.starts_with("interval="));
    EXPECT_FALSE(v.starts_with("interval=2500"));
    EXPECT_EQ(str(v.drop(9)), "250");
    EXPECT_TRUE(v.drop(99).empty());
    EXPECT_TRUE(v.equals("interval=250"));
    EXPECT_FALSE(v.equals("interval=25"));
}

TEST(Words, CopyCStringCutsAndTerminates) {
    char buf[6];
    std::memset(buf, 'x', sizeof buf);
    lib::copy_c_string(buf, sizeof buf, "corridor");
    EXPECT_STREQ(buf, "corri") << "five characters and the NUL";
    lib::copy_c_string(buf, sizeof buf, "ball");
    EXPECT_STREQ(buf, "ball");
    lib::copy_c_string(buf, 1, "ball");
    EXPECT_STREQ(buf, "");
}

TEST(Fmt, FormatsAndTruncates) {
    lib::Fmt f;
    f.s("page ").u(4294967295u).s(" at ").hex(0x4B00);
    EXPECT_STREQ(f.c_str(), "page 4294967295 at 0x00004b00");
    EXPECT_FALSE(f.cut());
    lib::Fmt full;  // exactly full: nothing dropped
    for (size_t i = 0; i < lib::Fmt::CAPACITY; ++i) full.s("x");
    EXPECT_FALSE(full.cut());
    EXPECT_EQ(strlen(full.c_str()), lib::Fmt::CAPACITY);
    lib::Fmt big;  // one more: the end says it was cut
    for (size_t i = 0; i <= lib::Fmt::CAPACITY; ++i) big.s("x");
    EXPECT_TRUE(big.cut());
    EXPECT_EQ(strlen(big.c_str()), lib::Fmt::CAPACITY);
    EXPECT_EQ(std::string(big.c_str()).substr(lib::Fmt::CAPACITY - strlen(lib::Fmt::CUT)), lib::Fmt::CUT);
}

// The longest error the kernel's server builds from a list, an unknown mapper's (every mapper
// named), fits with a name as long as a command line can be.
TEST(Fmt, HoldsTheWholeMapperList) {
    size_t list = std::strlen("unknown mapper '") + lib::LineAssembler::MAX_LINE + std::strlen("' (mappers: ") + std::strlen(")");
    for (int i = 0; i < raster::MAPPER_COUNT; ++i) list += std::strlen(raster::MAPPERS[i].name) + (i ? 2 : 0);
    EXPECT_LE(list, lib::Fmt::CAPACITY);
}

TEST(Fmt, TenthsAndDecimals) {
    lib::Fmt t;
    t.tenths(0).s(" ").tenths(7).s(" ").tenths(123).s(" ").tenths(50000000000ull);
    EXPECT_STREQ(t.c_str(), "0.0 0.7 12.3 5000000000.0");
    lib::Fmt d;
    for (double v : {0.0, 0.5, 1.0, 2.25, 0.808, 9.999, 10.0, 127.6, -1.0}) d.decimal(v).s(" ");
    EXPECT_STREQ(d.c_str(), "0 0.5 1 2.25 0.81 10 10 128 ? ");
}

}  // namespace
