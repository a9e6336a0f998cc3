// The command server under hostile input: random and mutated command lines and uploads, from a
// fixed seed, to one booted kernel, their lines ended by LF, CR or CR LF at random; after each, a
// marker command (`load sync-N`, whose error names it) must still be answered, every reply with
// the next sequence number, and QEMU must still run. Every payload carries lines that would
// answer `leak-N` if run: no reply may ever name one. Long work is interrupted at random points:
// a reply that says it was not interrupted has done all that was asked, one that was, less.
// `make test` sends a few hundred inputs; `make fuzz-protocol` many more (MODEXLAB_PROTOCOL_FUZZ
// inputs, MODEXLAB_PROTOCOL_SEED).
#include <cstdlib>
#include <random>

#include "kernel/lib/encode.h"
#include "kernel/lib/protocol.h"
#include "tests/system/system.h"

namespace {

using namespace systest;

// Words each command takes, valid and not; the commands that end the session (exit, fault) are left
// out. Long work (play 100000, selftest 100000) stops at the marker that follows it.
const std::vector<std::vector<std::string>> COMMANDS = {
    {"hello"}, {"help"}, {"files"}, {"mappers"},
    {"mode", "13h", "modex", "12h", ""},
    {"pattern", "ramp", "planes", "grid", "border", "0", "1", "2", "3", "-1"},
    {"clear", "0", "1", "2", "255", "256", "0x10"},
    {"palette", "default", "gray", "purple"},
    {"flip", "0", "1", "2", "4294967296"},
    {"readback", "0", "1", "2", "9"},
    {"load", "corridor.scene", "ball.scene", "mesh.scene", "upload.scene", "x.bmp", "nothing"},
    {"render", "exact", "affine", "auto", "fast-affine", "quake-subdiv16", "xsharp-column", "0", "1", "linear", "planar", "vga", "asm", "twin"},
    {"frame", "0", "7", "359", "1000000", "exact", "auto", "fatmap-lut", "0", "1", "linear", "vga", "twin"},
    {"play", "1", "2", "100000", "exact", "auto", "fast-columns", "planar", "vga"},
    {"bench", "1", "2", "1000", "exact", "auto", "linear", "asm"},
    {"budget", "scene", "0", "0.5", "4", "any", "exact", "-1", "1e9", "486", "pentium", "icount"},
    {"selftest", "1", "2", "0", "100000"},
    {"vbe", "on", "off"},
};

// Whether the server, reading `input` as lines (the kernel's own line assembler), would run a
// command that ends the session: a mutation can make one (a CR inside "default" leaves "fault").
bool ends_session(const std::string& input) {
    lib::LineAssembler lines;
    for (char c : input) {
        if (lines.feed(c) != lib::LineAssembler::Result::Line) continue;
        lib::StrView words[2];
        if (lib::split_words(lines.line(), words, 2) && (words[0].equals("fault") || words[0].equals("exit"))) return true;
    }
    return false;
}

class Fuzzer {
public:
    explicit Fuzzer(uint32_t seed) : rng_(seed) {}

    uint32_t below(uint32_t n) { return std::uniform_int_distribution<uint32_t>(0, n - 1)(rng_); }
    bool chance(uint32_t percent) { return below(100) < percent; }

    // A command line from the dictionary: its name and up to five of its words, or a number.
    std::string line() {
        const auto& c = COMMANDS[below(uint32_t(COMMANDS.size()))];
        std::string out = c[0];
        for (uint32_t n = below(6), i = 0; i < n && c.size() > 1; ++i) out += " " + word(c);
        return out;
    }
    std::string word(const std::vector<std::string>& c) {
        switch (below(8)) {
        case 0: return std::to_string(int64_t(rng_()) - int64_t(1u << 31));
        case 1: return "0x" + std::to_string(rng_());
        default: return c[1 + below(uint32_t(c.size() - 1))];
        }
    }
    // Bytes changed, inserted, dropped or repeated; line ends where they fall.
    std::string mutate(std::string s) {
        for (uint32_t n = 1 + below(4), i = 0; i < n; ++i) {
            const size_t at = s.empty() ? 0 : below(uint32_t(s.size()));
            switch (below(5)) {
            case 0: if (!s.empty()) s[at] = char(below(256)); break;
            case 1: s.insert(at, 1, char(below(256))); break;
            case 2: if (!s.empty()) s.erase(at, 1 + below(4)); break;
            case 3: s.insert(at, s.substr(at, below(16))); break;
            default: s.insert(at, 1, "\r\n\t \0"[below(5)]); break;
            }
        }
        return s;
    }
    // A line end: LF, CR or CR LF.
    std::string end() {
        static const char* const ENDS[] = {"\n", "\r", "\r\n"};
        return ENDS[below(3)];
    }
    // A header's line end before `payload`: CR alone only where the payload does not begin with LF
    // (an LF right after a header's CR belongs to its line end: docs/protocol.md).
    std::string end_before(const std::string& payload) {
        const std::string e = end();
        return e == "\r" && !payload.empty() && payload[0] == '\n' ? "\r\n" : e;
    }
    // Lines that would answer `leak-N` if run, put into a payload at random places.
    std::string with_leaks(std::string payload, uint32_t i) {
        for (uint32_t n = 1 + below(3), k = 0; k < n; ++k)
            payload.insert(payload.empty() ? 0 : below(uint32_t(payload.size())), end() + "load leak-" + std::to_string(i) + end());
        return payload;
    }
    // An upload's header (one line, sometimes broken when `may_break`: bytes changed, never a line
    // end) for the bytes.
    std::string upload_header(const std::string& payload, bool may_break = true) {
        char crc[16];
        std::snprintf(crc, sizeof crc, "0x%08x", lib::crc32(0, reinterpret_cast<const uint8_t*>(payload.data()), payload.size()));
        std::string header = (below(2) ? std::string("scene") : "file f" + std::to_string(below(4)) + ".scene") + " " +
                             std::to_string(payload.size()) + " " + (chance(80) ? std::string(crc) : std::to_string(rng_()));
        for (uint32_t n = may_break && chance(30) ? 1 + below(3) : 0, i = 0; i < n; ++i) {
            char c = char(below(256));
            header[below(uint32_t(header.size()))] = c == '\n' || c == '\r' ? 'x' : c;
        }
        return header;
    }
    // An upload's header the server must refuse, whose length is still right: what follows it is
    // its payload, never to be run (a name with a control byte, spaces, or too long for a line; a
    // checksum that is no number; a word too many or too few).
    std::string refused_header(const std::string& payload) {
        const std::string n = std::to_string(payload.size());
        switch (below(6)) {
        case 0: return "scene " + n + " 0xnothex";
        case 1: return "scene " + n + " 0 and more";
        case 2: return "file " + std::string(250 + below(100), 'n') + " " + n + " 0";
        case 3: {  // a control byte the line reader keeps and refuses: not a line end, tab, backspace or Ctrl-C
            char c;
            do c = char(1 + below(31));
            while (c == '\n' || c == '\r' || c == '\t' || c == '\b' || c == 0x03);
            return "file na" + std::string(1, c) + "me " + n + " 0";
        }
        case 4: return "file two words " + n + " 0";
        default: return "file name " + n;
        }
    }
private:
    std::mt19937 rng_;
};

// Bytes as C escapes, for a failure message.
std::string shown(const std::string& bytes) {
    std::string out = "\"";
    for (unsigned char c : bytes) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "\\x%02x", c);
        out += c >= 0x20 && c < 0x7F && c != '"' && c != '\\' ? std::string(1, char(c)) : std::string(hex);
    }
    return out + "\"";
}

uint32_t env_or(const char* name, uint32_t fallback) {
    const char* v = std::getenv(name);
    return v && *v ? uint32_t(std::strtoul(v, nullptr, 10)) : fallback;
}

TEST(ProtocolFuzz, TheServerAnswersAfterEveryRandomInput) {
    const uint32_t inputs = env_or("MODEXLAB_PROTOCOL_FUZZ", 300), seed = env_or("MODEXLAB_PROTOCOL_SEED", 2026);
    SessionOptions o = options_for_this_test();
    Session s(o);
    Fuzzer f(seed);
    const std::string scene = "modexlab-scene 1\ntexture checker 64 64\ntriangle 0 0 1 0 0  300 0 2 64 0  0 200 3 0 64\n";
    const std::string world = "modexlab-scene 2\ntexture t checker 64 64\nmesh m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 t\nobject a m\n";
    uint32_t replies = 0, uploads = 0, taken = 0, refused = 0, stopped = 0, whole = 0;
    size_t nasm_loops = 0;  // what a whole selftest checks: each NASM loop once, under its first mapper's name
    const json listed = s.ok("mappers");  // (kept: a range-for over a temporary's member would dangle)
    for (const json& m : listed["mappers"]) nasm_loops += m.value("asm_loop", std::string()) == m["name"].get<std::string>();
    // the bytes after a `ready` (an upload the kernel took): as many as it asked for; after an input
    // sent with its marker (which then went into the upload), a line end and the marker again
    std::string payload, marker;
    bool marker_again = false, impatient = false;
    auto on_event = [&](const json& e) {
        if (e.value("event", "") != "ready") return;  // frames of play and bench
        ++taken;
        if (impatient) return;  // the bytes went with the header
        std::string bytes = payload;
        bytes.resize(e.value("bytes", size_t(0)), '\n');
        s.send(marker_again ? bytes + "\n" + marker : bytes);
    };
    // every reply: none is a payload's line run (`load leak-N`; a parser's error may quote the bytes
    // of an upload it took)
    auto reply = [&](uint32_t i, const std::string& input, const KernelLink::EventFn& events) {
        json r = s.raw("", events);
        ++replies;
        EXPECT_FALSE(r.value("cmd", "") == "load" && r.dump().find("leak-") != std::string::npos)
            << "input " << i << ": a payload's line ran: " << shown(input) << "\n" << r.dump();
        return r;
    };
    // reads replies up to the marker's: each has the next seq (the harness checks)
    auto until_marker = [&](uint32_t i, const std::string& input) {
        std::string name = "'sync-" + std::to_string(i) + "'";
        json r = json::object();
        for (uint32_t read = 0; read < 64 && r.value("error", "").find(name) == std::string::npos; ++read) {
            r = reply(i, input, on_event);
            // a random line read as a refused upload header drops what follows, the marker perhaps:
            // a second marker, sent after that reply, is the one awaited
            if (r.value("discarded", 0) > 0) {
                name = "'resync-" + std::to_string(i) + "'";
                s.send("load resync-" + std::to_string(i) + "\n");
            }
        }
        ASSERT_NE(r.value("error", "").find(name), std::string::npos) << "input " << i << " did not let the marker through: " << shown(input);
        ASSERT_FALSE(s.exit_info()) << "input " << i << ": " << shown(input);
    };
    for (uint32_t i = 0; i < inputs && !HasFatalFailure(); ++i) {
        std::string input;
        payload.clear();
        marker = "load sync-" + std::to_string(i) + f.end();
        switch (f.below(7)) {
        case 0: input = f.line() + f.end(); break;
        case 1: input = f.mutate(f.line()) + f.end(); break;
        case 2: {  // as a protocol client: the header alone, the bytes once the kernel is ready
            const std::string& text = f.chance(50) ? scene : world;
            payload = f.chance(50) ? f.mutate(text) : text;
            if (f.chance(50)) payload = f.with_leaks(payload, i);
            input = f.upload_header(payload) + f.end_before(payload);
            ++uploads;
            marker_again = false;
            s.send(input);
            reply(i, input, on_event);  // the header's one reply: the upload's, or why not
            s.send(marker);
            until_marker(i, input);
            continue;
        }
        case 3: {  // an impatient client: the header and the bytes at once, not waiting for `ready`
            payload = f.chance(50) ? scene : world;
            if (f.chance(50)) payload = f.with_leaks(payload, i);
            input = f.upload_header(payload, false) + f.end_before(payload) + payload;
            ++uploads;
            impatient = true;
            s.send(input);
            reply(i, input, on_event);  // the upload's reply (its ready event seen on the way)
            impatient = false;
            s.send(marker);
            until_marker(i, input);
            continue;
        }
        case 4: {  // an impatient client whose header is refused: its payload is dropped, never run
            payload = f.with_leaks(f.chance(50) ? scene : world, i);
            input = f.refused_header(payload) + f.end_before(payload) + payload;
            ++refused;
            s.send(input);
            const json r = reply(i, input, on_event);
            EXPECT_FALSE(r.value("ok", true)) << shown(input) << "\n" << r.dump();
            EXPECT_EQ(r.value("discarded", -1), int(payload.size())) << shown(input) << "\n" << r.dump();
            s.send(marker);
            until_marker(i, input);
            continue;
        }
        case 5: {  // long work, stopped by the marker's line at a random point (or let finish)
            const std::string frames = std::to_string(1 + f.below(4));
            const std::string work[] = {"play " + frames + " fast-affine", "bench " + frames + " fast-affine", "play " + frames + " exact",
                                        "selftest 1000"};
            const std::string cmd = work[f.below(f.chance(5) ? 4 : 3)];
            input = "mode modex" + f.end() + "load cube.scene" + f.end() + cmd + f.end();
            const int stop_at = int(f.below(5)) - 1;  // -1: with the command; else after that many frames
            s.send(stop_at < 0 ? input + marker : input);
            reply(i, input, nullptr), reply(i, input, nullptr);
            int events = 0;
            bool sent = stop_at < 0;
            const json r = reply(i, input, [&](const json& e) {
                ++events;
                if (!sent && events > stop_at && e.value("event", "") != "progress") sent = true, s.send(marker);
            });
            if (!sent) s.send(marker);
            ASSERT_TRUE(r.value("ok", false)) << shown(input) << "\n" << r.dump();
            const bool cut = r["interrupted"].get<bool>();
            (cut ? stopped : whole) += 1;
            if (r.contains("frames")) {  // play, bench: one event a whole frame; all asked unless stopped
                EXPECT_EQ(r["frames"].get<int>(), events) << shown(input) << "\n" << r.dump();
                EXPECT_EQ(cut, r["frames"].get<int>() < r["frames_asked"].get<int>()) << shown(input) << "\n" << r.dump();
            } else if (!cut) {  // selftest: every loop, every case, unless stopped
                EXPECT_EQ(r["loops"].size(), nasm_loops) << shown(input) << "\n" << r.dump();
                for (const json& l : r["loops"]) EXPECT_EQ(l["cases"], r["cases"]) << shown(input) << "\n" << r.dump();
            }
            until_marker(i, input);
            continue;
        }
        default: {
            for (uint32_t n = 1 + f.below(40), k = 0; k < n; ++k) input += char(f.below(256));
            input += f.end();
        }
        }
        if (ends_session(input)) input = "hello" + f.end();
        // the input and the marker at once
        marker_again = true;
        s.send(input + marker);
        until_marker(i, input);
    }
    EXPECT_GT(taken, 0u) << "some uploads were taken";
    EXPECT_GT(refused, 0u);
    EXPECT_GT(stopped, 0u) << "some long work was stopped";
    EXPECT_GT(whole, 0u) << "some long work ran whole";
    std::printf("  %u inputs (%u uploads, %u taken, %u refused with their payloads; long work %u stopped, %u whole), %u replies, seed %u\n",
                inputs, uploads, taken, refused, stopped, whole, replies, seed);
}

}  // namespace
