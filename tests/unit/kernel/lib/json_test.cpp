// Under test: kernel/lib/json.h.
// The kernel's JSON line writer, read back with nlohmann-json: structure, escaping, numbers.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "kernel/lib/json.h"

namespace {

struct Capture {
    std::string text;
    lib::Sink sink() {
        return {[](void* ctx, const char* d, size_t n) { static_cast<Capture*>(ctx)->text.append(d, n); }, this};
    }
};

TEST(JsonLine, WritesOneParsableLine) {
    Capture c;
    lib::JsonLine j(c.sink());
    j.u32("seq", 7).boolean("ok", true).str("cmd", "hello").i32("neg", -2147483647 - 1).u64("big", 18446744073709551615ull);
    j.hex32("eip", 0x00100164).begin_object("cpu").str("vendor", "GenuineIntel").begin_array("features");
    j.item_str("fpu").item_str("tsc").end_array().end_object().begin_array("n").item_u32(1).item_u32(2).end_array();
    j.end();
    ASSERT_EQ(c.text.back(), '\n');
    EXPECT_EQ(c.text.find('\n'), c.text.size() - 1) << "exactly one line";
    auto p = nlohmann::json::parse(c.text);
    EXPECT_EQ(p["seq"], 7);
    EXPECT_EQ(p["ok"], true);
    EXPECT_EQ(p["neg"], -2147483647 - 1);
    EXPECT_EQ(p["big"].get<uint64_t>(), 18446744073709551615ull);
    EXPECT_EQ(p["eip"], "0x00100164");
    EXPECT_EQ(p["cpu"]["features"], nlohmann::json({"fpu", "tsc"}));
    EXPECT_EQ(p["n"], nlohmann::json({1, 2}));
}

TEST(JsonLine, EscapesEveryAwkwardByte) {
    std::string nasty = "quote\" back\\slash\nnew\ttab\x01\x7f\xff end";
    Capture c;
    lib::JsonLine(c.sink()).str("s", nasty.c_str()).end();
    EXPECT_EQ(c.text.find('\n'), c.text.size() - 1) << "a newline inside a value would split the reply";
    auto p = nlohmann::json::parse(c.text);
    // bytes >= 0x7F are written as \u00XX, i.e. Latin-1 code points (0xFF comes back as U+00FF in UTF-8)
    EXPECT_EQ(p["s"], "quote\" back\\slash\nnew\ttab\x01\x7f\xc3\xbf end");
}

TEST(JsonLine, RawStringsStreamUnescaped) {
    Capture c;
    lib::JsonLine j(c.sink());
    j.str("encoding", "x").begin_raw_string("data");
    j.raw_sink().write("QUJD", 4);
    j.end_raw_string().u32("after", 1).end();
    auto p = nlohmann::json::parse(c.text);
    EXPECT_EQ(p["data"], "QUJD");
    EXPECT_EQ(p["after"], 1);
}

// Fixed-point decimals: rounded, without trailing zeros, read back as the numbers they say.
TEST(JsonLine, WritesFixedDecimals) {
    Capture c;
    lib::JsonLine j(c.sink());
    j.fixed("half", 0.5, 6).fixed("two", 2.0, 3).fixed("neg", -1.25, 2).fixed("round", 2.6849, 2).fixed("tiny", 0.0004, 3);
    j.fixed("minus_one", -1.0, 6).fixed("zero", -0.0001, 2).end();
    EXPECT_NE(c.text.find("\"half\":0.5,"), std::string::npos) << c.text;
    EXPECT_NE(c.text.find("\"two\":2,"), std::string::npos) << c.text;
    auto p = nlohmann::json::parse(c.text);
    EXPECT_DOUBLE_EQ(p["half"].get<double>(), 0.5);
    EXPECT_DOUBLE_EQ(p["two"].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(p["neg"].get<double>(), -1.25);
    EXPECT_DOUBLE_EQ(p["round"].get<double>(), 2.68);
    EXPECT_DOUBLE_EQ(p["tiny"].get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(p["minus_one"].get<double>(), -1.0);
    EXPECT_EQ(p["zero"].dump(), "0") << "no negative zero";
}

}  // namespace
