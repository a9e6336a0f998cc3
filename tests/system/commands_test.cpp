// System tests: bad input gets an error and the server carries on; faults, triple faults and hangs
// are reported as the failures they are.
#include "tests/system/system.h"

namespace {

using namespace systest;

TEST(Commands, EveryMalformedCommandGetsAnErrorAndTheNextCommandWorks) {
    SessionOptions o = options_for_this_test();
    Session s(o);
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"bogus", "unknown command 'bogus'"},
        {"HELLO", "unknown command 'HELLO'"},
        {"hello there", "usage: hello"},
        {"pattern ramp 0", "no graphics mode"},
        {"mode", "usage: mode 13h|modex"},
        {"mode 12h", "unknown mode '12h'"},
        {"mode modex", ""},  // (not an error: sets up the cases below)
        {"pattern", "usage: pattern"},
        {"pattern ramp", "usage: pattern"},
        {"pattern spiral 0", "unknown pattern 'spiral'"},
        {"pattern ramp 3", "bad page '3': mode modex has pages 0..2"},
        {"pattern ramp -1", "bad page '-1'"},
        {"pattern ramp 0x", "bad page '0x'"},
        {"flip 4294967296", "bad page '4294967296'"},
        {"readback", "usage: readback PAGE [crc]"},
        {"readback 0 all", "usage: readback PAGE [crc]"},
        {"clear 0 256", "bad colour"},
        {"palette purple", "unknown palette 'purple'"},
        {"fault sideways", "unknown fault 'sideways'"},
        {"exit 64", "bad code"},
        {"exit", "usage: exit CODE"},
        {std::string(300, 'x'), "line too long"},
        {"\x01\x02\xff\xfe", "control character 0x01 at column 1"},
        {"\xff\xfe", "unknown command"},
        {"load cube.scene", ""},
        {"play 10 exact 1 vga", "unknown surface '1' (linear: rows in RAM then blit"},
        {"play 10 exact vga fast", "unknown variant 'fast' (asm: "},
    };
    for (const auto& [line, error] : bad) {
        json r = s.command(line);
        if (error.empty()) {
            EXPECT_TRUE(r["ok"].get<bool>());
            continue;
        }
        EXPECT_FALSE(r["ok"].get<bool>()) << line;
        EXPECT_NE(r.value("error", "").find(error), std::string::npos) << "for '" << line << "': " << r.dump();
        EXPECT_TRUE(s.ok("hello")["ok"].get<bool>()) << "the server carries on after '" << line << "'";
    }
    // an unknown mapper's error names every mapper, whole
    const std::string unknown = s.command("play 1 " + std::string(200, 'q')).value("error", "");
    for (int i = 0; i < raster::MAPPER_COUNT; ++i) EXPECT_NE(unknown.find(std::string(" ") + raster::MAPPERS[i].name), std::string::npos) << unknown;
    EXPECT_EQ(unknown.back(), ')') << unknown;
    // blank lines and carriage returns are not commands; backspace edits the line
    json r = s.raw("\r\n   \n\t\nhellx\bo\r\n");
    EXPECT_EQ(r["cmd"], "hello");
    s.ok("exit 63");
    EXPECT_EQ(s.wait_exit().status, 127);
}

// A string literal's bytes, NULs included.
template <size_t N>
std::string bytes_of(const char (&text)[N]) {
    return std::string(text, N - 1);
}

// Lines end at LF, CR or CR LF (a terminal's Enter sends any of them); a line holding a control
// character (a NUL too) is refused whole, naming the byte, so nothing after a NUL is cut off and
// nothing before it run; every line that is not blank gets one reply.
TEST(Commands, LinesEndAtCrOrLfAndControlCharactersAreRefused) {
    Session s(options_for_this_test());
    EXPECT_EQ(s.raw("hello\r")["cmd"], "hello");
    EXPECT_EQ(s.raw("hello\r\n")["cmd"], "hello");  // one reply: the next one's seq says so
    EXPECT_EQ(s.raw("hello\n")["cmd"], "hello");
    const std::vector<std::pair<std::string, std::string>> refused = {
        {bytes_of("mode modex\0junk\n"), "control character 0x00 at column 11"},
        {bytes_of("\0hello\n"), "control character 0x00 at column 1"},
        {bytes_of("\0\n"), "control character 0x00 at column 1"},
        {bytes_of("exit 0\0 please do not\n"), "control character 0x00 at column 7"},
        {"fault \x1b[A\n", "control character 0x1b at column 7"},
    };
    for (const auto& [bytes, error] : refused) {
        json r = s.raw(bytes);
        EXPECT_FALSE(r["ok"].get<bool>());
        EXPECT_NE(r.value("error", "").find(error), std::string::npos) << r.dump();
    }
    EXPECT_NE(s.command("pattern ramp 0").value("error", "").find("no graphics mode"), std::string::npos) << "'mode modex' was not run";
    // every byte value in order: Ctrl-C (3) drops the line so far; LF (10) and CR (13) end three
    // lines, each holding control characters (backspace and DEL edit them as a terminal's
    // would): three refusals
    std::string every;
    for (int b = 0; b < 256; ++b) every += char(b);
    json first = s.raw(every + "\n");
    EXPECT_NE(first.value("error", "").find("control character 0x04 at column 1"), std::string::npos) << first.dump();
    EXPECT_NE(s.raw("").value("error", "").find("control character 0x0b at column 1"), std::string::npos);
    EXPECT_NE(s.raw("").value("error", "").find("control character 0x0e at column 1"), std::string::npos);
    EXPECT_TRUE(s.ok("hello")["ok"].get<bool>());
    EXPECT_FALSE(s.exit_info()) << "QEMU still runs";
}

// A refused upload's bytes are read and dropped, never run as commands, whatever is wrong with its
// header: its length is read wherever it can be (scene's first word, file's second-to-last), and
// the bytes that follow are dropped while they come. Each payload here would leave QEMU with
// status 15 if it ran.
TEST(Commands, ARefusedUploadsBytesAreNeverRunAsCommands) {
    Session s(options_for_this_test());
    const std::string payload = "exit 7\nexit 7\n", n = std::to_string(payload.size());
    const std::vector<std::pair<std::string, std::string>> headers = {
        {"scene " + n + " 0x1ffffffff", "bad length or checksum"},  // a CRC wider than 32 bits
        {"scene 4194305 0", "bad length or checksum"},            // longer than an upload may be
        {"scene 99999999999 0", "bad length or checksum"},        // beyond 32 bits
        {"scene " + n, "usage: scene"},                           // no checksum
        {"scene " + n + " 0 extra", "usage: scene"},
        {"file " + std::string(64, 'n') + " " + n + " 0", "bad name"},
        {"file two words " + n + " 0", "usage: file"},  // a name with a space
        {"file x.bmp " + n, "usage: file"},
    };
    for (const auto& [header, error] : headers) {
        json r = s.raw(header + "\n" + payload);
        EXPECT_FALSE(r["ok"].get<bool>()) << header;
        EXPECT_NE(r.value("error", "").find(error), std::string::npos) << header << ": " << r.dump();
        EXPECT_EQ(r.value("discarded", -1), int(payload.size())) << header << ": " << r.dump();
        ASSERT_TRUE(s.ok("hello")["ok"].get<bool>()) << "after '" << header << "'";
        ASSERT_FALSE(s.exit_info()) << "the payload after '" << header << "' ran";
    }
    // a client that waits for `ready` hears the refusal at once and sends nothing
    json r = s.command("scene 0 0");
    EXPECT_FALSE(r["ok"].get<bool>());
    EXPECT_EQ(r["discarded"], 0);
}

// `file` uploads fill the file table up to its last place, which stays the scene upload's.
TEST(Commands, AFullFileTableStillTakesASceneUpload) {
    Session s(options_for_this_test());
    int taken = 0;
    json r;
    for (; taken < 100; ++taken) {
        r = s.upload_file("f" + std::to_string(taken) + ".bmp", "x");
        if (!r["ok"].get<bool>()) break;
    }
    EXPECT_NE(r.value("error", "").find("too many files"), std::string::npos) << r.dump();
    EXPECT_EQ(r.value("discarded", -1), 0) << "refused before the byte was sent";
    EXPECT_GT(taken, 50);
    EXPECT_TRUE(s.upload_file("f0.bmp", "y")["ok"].get<bool>()) << "a name already there is replaced";
    const std::string scene = "modexlab-scene 1\ntexture checker 64 64\ntriangle 0 0 1 0 0  100 0 1 64 0  0 100 1 0 64\n";
    json up = s.upload_scene(scene);
    EXPECT_TRUE(up["ok"].get<bool>()) << up.dump();
    EXPECT_TRUE(s.upload_scene(scene)["ok"].get<bool>()) << "and again";
    EXPECT_EQ(s.ok("files")["files"].size(), 96u);
}

// A line sent while play, bench or selftest runs stops it after the frame (or loop) in hand: its
// reply says interrupted and how far it got, and the line is then answered as the next command.
TEST(Commands, ALineSentDuringLongWorkInterruptsIt) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    s.ok("load corridor.scene");
    for (const std::string& cmd : {std::string("play 100000 exact"), std::string("bench 1000 exact")}) {
        int events = 0;
        json r = s.command(cmd, [&](const json&) {
            if (events++ == 1) s.send("hello\n");
        });
        EXPECT_TRUE(r["ok"].get<bool>()) << r.dump();
        EXPECT_TRUE(r["interrupted"].get<bool>()) << cmd;
        EXPECT_GE(r["frames"].get<int>(), 2) << cmd;
        EXPECT_LE(r["frames"].get<int>(), 5) << cmd << ": stopped within a frame or so of the line";
        EXPECT_EQ(r["frames"].get<int>(), events) << "one event a frame drawn";
        EXPECT_EQ(s.raw("")["cmd"], "hello") << "the line is answered next";
    }
    // selftest sends no events: the line goes with the command, and the first 1000 cases of the
    // first loop are checked (a million would take many minutes: it stops between thousands)
    json st = s.raw("selftest 1000000\nhello\n");
    EXPECT_TRUE(st["interrupted"].get<bool>()) << st.dump();
    ASSERT_EQ(st["loops"].size(), 1u);
    EXPECT_EQ(st["loops"][0]["cases"], 1000) << st.dump();
    EXPECT_EQ(s.raw("")["cmd"], "hello");
    json r = s.command("play 3 exact", [](const json&) {});
    EXPECT_FALSE(r["interrupted"].get<bool>());
    EXPECT_EQ(r["frames"], 3);
    EXPECT_EQ(r["frames_asked"], 3);
}

// Replacing an upload frees its old copy: the uploads after it move down, intact, and the space is
// used again.
TEST(Commands, ReplacingAnUploadFreesItsSpace) {
    Session s(options_for_this_test());
    const uint64_t start = s.ok("files")["upload_space_used"].get<uint64_t>();
    const std::string scene = "modexlab-scene 1\ntexture checker 64 64\ntriangle 0 0 1 0 0  100 0 1 64 0  0 100 1 0 64\n";
    EXPECT_EQ(s.upload_file("a.bin", std::string(1000, 'a'))["upload_space_used"], start + 1000);
    EXPECT_EQ(s.upload_file("s.scene", scene)["upload_space_used"], start + 1000 + scene.size());
    for (int i = 0; i < 3; ++i) {
        json r = s.upload_file("a.bin", std::string(2000 + i, 'b'));
        EXPECT_EQ(r["upload_space_used"], start + scene.size() + 2000 + i) << "the old copy is freed";
    }
    json loaded = s.ok("load s.scene");
    EXPECT_EQ(loaded["polygons"], 1) << "the scene after it moved down intact";
}

// A drawing that takes long says so with a progress event a second, and a line stops it between
// polygons: 800 screen-size triangles with the exact mapper (about 5 billion instructions).
TEST(Commands, ALongRenderShowsProgressAndALineStopsIt) {
    Session s(options_for_this_test());
    s.ok("mode modex");
    std::string scene = "modexlab-scene 1\ntexture checker 64 64\n";
    for (int i = 0; i < 800; ++i) scene += "triangle -10 -10 1 0 0  700 -10 2 64 0  -10 500 3 0 64\n";
    ASSERT_TRUE(s.upload_scene(scene)["ok"].get<bool>());
    json r = stopped_at_first_progress(s, "render exact 0", "render", 800);
    EXPECT_TRUE(r["ok"].get<bool>()) << r.dump();
    EXPECT_TRUE(r["interrupted"].get<bool>());
    EXPECT_GT(r["polygons"].get<int>(), 0);
    EXPECT_LT(r["polygons"].get<int>(), 800);
    EXPECT_EQ(s.raw("")["cmd"], "hello");
}

// A CPU exception is this command's reply, names the vector and the faulting EIP, and ends QEMU
// with status 2 * (0x40 + vector) + 1.
void expect_fault(const std::string& which, int vector, const std::string& name, const std::string& site, uint32_t error_code) {
    Session s(options_for_this_test());
    s.ok("hello");
    uint32_t eip = kernel_symbol(site);
    ASSERT_NE(eip, 0u) << site << " not in the kernel's symbols";
    try {
        s.command("fault " + which);
        FAIL() << "fault " << which << " did not fault";
    } catch (const KernelFault& f) {
        const json& r = f.report();
        EXPECT_EQ(r["seq"], 2) << "the fault report is the reply to the command";
        EXPECT_EQ(r["fault"], true);
        EXPECT_FALSE(r.contains("event")) << "a line with seq is a reply, never an event too";
        EXPECT_EQ(r["vector"], vector);
        EXPECT_EQ(r["name"], name);
        char want[16];
        std::snprintf(want, sizeof want, "0x%08x", eip);
        EXPECT_EQ(r["eip"], want);
        std::snprintf(want, sizeof want, "0x%08x", error_code);
        EXPECT_EQ(r["error_code"], want);
        for (const char* reg : {"eax", "ebx", "ecx", "edx", "esi", "edi", "ebp", "esp", "eflags", "cs"}) EXPECT_TRUE(r.contains(reg)) << reg;
        EXPECT_NE(std::string(f.what()).find("CPU exception, vector " + std::to_string(vector)), std::string::npos) << f.what();
    }
    auto e = s.exit_info();
    ASSERT_TRUE(e);
    EXPECT_EQ(e->status, 2 * (0x40 + vector) + 1) << e->describe();
}

TEST(Commands, InvalidOpcodeFaultIsReported) { expect_fault("ud", 6, "#UD", "fault_ud2", 0); }
TEST(Commands, DivideErrorIsReported) { expect_fault("de", 0, "#DE", "fault_divide_site", 0); }
TEST(Commands, GeneralProtectionFaultIsReported) { expect_fault("gp", 13, "#GP", "fault_gp_site", 0x18); }

TEST(Commands, ATripleFaultIsAFailureNotAPass) {
    Session s(options_for_this_test());
    try {
        s.command("fault triple");
        FAIL() << "a triple fault produced a reply";
    } catch (const HarnessError& e) {
        EXPECT_NE(std::string(e.what()).find("never a pass"), std::string::npos) << e.what();
    }
    auto e = s.exit_info();
    ASSERT_TRUE(e);
    EXPECT_EQ(e->status, 0);
}

TEST(Commands, AHangIsCaughtByTheTimeoutAndQemuIsKilled) {
    SessionOptions o = options_for_this_test();
    o.command_timeout = std::chrono::milliseconds(1500);
    Session s(o);
    auto t0 = std::chrono::steady_clock::now();
    try {
        s.command("fault hang");
        FAIL() << "a hang produced a reply";
    } catch (const HarnessError& e) {
        std::string what = e.what();
        EXPECT_NE(what.find("no reply to 'fault hang' within 1500 ms"), std::string::npos) << what;
        EXPECT_NE(what.find("> fault hang"), std::string::npos) << "the last serial lines are shown: " << what;
    }
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(10));
    auto e = s.exit_info();
    ASSERT_TRUE(e) << "QEMU must not be left running";
    EXPECT_FALSE(e->exited);
    EXPECT_EQ(e->signal, SIGKILL);
}

}  // namespace
