// modexlab: the host harness's command line. `run` boots the kernel, shows every pattern and plays
// every demo scene, with screenshots checked against the host's rendering; `exec` sends the given
// commands and prints the replies.
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "qemu/tools/demo_scenes.h"
#include "qemu/tools/trade.h"
#include "qemu/lib/command_line.h"
#include "qemu/lib/error.h"
#include "qemu/lib/host_image.h"
#include "qemu/accuracy/measure.h"
#include "qemu/harness/session.h"

namespace {

using namespace harness;

const char* USAGE =
    "usage: modexlab run  [BOOT] [--out DIR] [--scene NAME|FILE] [--mapper NAME] [--frames N] [--display]\n"
    "       modexlab exec [BOOT] [--full] COMMAND...\n"
    "BOOT:  --kernel ELF [--append OPTIONS] [--module PATH[=NAME]]... | --iso ISO [--usb]\n"
    "                     (default: build/kernel/modexlab.elf; a module's name is its path unless given)\n"
    "       --icount      count guest instructions (rdtsc = instructions executed; run counts them always)\n"
    "       --cpu MODEL   QEMU's -cpu (486, pentium, ...)\n"
    "       --plugin SPEC QEMU's -plugin (the timing model: docs/cycles.md, \"Whole frames\")\n"
    "run:   boots, says hello, sets Mode X; draws, shows and screenshots every test pattern; then\n"
    "       plays every demo scene (or NAME, or a scene file of one's own) for N frames (default 90:\n"
    "       three seconds of its animation) with the mapper (default auto: the scene's budget),\n"
    "       page-flipped, and screenshots the last frame. Each screenshot must equal the host's\n"
    "       rendering. Screenshots go to DIR (default build/run). --display: a QEMU window playing\n"
    "       the demo scene(s) until it is closed. The scene and the mapper are checked before booting.\n"
    "exec:  sends each COMMAND (one kernel command line, quote it) and prints the JSON replies;\n"
    "       'screendump:NAME' saves a screendump as NAME.png in the run directory instead;\n"
    "       'scene:FILE' uploads a scene file (scene BYTES CRC32 and the bytes);\n"
    "       'file:NAME=PATH' uploads a file under NAME (file NAME BYTES CRC32 and the bytes);\n"
    "       'key:NAME' presses a key on the PS/2 keyboard (QEMU's names: b, esc, right, ...), for the\n"
    "       show, which plays until the first command (--append boot=demo); 'wait:EVENT' prints the\n"
    "       kernel's events until one named EVENT (bench_row, bench_done, key, ...).\n"
    "       Events a command sends before its reply (play's frames) are printed as they come.\n"
    "       Long \"data\" fields are shortened unless --full. Exit status: 1 if a reply was not ok,\n"
    "       else the kernel's own exit code where an `exit N` ended it, else 0.\n";

struct Args {
    std::string verb;
    SessionOptions session;
    std::string out;
    bool full = false;
    std::vector<std::string> commands;
    std::string scene, mapper = "auto";
    std::string scene_file;  // --scene named a file, not a demo scene
    int frames = 90;
};

// The settings a command line asks for; none when it asks for the usage. BOOT's options go with
// either verb, the others with one.
std::optional<Args> parse(const std::vector<std::string>& words) {
    if (words.empty()) throw UsageError("no verb");
    Args a;
    a.verb = words[0];
    if (a.verb == "-h" || a.verb == "--help") return std::nullopt;
    if (a.verb != "run" && a.verb != "exec") throw UsageError("unknown verb '" + a.verb + "'");
    const bool run = a.verb == "run";
    std::vector<std::string_view> with_value = {"--kernel", "--iso", "--append", "--module", "--cpu", "--plugin"}, flags = {"--usb", "--icount"};
    if (run) {
        with_value.insert(with_value.end(), {"--out", "--scene", "--mapper", "--frames"});
        flags.push_back("--display");
    } else {
        flags.push_back("--full");
    }
    const CommandLine args = parse_command_line(std::vector<std::string>(words.begin() + 1, words.end()), with_value, flags);
    if (args.help()) return std::nullopt;

    // BOOT: a kernel, or an ISO as a CD-ROM or a USB stick (default: the one make builds)
    if (args.has("--kernel") && args.has("--iso")) throw UsageError("--kernel and --iso are alternatives");
    if (args.has("--kernel") && args.has("--usb")) throw UsageError("--usb goes with --iso");
    a.session.image = args.text(args.has("--iso") ? "--iso" : "--kernel");
    if (args.has("--iso")) a.session.medium = BootMedium::Cdrom;
    if (args.has("--usb")) a.session.medium = BootMedium::Usb;
    if (a.session.medium == BootMedium::Usb && a.session.image.empty()) a.session.image = build_dir() + "/modexlab.iso";
    a.session.append = args.text("--append");
    a.session.icount = args.has("--icount");
    a.session.cpu = args.text("--cpu");
    a.session.plugin = args.text("--plugin");
    for (const std::string& m : args.texts("--module")) {
        size_t eq = m.find('=');
        a.session.modules.push_back(eq == std::string::npos ? m : m.substr(0, eq) + " " + m.substr(eq + 1));
    }

    if (run) {
        if (!args.positionals().empty()) throw UsageError("unexpected argument '" + args.positionals()[0] + "'");
        a.session.display = args.has("--display");
        a.session.icount = !a.session.display;  // (its figures in instructions; a window plays at the PC's pace)
        if (a.session.display) window_backend();  // (before booting: a display, and QEMU's window for it)
        a.out = args.text("--out", build_dir() + "/run");
        a.scene = args.text("--scene");
        if (!a.scene.empty()) {  // (before booting: a demo scene's name, or a scene file the host reads)
            try {
                a.scene_file = choose_scene(a.scene).demo ? "" : a.scene;
            } catch (const HarnessError& e) {
                throw UsageError(e.what());
            }
            if (!a.scene_file.empty()) load_world_file(a.scene_file);  // (its errors: FILE:LINE: what)
            if (!a.scene_file.empty() && a.session.display) throw UsageError("--display plays the demo scenes; a scene file plays headless");
        }
        a.mapper = args.text("--mapper", a.mapper);
        if (!raster::find_mapper({a.mapper.data(), a.mapper.size()})) throw UsageError(unknown_mapper(a.mapper));
        a.frames = args.integer("--frames", 1, 100000, a.frames);
    } else {
        a.full = args.has("--full");
        a.commands = args.positionals();
        if (a.commands.empty()) throw UsageError("exec needs at least one COMMAND");
    }
    return a;
}

std::string shorten_data(json reply, bool full) {
    if (!full && reply.contains("data") && reply["data"].is_string()) {
        std::string d = reply["data"];
        if (d.size() > 48) reply["data"] = d.substr(0, 48) + "...(" + std::to_string(d.size()) + " chars)";
    }
    return reply.dump();
}

// `run --display`: the boot show in a window, until the window is closed.
int watch(Args& a) {
    a.session.name = "watch";
    a.session.append = "boot=demo mapper=" + a.mapper + (a.scene.empty() ? "" : " scene=" + a.scene + ".scene");
    Session s(a.session);  // (the window is open once the kernel has booted in it)
    std::printf("modexlab run: a QEMU window plays %s with %s; close it to stop\n", a.scene.empty() ? "every demo scene" : a.scene.c_str(),
                a.mapper.c_str());
    std::fflush(stdout);
    ExitInfo e = s.wait_exit(std::chrono::hours(24 * 365));
    std::printf("%s\n", e.describe().c_str());
    return 0;
}

// What make run says of the scenes it played, summed for its closing line.
struct Played {
    int scenes = 0, differ = 0;
    uint64_t frames = 0, pixels = 0, draw_instructions = 0;
    raster::AccuracyMetrics errors;   // the last frames' against the reference, merged
    std::vector<std::string> nothing; // the scenes the mapper drew nothing of
};

// The lines under a scene's row where the mapper refused polygons of its last frame: how many, why,
// and where it refused them all, the demo scenes it draws whole.
void say_refusal(const raster::Mapper& mapper, const raster::RenderStats& stats, std::vector<std::string>* whole) {
    const std::string why = refusal(mapper, stats);
    if (why.empty()) return;
    std::printf("%9s %s %s\n", "", mapper.name, why.c_str());
    if (stats.polygons) return;
    if (whole->empty()) *whole = demo_scenes_drawn_whole(mapper);
    std::string names;
    for (const std::string& n : *whole) names += (names.empty() ? "" : ", ") + n;
    std::printf("%9s the demo scenes it draws whole: %s\n", "", names.empty() ? "none" : names.c_str());
}

// Plays every demo scene (or one, or the scene file) and checks the last frame of each against the
// host's, and measures it against the exact reference.
Played play_scenes(Args& a, Session& s) {
    Played played;
    std::vector<SceneChoice> scenes;
    if (!a.scene_file.empty()) scenes.push_back(choose_scene(a.scene_file));
    for (const DemoScene& d : demo_scenes())
        if (a.scene_file.empty() && (a.scene.empty() || a.scene == d.name)) scenes.push_back(choose_scene(d.name));
    const raster::Mapper& mapper = *raster::find_mapper({a.mapper.data(), a.mapper.size()});
    const bool progress = isatty(1);  // frame counts on a terminal, not in logs
    std::vector<std::string> whole;
    std::printf("\nscenes, %d frames each (%.1f s of animation), drawn with %s\n", a.frames, double(a.frames) / raster::FRAMES_PER_SECOND,
                a.mapper.c_str());
    std::printf("instr/px: drawing instructions a pixel (QEMU icount); max and mean error: the last frame against the exact\n"
                "reference, in footprints (docs/accuracy.md); vs host: the screenshot against the host's drawing with %s\n", a.mapper.c_str());
    std::printf("%-12s %6s %8s %10s %8s %8s %8s  %-28s %s\n", "scene", "frames", "polygons", "pixels", "instr/px", "max err", "mean err", "screenshot",
                "vs host");
    for (size_t i = 0; i < scenes.size(); ++i) {
        const SceneChoice& d = scenes[i];
        const LoadedWorld host = load_world_file(d.path);
        load_scene_in_kernel(s, d, host);
        json last;
        uint64_t draw = 0;
        json r = s.ok("play " + std::to_string(a.frames) + " " + a.mapper, [&](const json& e) {
            last = e;
            draw += e["ticks_draw"].get<uint64_t>();
            if (progress && e["n"].get<int>() % 10 == 9) {
                std::printf("\r  scene %zu/%zu %s: frame %d/%d", i + 1, scenes.size(), d.name.c_str(), e["n"].get<int>() + 1, a.frames);
                std::fflush(stdout);
            }
        });
        if (progress) std::printf("\r%60s\r", "");
        auto frame = world_frame(host, last["frame"].get<int32_t>());
        raster::RenderStats stats;
        IndexImage want = render_world_frame(host, *frame, mapper, home_axis(mapper), &stats);
        const raster::AccuracyMetrics errors = measure_world_frame(host, *frame, mapper, home_axis(mapper));
        std::string stem = "scene-" + d.name;
        RgbImage dump = s.screendump(stem);
        bool same = dump.rgb == screendump_of(want, host.world->palette).rgb && compare(s.readback(last["page"].get<int>()), want).equal();
        std::filesystem::copy_file(s.run_dir() + "/" + stem + ".png", a.out + "/" + stem + ".png", std::filesystem::copy_options::overwrite_existing);
        const uint64_t pixels = r["pixels"].get<uint64_t>();
        std::printf("%-12s %6d %8d %10llu %8s %8s %8s  %-28s %s\n", d.name.c_str(), a.frames, last["polygons"].get<int>(), (unsigned long long)pixels,
                    pixels ? fixed(double(draw) / double(pixels), 2).c_str() : "-", errors.compared ? fixed(errors.max_footprint_error, 3).c_str() : "-",
                    errors.compared ? fixed(errors.mean_footprint_error, 4).c_str() : "-", (a.out + "/" + stem + ".png").c_str(), same ? "equal" : "DIFFERS");
        const json& drawn_by = r["drawn_by"];  // the mappers that drew: several when auto chose
        if (drawn_by.size() > 1 || (drawn_by.size() == 1 && a.mapper != drawn_by[0]["mapper"])) {
            std::string by;
            for (const json& m : drawn_by)
                by += (by.empty() ? "" : ", ") + m["mapper"].get<std::string>() + " " + std::to_string(m["polygons"].get<uint64_t>()) +
                      " polygons (" + std::to_string(pixels ? 100 * m["pixels"].get<uint64_t>() / pixels : 0) + "% of pixels)";
            std::printf("%9s drawn by %s\n", "", by.c_str());
        }
        say_refusal(mapper, stats, &whole);
        if (!same) {
            ++played.differ;
            save_png(a.out + "/" + stem + "-expected.png", screendump_of(want, host.world->palette));
        }
        if (!pixels) played.nothing.push_back(d.name);
        ++played.scenes, played.frames += uint64_t(r["frames"].get<int>()), played.pixels += pixels, played.draw_instructions += draw;
        raster::merge(played.errors, errors);
        std::fflush(stdout);
    }
    raster::finish_metrics(played.errors);
    return played;
}

// The run in one line, as a timedemo gives it: the mapper, what it played, its speed and its error.
void say_played(const std::string& mapper, const Played& p) {
    std::printf("%s: %d scene%s, %llu frames, %s drawing instructions a pixel (icount), error against the exact reference max %s, mean %s "
                "footprints (the last frames); %s\n",
                mapper.c_str(), p.scenes, p.scenes == 1 ? "" : "s", (unsigned long long)p.frames,
                p.pixels ? fixed(double(p.draw_instructions) / double(p.pixels), 2).c_str() : "-",
                p.errors.compared ? fixed(p.errors.max_footprint_error, 3).c_str() : "-", p.errors.compared ? fixed(p.errors.mean_footprint_error, 4).c_str() : "-",
                p.differ ? (std::to_string(p.differ) + " screenshot(s) DIFFER from the host's").c_str() : "every screenshot equal to the host's");
    std::string nothing;
    for (const std::string& n : p.nothing) nothing += (nothing.empty() ? "" : ", ") + n;
    if (!nothing.empty()) std::printf("modexlab run: %s drew nothing of %s\n", mapper.c_str(), nothing.c_str());
}

int run(Args& a) {
    if (a.session.display) return watch(a);
    a.session.name = "run";
    std::printf("modexlab run: booting %s in QEMU (TCG%s, headless)\n",
                a.session.image.empty() ? (build_dir() + "/kernel/modexlab.elf").c_str() : a.session.image.c_str(),
                a.session.icount ? ", icount" : "");
    std::fflush(stdout);
    Session s(a.session);
    std::filesystem::create_directories(a.out);

    json hello = s.ok("hello");
    const json& cpu = hello["cpu"];
    const std::string clock = hello["clock"]["name"] == "tsc" ? "TSC" : "PIT";
    std::printf("hello: modexlab %s on %s (family %d, model %d: %s), the %s build; clock %s %.3f MHz; mode %s\n",
                hello["version"].get<std::string>().c_str(), cpu["vendor"].get<std::string>().c_str(),
                cpu["family"].get<int>(), cpu["model"].get<int>(), hello["cpu_class"].get<std::string>().c_str(),
                hello["isa"].get<std::string>().c_str(), clock.c_str(), hello["clock"]["hz"].get<double>() / 1e6,
                hello["mode"].get<std::string>().c_str());
    std::printf("       features: %s\n", cpu["features"].dump().c_str());

    json mode = s.ok("mode modex");
    std::printf("mode modex: %dx%d, %d pages, set in %llu instructions\n", mode["width"].get<int>(), mode["height"].get<int>(),
                mode["pages"].get<int>(), mode["ticks"].get<unsigned long long>());
    const raster::Palette& palette = raster::palette(raster::PaletteId::Default);

    int failures = 0;
    std::printf("%-8s %-4s %-12s %-30s %s\n", "pattern", "page", "draw instr", "screendump vs host", "readback vs host");
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
    const Played played = play_scenes(a, s);
    failures += played.differ;
    s.ok("exit 0");
    ExitInfo e = s.wait_exit();
    std::printf("screenshots (640x480, QEMU screendump): %s/pattern-*.png, %s/scene-*.png\n", a.out.c_str(), a.out.c_str());
    std::printf("serial log: %s/serial.log\n%s\n", s.run_dir().c_str(), e.describe().c_str());
    say_played(a.mapper, played);
    if (failures) std::printf("modexlab run: %d comparison(s) FAILED\n", failures);
    return failures || !played.nothing.empty() || !(e.exited && e.status == 1) ? 1 : 0;
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
        if (c.rfind("key:", 0) == 0) {
            s.send_key(c.substr(4));
            std::printf("key %s\n", c.substr(4).c_str());
            continue;
        }
        if (c.rfind("wait:", 0) == 0) {
            auto print = [](const json& event) {
                std::printf("%s\n", event.dump().c_str());
                std::fflush(stdout);
            };
            print(s.wait_event(c.substr(5), print));
            continue;
        }
        json reply;
        if (c.rfind("scene:", 0) == 0) {
            reply = s.upload_scene(read_whole_file(c.substr(6)));
        } else if (c.rfind("file:", 0) == 0) {
            size_t eq = c.find('=');
            if (eq == std::string::npos) throw HarnessError("'" + c + "': file:NAME=PATH");
            reply = s.upload_file(c.substr(5, eq - 5), read_whole_file(c.substr(eq + 1)));
        } else {
            reply = s.command(c, [&](const json& event) {
                std::printf("%s\n", event.dump().c_str());
                std::fflush(stdout);
            });
        }
        std::printf("%s\n", shorten_data(reply, a.full).c_str());
        std::fflush(stdout);
        all_ok = all_ok && reply["ok"].get<bool>();
        if (reply.value("cmd", "") == "exit" && reply["ok"].get<bool>()) {
            const ExitInfo e = s.wait_exit();
            std::printf("%s\n", e.describe().c_str());
            // the kernel's own exit code (isa-debug-exit: status 2 code + 1, codes 0..63), else 1
            const bool by_code = e.exited && e.status % 2 == 1 && (e.status >> 1) <= 0x3F;
            return !all_ok ? 1 : by_code ? e.status >> 1 : 1;
        }
    }
    return all_ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    return run_cli("modexlab", USAGE, argc, argv, [](const std::vector<std::string>& words) {
        std::optional<Args> a = parse(words);
        if (!a) return show_usage(USAGE);
        try {
            return a->verb == "run" ? run(*a) : exec(*a);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "modexlab %s: FAILED: %s\n", a->verb.c_str(), e.what());
            return 1;
        }
    });
}
