// The command server as a terminal and a hostile client meet it: lines ended by CR LF, CR or LF,
// upload headers ended each way, refused headers whose payload must never run, frames cut short,
// Ctrl-C, escape sequences, replies in the client's own line ends (docs/protocol.md, "Lines").
#include "tests/system/system.h"

#include <fstream>
#include <sstream>

#include "kernel/lib/encode.h"

namespace {

using namespace systest;

const char* const ENDS[] = {"\r\n", "\r", "\n"};

std::string shown_end(const std::string& end) { return end == "\r\n" ? "CR LF" : end == "\r" ? "CR" : "LF"; }

std::string crc_of(const std::string& bytes) {
    char crc[16];
    std::snprintf(crc, sizeof crc, "0x%08x", lib::crc32(0, reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()));
    return crc;
}

// The serial log as the harness received it (it writes it as it reads).
std::string serial_log(Session& s) {
    std::ifstream in(s.run_dir() + "/serial.log", std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Long work ended by CR LF ran whole: the LF after the CR is the line's end, not a second line
// that stops it. Each of CR LF, CR and LF ends exactly one line.
TEST(Terminal, EachLineEndEndsOneLineAndLongWorkRunsWhole) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    s.ok("load cube.scene");
    for (const std::string end : ENDS) {
        SCOPED_TRACE(shown_end(end));
        json play = s.raw("play 30 fast-affine" + end, [](const json&) {});
        EXPECT_EQ(play["frames"], 30) << play.dump();
        EXPECT_EQ(play["interrupted"], false);
        json bench = s.raw("bench 5 fast-affine" + end, [](const json&) {});
        EXPECT_EQ(bench["frames"], 5) << bench.dump();
        EXPECT_EQ(bench["interrupted"], false);
        json frame = s.raw("frame 10 exact 1" + end);
        EXPECT_EQ(frame["interrupted"], false) << frame.dump();
        EXPECT_GT(frame["polygons"].get<int>(), 0);
        json self = s.raw("selftest 1000" + end);  // (an LF would stop it between its loops)
        EXPECT_EQ(self["interrupted"], false) << self.dump();
        for (const json& loop : self["loops"]) EXPECT_EQ(loop["cases"], 1000) << loop.dump();
        EXPECT_EQ(s.raw("hello" + end)["cmd"], "hello");
    }
}

// Replies end the way the client's last line ended: CR LF after CR LF or CR (a terminal shows LF
// alone as a staircase), LF after LF.
TEST(Terminal, RepliesEndAsTheClientsLinesDo) {
    Session s(options_for_this_test());
    for (const std::string end : ENDS) {
        const json r = s.raw("files" + end);
        const std::string log = serial_log(s), wanted = std::string("\"upload_space\":") + std::to_string(r["upload_space"].get<uint64_t>()) + "}";
        const size_t at = log.rfind(wanted);
        ASSERT_NE(at, std::string::npos);
        EXPECT_EQ(log.substr(at + wanted.size()), end == "\n" ? "\n" : "\r\n") << shown_end(end);
    }
}

// An upload header ended by CR LF or CR: the LF after its CR is not the payload's first byte, and
// no payload byte is left over for the command reader. A header ended by LF keeps a payload that
// begins with LF whole.
TEST(Terminal, UploadHeadersEndedEachWayTakeTheirBytesWhole) {
    Session s(options_for_this_test());
    for (const std::string end : ENDS) {
        SCOPED_TRACE(shown_end(end));
        const std::string bytes = "abc";
        json r = s.raw("file a.txt 3 " + crc_of(bytes) + end + bytes, [](const json&) {});
        EXPECT_TRUE(r["ok"].get<bool>()) << r.dump();
        EXPECT_EQ(r["bytes"], 3);
        EXPECT_EQ(s.raw("hello" + end)["cmd"], "hello") << "no payload byte left for the reader";
        const std::string scene = "modexlab-scene 1\ntexture checker 64 64\ntriangle 0 0 1 0 0  100 0 1 64 0  0 100 1 0 64\n";
        r = s.raw("scene " + std::to_string(scene.size()) + " " + crc_of(scene) + end + scene, [](const json&) {});
        EXPECT_TRUE(r["ok"].get<bool>()) << r.dump();
        EXPECT_EQ(r["polygons"], 1);
    }
    const std::string led = "\nabc";
    json r = s.raw("file b.txt 4 " + crc_of(led) + "\n" + led, [](const json&) {});
    EXPECT_TRUE(r["ok"].get<bool>()) << r.dump();
    EXPECT_EQ(s.raw("hello\n")["cmd"], "hello");
}

// A header the server refuses as a line (too long, a control byte) or whose length it cannot read
// still announces a payload: its bytes are dropped, never run. Each payload here would answer
// `hello` twice, or leave QEMU with status 15, if it ran.
TEST(Terminal, ARefusedHeadersPayloadIsNeverRun) {
    Session s(options_for_this_test());
    for (const std::string end : ENDS) {
        SCOPED_TRACE(shown_end(end));
        for (const std::string& payload : {std::string("hello\nhello\n"), std::string("exit 7\nexit 7\n")}) {
            const std::string n = std::to_string(payload.size());
            const std::vector<std::pair<std::string, std::string>> headers = {
                {"file " + std::string(300, 'n') + " " + n + " 0", "line too long"},
                {"file a\x01" "b " + n + " 0", "control character 0x01 at column 7"},
                {"file a b c", "bad length or checksum"},  // no length to read: dropped until the line is quiet
                {"scene " + n + " 0x1ffffffff", "bad length or checksum"},
            };
            for (const auto& [header, error] : headers) {
                json r = s.raw(header + end + payload);
                EXPECT_FALSE(r["ok"].get<bool>()) << header;
                EXPECT_NE(r.value("error", "").find(error), std::string::npos) << header << ": " << r.dump();
                EXPECT_EQ(r.value("discarded", -1), int(payload.size())) << header << ": " << r.dump();
                ASSERT_EQ(s.raw("files\n")["cmd"], "files") << "the payload after '" << header << "' was read as lines";
                ASSERT_FALSE(s.exit_info()) << "the payload after '" << header << "' ran";
            }
        }
    }
}

// The next line stops play and bench inside their only frame: the reply says so, and counts no
// frame it cut (a bench row of a cut frame would be wrong data).
TEST(Terminal, AFrameCutShortIsReportedCutAndNotCounted) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    s.ok("load corridor-cut.scene");  // (a drawing stops between polygons, every 16th)
    for (const std::string& cmd : {std::string("play 1 exact"), std::string("bench 1 exact")}) {
        int events = 0;
        json r = s.raw(cmd + "\nhello\n", [&](const json&) { ++events; });
        EXPECT_TRUE(r["ok"].get<bool>()) << r.dump();
        EXPECT_EQ(r["interrupted"], true) << cmd << ": " << r.dump();
        EXPECT_EQ(r["frames"], 0) << cmd << ": " << r.dump();
        EXPECT_EQ(r["frames_asked"], 1);
        EXPECT_EQ(r["pixels"], 0) << cmd;
        EXPECT_EQ(events, 0) << cmd << ": no event for a frame not drawn whole";
        EXPECT_EQ(s.raw("")["cmd"], "hello");
    }
}

// Ctrl-C stops long work and is consumed; at the prompt it drops what was typed, unanswered.
// An arrow key's escape sequence is refused with a word on line editing.
TEST(Terminal, CtrlCInterruptsAndVanishesAndArrowKeysAreExplained) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    s.ok("load cube.scene");
    int events = 0;
    json r = s.command("play 100000 fast-affine", [&](const json&) {
        if (events++ == 1) s.send("\x03");
    });
    EXPECT_EQ(r["interrupted"], true) << r.dump();
    EXPECT_GE(r["frames"].get<int>(), 2);
    const json hello = s.raw("hello\n");
    EXPECT_EQ(hello["cmd"], "hello") << hello.dump();
    EXPECT_EQ(hello["seq"], r["seq"].get<int>() + 1) << "Ctrl-C was answered";
    const json typed = s.raw("mode 13h\x03hello\r\n");
    EXPECT_EQ(typed["cmd"], "hello") << typed.dump();
    EXPECT_EQ(typed["seq"], hello["seq"].get<int>() + 1);
    EXPECT_EQ(s.ok("hello")["mode"], "modex") << "the line before Ctrl-C was not run";
    const json arrow = s.raw("hello\x1b[A\n");
    EXPECT_NE(arrow.value("error", "").find("line editing is not supported"), std::string::npos) << arrow.dump();
}

// A budget is echoed as it is used: every decimal the parser takes, none rounded away.
TEST(Terminal, ABudgetIsEchoedAsUsed) {
    Session s(options_for_this_test());
    s.ok("load cube.scene");
    for (const std::string& b : {std::string("0.0005"), std::string("0.000001"), std::string("2.25"), std::string("1000000")}) {
        const json r = s.ok("budget " + b);
        EXPECT_EQ(r["budget"]["max_error"].get<double>(), std::stod(b)) << r.dump();
    }
    EXPECT_NE(s.command("budget 0.0000001").value("error", "").find("usage: budget"), std::string::npos) << "7 decimals: refused";
}

}  // namespace
