// Under test: qemu/lib/command_line.h.
// The host tools' one argument parser: how words become options, flags and positionals, what each
// getter accepts, and the messages and exit statuses of run_cli.
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>

#include "qemu/lib/command_line.h"
#include "qemu/lib/error.h"
#include "kernel/version.h"

namespace {

using namespace harness;

const std::vector<std::string_view> WITH_VALUE = {"--out", "--frames", "--axis", "--module", "--mapper", "--list"};
const std::vector<std::string_view> FLAGS = {"--compare", "--full"};

CommandLine parse(const std::vector<std::string>& words) { return parse_command_line(words, WITH_VALUE, FLAGS); }

// The message of the UsageError that f throws, or a note that it threw none.
std::string usage_error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const UsageError& e) {
        return e.what();
    }
    return "(no UsageError)";
}

enum class Walk { Rows, Columns, Diagonal };

Walk walk_of(const CommandLine& c) {
    return c.choice<Walk>("--axis", {{"rows", Walk::Rows}, {"columns", Walk::Columns}}, Walk::Diagonal);
}

TEST(Args, SortsValuesFlagsAndPositionals) {
    CommandLine c = parse({"scene.txt", "--out", "x.png", "--compare", "more", "-x"});
    EXPECT_EQ(c.positionals(), (std::vector<std::string>{"scene.txt", "more", "-x"})) << "a single dash is a positional";
    EXPECT_EQ(c.text("--out"), "x.png");
    EXPECT_TRUE(c.has("--out"));
    EXPECT_TRUE(c.has("--compare"));
    EXPECT_FALSE(c.has("--full"));
    EXPECT_FALSE(c.has("--frames"));
    EXPECT_EQ(c.text("--frames"), "");
    EXPECT_EQ(c.text("--frames", "default"), "default");
    EXPECT_TRUE(c.texts("--module").empty());
    EXPECT_FALSE(c.help());
}

TEST(Args, AValueIsTheNextWordWhateverItLooksLike) {
    CommandLine c = parse({"--out", "--compare", "--module", "", "--frames", "-3"});
    EXPECT_EQ(c.text("--out"), "--compare");
    EXPECT_FALSE(c.has("--compare"));
    EXPECT_TRUE(c.has("--module")) << "an empty value is still given";
    EXPECT_EQ(c.text("--module", "fallback"), "");
    EXPECT_TRUE(c.positionals().empty());
}

TEST(Args, NothingGivenIsNothing) {
    CommandLine c = parse({});
    EXPECT_TRUE(c.positionals().empty());
    EXPECT_FALSE(c.has("--out"));
    EXPECT_FALSE(c.help());
}

TEST(Args, RefusesAnUnknownOption) {
    EXPECT_EQ(usage_error_of([] { parse({"a", "--bogus", "b"}); }), "unknown option --bogus");
    EXPECT_EQ(usage_error_of([] { parse({"--outx", "y"}); }), "unknown option --outx") << "no prefixes";
    EXPECT_EQ(usage_error_of([] { parse({"--outx=y"}); }), "unknown option --outx") << "no prefixes in --name=value";
    EXPECT_EQ(usage_error_of([] { parse_command_line({"--out", "x"}, {}, {}); }), "unknown option --out");
}

TEST(Args, RefusesAnOptionWithoutItsValue) {
    EXPECT_EQ(usage_error_of([] { parse({"a", "--out"}); }), "--out needs a value");
    EXPECT_EQ(usage_error_of([] { parse({"--compare", "--frames"}); }), "--frames needs a value");
}

TEST(Args, HelpStopsTheParse) {
    for (const char* help : {"-h", "--help"}) {
        CommandLine c = parse({"--out", "x", help, "--bogus", "--frames"});
        EXPECT_TRUE(c.help()) << help;
        EXPECT_EQ(c.text("--out"), "x");
    }
    EXPECT_EQ(usage_error_of([] { parse({"--bogus", "--help"}); }), "unknown option --bogus") << "what comes first counts";
    EXPECT_FALSE(parse({"--out", "--help"}).help()) << "a value, not a request for help";
}

TEST(Args, ARepeatedOptionCountsWithItsLastValueOrAllOfThem) {
    CommandLine c = parse({"--out", "a", "--module", "m1", "--out", "b", "--compare", "--module", "m2=x", "--compare"});
    EXPECT_EQ(c.text("--out"), "b");
    EXPECT_EQ(c.texts("--out"), (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(c.texts("--module"), (std::vector<std::string>{"m1", "m2=x"}));
    EXPECT_TRUE(c.has("--compare"));
    EXPECT_EQ(parse({"--frames", "x", "--frames", "7"}).integer("--frames", 1, 10, 5), 7) << "only the last value is read";
}

TEST(Args, AListIsItsCommaSeparatedItems) {
    EXPECT_EQ(parse({"--out", "a,b,,c,"}).list("--out"), (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_EQ(parse({"--out", ",x"}).list("--out"), (std::vector<std::string>{"x"}));
    EXPECT_TRUE(parse({"--out", ""}).list("--out").empty());
    EXPECT_TRUE(parse({}).list("--out").empty());
}

TEST(Args, IntegersInRange) {
    EXPECT_EQ(parse({"--frames", "12"}).integer("--frames", 1, 1000, 8), 12);
    EXPECT_EQ(parse({"--frames", "1"}).integer("--frames", 1, 1000, 8), 1);
    EXPECT_EQ(parse({"--frames", "1000"}).integer("--frames", 1, 1000, 8), 1000);
    EXPECT_EQ(parse({"--frames", "-4"}).integer("--frames", -5, 5, 0), -4);
    EXPECT_EQ(parse({}).integer("--frames", 1, 1000, 8), 8) << "absent: the fallback, even outside the range";
    EXPECT_EQ(parse({}).integer("--frames", 1, 1000, 0), 0);
    for (const char* bad : {"0", "1001", "-1", "12abc", "abc", "", " 12", "+12", "1.5", "99999999999999999999"}) {
        CommandLine c = parse({"--frames", bad});
        EXPECT_EQ(usage_error_of([&] { c.integer("--frames", 1, 1000, 8); }), "--frames takes 1..1000") << "'" << bad << "'";
    }
}

TEST(Args, AChoiceFromAList) {
    EXPECT_EQ(walk_of(parse({"--axis", "rows"})), Walk::Rows);
    EXPECT_EQ(walk_of(parse({"--axis", "columns"})), Walk::Columns);
    EXPECT_EQ(walk_of(parse({})), Walk::Diagonal) << "absent: the fallback";
    for (const char* bad : {"diagonal", "Rows", "row", ""}) {
        CommandLine c = parse({"--axis", bad});
        EXPECT_EQ(usage_error_of([&] { walk_of(c); }), "--axis takes rows or columns") << "'" << bad << "'";
    }
    CommandLine c = parse({"--out", "png"});
    EXPECT_EQ(usage_error_of([&] { c.choice<int>("--out", {{"bmp", 1}, {"pcx", 2}, {"ppm", 3}}, 0); }), "--out takes bmp, pcx or ppm");
}

TEST(Args, NamesTheAllowedValues) {
    EXPECT_EQ(CommandLine::one_of({}), "");
    EXPECT_EQ(CommandLine::one_of({"a"}), "a");
    EXPECT_EQ(CommandLine::one_of({"a", "b"}), "a or b");
    EXPECT_EQ(CommandLine::one_of({"a", "b", "c", "d"}), "a, b, c or d");
}

TEST(Args, AGetterForAnOptionNotDeclaredIsABug) {
    CommandLine c = parse({"x"});
    EXPECT_THROW(c.has("--outt"), std::logic_error);
    EXPECT_THROW(c.text("--outt"), std::logic_error);
    EXPECT_THROW(c.texts("--outt"), std::logic_error);
    EXPECT_THROW(c.integer("--outt", 0, 1, 0), std::logic_error);
}

TEST(Args, RunCliTurnsErrorsIntoStatusesAndMessages) {
    const char* usage = "usage: tool FILE\n";
    const std::string every = "-h, --help: this text; --version: the version; an option's value may follow it after '='\n";
    char program[] = "tool", file[] = "x.scene";
    char* argv[] = {program, file, nullptr};
    testing::internal::CaptureStderr();
    int status = run_cli("tool", usage, 2, argv, [](const std::vector<std::string>&) -> int { throw UsageError("no FILE"); });
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "tool: no FILE\nusage: tool FILE\n" + every);
    EXPECT_EQ(status, 2);

    testing::internal::CaptureStderr();
    status = run_cli("tool", usage, 2, argv, [](const std::vector<std::string>&) -> int { throw HarnessError("x.scene:3: bad"); });
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "tool: x.scene:3: bad\n") << "a failure, not a usage error: no usage";
    EXPECT_EQ(status, 1);

    testing::internal::CaptureStderr();
    std::vector<std::string> given;
    status = run_cli("tool", usage, 2, argv, [&](const std::vector<std::string>& words) {
        given = words;
        return 3;
    });
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    EXPECT_EQ(status, 3);
    EXPECT_EQ(given, std::vector<std::string>{"x.scene"}) << "the words after the program's name";

    testing::internal::CaptureStdout();
    EXPECT_EQ(show_usage(usage), 0);
    EXPECT_EQ(testing::internal::GetCapturedStdout(), usage + every);
}

// A typo's name: the nearest within a third of the word's length (at least 1 edit), never the word.
TEST(Args, ANearNameIsOnlyATyposDistanceAway) {
    EXPECT_EQ(near_name("tile.bmp", {"floor.bmp", "tiles.bmp", "wall.bmp"}), "tiles.bmp");
    EXPECT_EQ(near_name("corridr", {"cube", "corridor", "corridor-cut"}), "corridor");
    EXPECT_EQ(near_name("stone.bmp", {"tiles.bmp", "brick.pcx"}), "") << "nothing near";
    EXPECT_EQ(near_name("ab", {"xy"}), "") << "two substitutions in two letters: not a typo of it";
    EXPECT_EQ(near_name("a.bmp", {"a.bmp"}), "");
    EXPECT_EQ(near_name("a", {}), "");
}

// --version, wherever it is, answers with the program's name and the version, and runs nothing.
TEST(Args, VersionIsAnsweredBeforeAnythingRuns) {
    char program[] = "tool", file[] = "x.scene", version[] = "--version";
    char* argv[] = {program, file, version, nullptr};
    bool ran = false;
    testing::internal::CaptureStdout();
    const int status = run_cli("tool", "usage: tool FILE\n", 3, argv, [&](const std::vector<std::string>&) {
        ran = true;
        return 1;
    });
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "tool " MODEXLAB_VERSION "\n");
    EXPECT_EQ(status, 0);
    EXPECT_FALSE(ran);
}

// --option=value is --option value; a flag takes none; the option's name is checked either way.
TEST(Args, AnOptionsValueMayFollowAnEqualsSign) {
    const CommandLine c = parse({"--out=a.png", "--mapper=fast-affine", "--compare", "--list=a,b=c", "x"});
    EXPECT_EQ(c.text("--out"), "a.png");
    EXPECT_EQ(c.text("--mapper"), "fast-affine");
    EXPECT_EQ(c.text("--list"), "a,b=c") << "the first '=' splits";
    EXPECT_TRUE(c.has("--compare"));
    EXPECT_EQ(c.positionals(), std::vector<std::string>{"x"});
    EXPECT_EQ(parse({"--out="}).text("--out", "unset"), "") << "an empty value, given";
    EXPECT_EQ(usage_error_of([] { parse({"--compare=yes"}); }), "--compare takes no value");
    EXPECT_EQ(usage_error_of([] { parse({"--outt=a.png"}); }), "unknown option --outt");
}

}  // namespace
