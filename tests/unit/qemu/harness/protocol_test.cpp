// Under test: qemu/harness/channel.h, kernel_link.h, qmp.h.
// Framing and reply parsing: LineSplitter, LineChannel deadlines, QMP and the kernel's serial protocol,
// each against a scripted peer on a socketpair.
#include <gtest/gtest.h>

#include <sys/socket.h>
#include <unistd.h>

#include <thread>

#include "qemu/harness/channel.h"
#include "qemu/lib/error.h"
#include "qemu/harness/kernel_link.h"
#include "qemu/harness/qmp.h"

namespace {

using namespace harness;
using namespace std::chrono_literals;

// One end for the code under test, one for the test to script the peer.
struct Pair {
    int ours = -1, peer = -1;
    Pair() {
        int fds[2];
        if (::socketpair(AF_UNIX, SOCK_STREAM, 0, fds) != 0) throw std::runtime_error("socketpair");
        ours = fds[0];
        peer = fds[1];
    }
    ~Pair() {
        if (peer >= 0) ::close(peer);
    }
    void say(const std::string& s) const { ASSERT_EQ(::write(peer, s.data(), s.size()), ssize_t(s.size())); }
    std::string heard() const {
        char buf[4096];
        ssize_t n = ::read(peer, buf, sizeof buf);
        return n > 0 ? std::string(buf, size_t(n)) : "";
    }
    void hang_up() {
        ::close(peer);
        peer = -1;
    }
};

TEST(LineSplitter, ReassemblesPartialLinesAndStripsCr) {
    LineSplitter s;
    s.feed("{\"a\":");
    EXPECT_FALSE(s.next());
    s.feed("1}\r\n{\"b\":2}\n\n{\"c\"");
    EXPECT_EQ(s.next(), "{\"a\":1}");
    EXPECT_EQ(s.next(), "{\"b\":2}");
    EXPECT_EQ(s.next(), "");
    EXPECT_FALSE(s.next());
    EXPECT_EQ(s.pending(), "{\"c\"");
    s.feed(":3}\n");
    EXPECT_EQ(s.next(), "{\"c\":3}");
}

TEST(LineChannel, TimesOutAndReportsEndOfStream) {
    Pair p;
    LineChannel ch(p.ours);
    auto t0 = Clock::now();
    EXPECT_FALSE(ch.read_line(Clock::now() + 50ms));
    EXPECT_GE(Clock::now() - t0, 50ms);
    p.say("one\ntw");
    EXPECT_EQ(ch.read_line(Clock::now() + 1s), "one");
    p.hang_up();
    try {
        ch.read_line(Clock::now() + 1s);
        FAIL() << "no error at end of stream";
    } catch (const HarnessError& e) {
        EXPECT_NE(std::string(e.what()).find("partial line: tw"), std::string::npos) << e.what();
    }
}

TEST(Qmp, ParsesTheFourKinds) {
    EXPECT_EQ(parse_qmp_line(R"({"QMP":{"version":{}}})").kind, QmpMessage::Kind::Greeting);
    EXPECT_EQ(parse_qmp_line(R"({"return":{},"id":3})").id, 3);
    EXPECT_EQ(parse_qmp_line(R"({"error":{"class":"GenericError","desc":"x"},"id":4})").kind, QmpMessage::Kind::Error);
    EXPECT_EQ(parse_qmp_line(R"({"event":"STOP","timestamp":{}})").kind, QmpMessage::Kind::Event);
    EXPECT_THROW(parse_qmp_line("not json"), HarnessError);
    EXPECT_THROW(parse_qmp_line(R"({"something":"else"})"), HarnessError);
    EXPECT_THROW(parse_qmp_line("[1,2]"), HarnessError);
}

TEST(Qmp, HandshakeCommandsEventsAndErrors) {
    Pair p;
    std::thread peer([&] {
        p.say("{\"QMP\": {\"version\": {}, \"capabilities\": []}}\r\n");
        auto caps = json::parse(p.heard());
        EXPECT_EQ(caps["execute"], "qmp_capabilities");
        p.say("{\"return\": {}, \"id\": " + caps["id"].dump() + "}\r\n");
        auto stop = json::parse(p.heard());
        EXPECT_EQ(stop["execute"], "stop");
        // an event arrives between the command and its return, in two pieces
        p.say("{\"timestamp\": {\"seconds\": 1}, \"event\": \"ST");
        p.say("OP\"}\r\n{\"return\": {}, \"id\": " + stop["id"].dump() + "}\r\n");
        auto dump = json::parse(p.heard());
        EXPECT_EQ(dump["arguments"]["format"], "png");
        p.say("{\"error\": {\"class\": \"GenericError\", \"desc\": \"no surface\"}, \"id\": " + dump["id"].dump() + "}\r\n");
        auto late = json::parse(p.heard());
        p.say("{\"return\": {}, \"id\": 999}\r\n");  // wrong id
        (void)late;
    });
    QmpClient q{LineChannel(p.ours)};
    q.handshake(2s);
    EXPECT_NO_THROW(q.execute("stop"));
    ASSERT_EQ(q.events().size(), 1u);
    EXPECT_EQ(q.events()[0]["event"], "STOP");
    try {
        q.execute("screendump", {{"filename", "/x.png"}, {"format", "png"}});
        FAIL() << "an error reply must throw";
    } catch (const HarnessError& e) {
        EXPECT_NE(std::string(e.what()).find("no surface"), std::string::npos) << e.what();
    }
    EXPECT_THROW(q.execute("cont"), HarnessError);
    peer.join();
}

TEST(Qmp, TimesOutWhenQemuIsSilent) {
    Pair p;
    QmpClient q{LineChannel(p.ours)};
    EXPECT_THROW(q.handshake(100ms), HarnessError);
}

TEST(KernelLine, Classification) {
    EXPECT_EQ(classify_kernel_line("").kind, KernelLine::Kind::Blank);
    EXPECT_EQ(classify_kernel_line(R"({"seq":1,"ok":true})").kind, KernelLine::Kind::Reply);
    EXPECT_EQ(classify_kernel_line(R"({"seq":2,"ok":false,"fault":true,"vector":6})").kind, KernelLine::Kind::Fault);
    EXPECT_EQ(classify_kernel_line(R"({"event":"boot"})").kind, KernelLine::Kind::BootEvent);
    EXPECT_EQ(classify_kernel_line(R"({"event":"panic","error":"x"})").kind, KernelLine::Kind::PanicEvent);
    for (const char* bad : {"garbage", R"({"seq":1})", R"({"seq":"1","ok":true})", R"({"seq":-1,"ok":true})",
                            R"({"seq":1,"ok":"yes"})", R"({"ok":true})", "[1]", R"({"seq":1,"ok":tr)"})
        EXPECT_THROW(classify_kernel_line(bad), HarnessError) << bad;
}

TEST(KernelLink, BootThenRepliesInSequence) {
    Pair p;
    KernelLink k{LineChannel(p.ours)};
    p.say("SeaBIOS noise\r\n\x1b[2J{\"event\":\"boot\",\"version\":\"x\"}\n");
    EXPECT_EQ(k.wait_boot(1s)["version"], "x");
    p.say("{\"seq\":1,\"ok\":true,\"cmd\":\"hello\"}\n");
    EXPECT_EQ(k.request("hello", 1s)["cmd"], "hello");
    EXPECT_EQ(p.heard(), "hello\n");
    p.say("\n{\"seq\":2,\"ok\":false,\"error\":\"unknown command\"}\n");
    EXPECT_FALSE(k.request("bogus", 1s)["ok"].get<bool>());
    EXPECT_EQ(k.next_seq(), 3u);
}

TEST(KernelLink, ALostReplyIsAFailure) {
    Pair p;
    KernelLink k{LineChannel(p.ours)};
    p.say("{\"seq\":2,\"ok\":true}\n");  // seq 1 never came
    try {
        k.request("hello", 1s);
        FAIL();
    } catch (const HarnessError& e) {
        EXPECT_NE(std::string(e.what()).find("seq 2, expected 1"), std::string::npos) << e.what();
    }
}

TEST(KernelLink, AGarbledLineIsAFailure) {
    Pair p;
    KernelLink k{LineChannel(p.ours)};
    p.say("{\"seq\":1,\"ok\":tr\x00ue}\n");
    EXPECT_THROW(k.request("hello", 1s), HarnessError);
}

TEST(KernelLink, FaultPanicRebootAndSilence) {
    {
        Pair p;
        KernelLink k{LineChannel(p.ours)};
        p.say("{\"seq\":1,\"ok\":false,\"error\":\"CPU exception #UD\",\"fault\":true,\"vector\":6,\"eip\":\"0x00100164\"}\n");
        try {
            k.request("fault", 1s);
            FAIL();
        } catch (const KernelFault& f) {
            EXPECT_EQ(f.report()["vector"], 6);
            EXPECT_EQ(f.report()["eip"], "0x00100164");
        }
    }
    {
        Pair p;
        KernelLink k{LineChannel(p.ours)};
        p.say("{\"event\":\"panic\",\"error\":\"bad multiboot magic\"}\n");
        EXPECT_THROW(k.wait_boot(1s), HarnessError);
    }
    {
        Pair p;
        KernelLink k{LineChannel(p.ours)};
        p.say("noise{\"seq\":1,\"ok\":false,\"fault\":true,\"vector\":13}\n");
        EXPECT_THROW(k.wait_boot(1s), KernelFault) << "a fault before the boot line";
    }
    {
        Pair p;
        KernelLink k{LineChannel(p.ours)};
        p.say("{\"event\":\"boot\"}\n");
        EXPECT_THROW(k.request("hello", 1s), HarnessError) << "a boot line in place of a reply is a reboot";
    }
    {
        Pair p;
        KernelLink k{LineChannel(p.ours)};
        auto t0 = Clock::now();
        EXPECT_THROW(k.request("hello", 100ms), HarnessError);
        EXPECT_LT(Clock::now() - t0, 2s);
        EXPECT_NE(k.transcript_tail().find("> hello"), std::string::npos);
    }
}

}  // namespace
