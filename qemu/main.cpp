// modexlab: the host harness's command line. `run` boots the kernel and shows every pattern with
// screenshots checked against the host's rendering; `exec` sends the given commands and prints the replies.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <iostream>
#include <string>
#include <vector>

#include "qemu/error.h"
#include "qemu/image.h"
#include "qemu/session.h"

namespace {

using namespace harness;

const char* USAGE =
    "usage: modexlab run  [BOOT] [--out DIR]\n"
    "       modexlab exec [BOOT] [--full] COMMAND...\n"
    "BOOT:  --kernel ELF [--append OPTIONS] | --iso ISO [--usb]   (default: build/kernel/modexlab.elf)\n"
    "       --icount      count guest instructions (rdtsc = instructions executed)\n"
    "run:   boots, says hello, sets Mode X and draws, shows and screenshots every test pattern;\n"
    "       each screendump and readback must equal the host's rendering. Screenshots go to DIR\n"
    "       (default build/run).\n"
    "exec:  sends each COMMAND (one kernel command line, quote it) and prints the JSON replies;\n"
    "       'screendump:NAME' saves a screendump as NAME.png in the run directory instead;\n"
    "       'scene:FILE' uploads a scene file (scene BYTES CRC32 and the bytes).\n"
    "       Long \"data\" fields are shortened unless --full.\n";

struct Args {
    std::string verb;
    SessionOptions session;
    std::string out;
    bool full = false;
    std::vector<std::string> commands;
};

[[noreturn]] void usage_error(const std::string& why) {
    std::fprintf(stderr, "modexlab: %s\n%s", why.c_str(), USAGE);
    std::exit(2);
}

Args parse(int argc, char** argv) {
    if (argc < 2) usage_error("no verb");
    Args a;
    a.verb = argv[1];
    if (a.verb == "-h" || a.verb == "--help") {
        std::fputs(USAGE, stdout);
        std::exit(0);
    }
    if (a.verb != "run" && a.verb != "exec") usage_error("unknown verb '" + a.verb + "'");
    a.out = build_dir() + "/run";
    for (int i = 2; i < argc; ++i) {
        std::string s = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usage_error(s + " needs a value");
            return argv[++i];
        };
        if (s == "--kernel") {
            a.session.medium = BootMedium::Kernel;
            a.session.image = value();
        } else if (s == "--iso") {
            if (a.session.medium == BootMedium::Kernel) a.session.medium = BootMedium::Cdrom;
            a.session.image = value();
        } else if (s == "--usb") {
            a.session.medium = BootMedium::Usb;
        } else if (s == "--append") {
            a.session.append = value();
        } else if (s == "--icount") {
            a.session.icount = true;
        } else if (s == "--out" && a.verb == "run") {
            a.out = value();
        } else if (s == "--full" && a.verb == "exec") {
            a.full = true;
        } else if (s.rfind("--", 0) == 0) {
            usage_error("unknown option " + s);
        } else if (a.verb == "exec") {
            a.commands.push_back(s);
        } else {
            usage_error("unexpected argument '" + s + "'");
        }
    }
    if (a.session.medium == BootMedium::Usb && a.session.image.empty()) a.session.image = build_dir() + "/modexlab.iso";
    if (a.verb == "exec" && a.commands.empty()) usage_error("exec needs at least one COMMAND");
    return a;
}

std::string shorten_data(json reply, bool full) {
    if (!full && reply.contains("data") && reply["data"].is_string()) {
        std::string d = reply["data"];
        if (d.size() > 48) reply["data"] = d.substr(0, 48) + "...(" + std::to_string(d.size()) + " chars)";
    }
    return reply.dump();
}

int run(Args& a) {
    a.session.name = "run";
    std::printf("modexlab run: booting %s in QEMU (TCG%s, headless)\n",
                a.session.image.empty() ? (build_dir() + "/kernel/modexlab.elf").c_str() : a.session.image.c_str(),
                a.session.icount ? ", icount" : "");
    std::fflush(stdout);
    Session s(a.session);
    std::filesystem::create_directories(a.out);

    json hello = s.ok("hello");
    const json& cpu = hello["cpu"];
    std::printf("hello: modexlab %s on %s (family %d, model %d); TSC %.3f MHz; mode %s\n",
                hello["version"].get<std::string>().c_str(), cpu["vendor"].get<std::string>().c_str(),
                cpu["family"].get<int>(), cpu["model"].get<int>(), hello["tsc_hz"].get<double>() / 1e6,
                hello["mode"].get<std::string>().c_str());
    std::printf("       features: %s\n", cpu["features"].dump().c_str());

    json mode = s.ok("mode modex");
    std::printf("mode modex: %dx%d, %d pages, set in %llu TSC ticks\n", mode["width"].get<int>(), mode["height"].get<int>(),
                mode["pages"].get<int>(), mode["ticks"].get<unsigned long long>());
    const raster::Palette& palette = raster::palette(raster::PaletteId::Default);

    int failures = 0;
    std::printf("%-8s %-4s %-12s %-30s %s\n", "pattern", "page", "draw ticks", "screendump vs host", "readback vs host");
    for (int i = 0; i < raster::PATTERN_COUNT; ++i) {
        auto pattern = raster::Pattern(i);
        std::string name = raster::pattern_name(pattern);
        int page = i % 3;
        json drawn = s.ok("pattern " + name + " " + std::to_string(page));
        s.ok("flip " + std::to_string(page));
        IndexImage expected = render_pattern(pattern, MODE_X);
        IndexImage shot = s.screenshot("pattern-" + name, MODE_X, palette);
        std::filesystem::copy_file(s.run_dir() + "/pattern-" + name + ".png", a.out + "/pattern-" + name + ".png",
                                   std::filesystem::copy_options::overwrite_existing);
        Comparison by_dump = compare(shot, expected);
        Comparison by_readback = compare(s.readback(page), expected);
        std::printf("%-8s %-4d %-12llu %-30s %s\n", name.c_str(), page, drawn["ticks"].get<unsigned long long>(),
                    by_dump.equal() ? "equal" : by_dump.summary().c_str(), by_readback.equal() ? "equal" : by_readback.summary().c_str());
        if (!by_dump.equal()) {
            ++failures;
            std::printf("         %s\n", write_mismatch(a.out, "pattern-" + name, shot, expected, palette).c_str());
        }
        if (!by_readback.equal()) ++failures;
        std::fflush(stdout);
    }
    s.ok("exit 0");
    ExitInfo e = s.wait_exit();
    std::printf("screenshots (640x480, QEMU screendump): %s/pattern-*.png\n", a.out.c_str());
    std::printf("serial log: %s/serial.log\n%s\n", s.run_dir().c_str(), e.describe().c_str());
    if (failures) std::printf("modexlab run: %d comparison(s) FAILED\n", failures);
    return failures || !(e.exited && e.status == 1) ? 1 : 0;
}

int exec(Args& a) {
    a.session.name = "exec";
    Session s(a.session);
    std::printf("%s\n", s.boot_line().dump().c_str());
    bool all_ok = true;
    for (const std::string& c : a.commands) {
        if (c.rfind("screendump:", 0) == 0) {
            std::string name = c.substr(11);
            RgbImage img = s.screendump(name);
            std::printf("screendump %s/%s.png (%dx%d)\n", s.run_dir().c_str(), name.c_str(), img.width, img.height);
            continue;
        }
        json reply;
        if (c.rfind("scene:", 0) == 0) {
            std::ifstream in(c.substr(6), std::ios::binary);
            if (!in) throw HarnessError("cannot open " + c.substr(6));
            std::stringstream text;
            text << in.rdbuf();
            reply = s.upload_scene(text.str());
        } else {
            reply = s.command(c);
        }
        std::printf("%s\n", shorten_data(reply, a.full).c_str());
        std::fflush(stdout);
        all_ok = all_ok && reply["ok"].get<bool>();
        if (reply.value("cmd", "") == "exit" && reply["ok"].get<bool>()) {
            std::printf("%s\n", s.wait_exit().describe().c_str());
            return all_ok ? 0 : 1;
        }
    }
    return all_ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    Args a = parse(argc, argv);
    try {
        return a.verb == "run" ? run(a) : exec(a);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "modexlab %s: FAILED: %s\n", a.verb.c_str(), e.what());
        return 1;
    }
}
