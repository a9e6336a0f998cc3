// Session: boot, talk, snapshot, and on any failure kill QEMU and say what happened around it.
#include "qemu/harness/session.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "kernel/lib/encode.h"
#include "qemu/harness/readback.h"

namespace harness {

std::vector<ElfSymbol> elf_symbols(const std::string& elf) {
    // whole, then line by line: C++ symbols (lambdas in templates) run to hundreds of characters
    std::string text;
    command_output("nm -P " + elf + " 2>/dev/null", &text);
    std::istringstream lines(text);
    std::vector<ElfSymbol> symbols;
    for (std::string line; std::getline(lines, line);) {
        std::istringstream fields(line);
        std::string symbol, type, address;
        if (fields >> symbol >> type >> address) symbols.push_back(ElfSymbol{symbol, type[0], std::stoull(address, nullptr, 16)});
    }
    return symbols;
}

uint64_t elf_symbol(const std::string& elf, const std::string& name) {
    uint64_t found = 0;
    for (const ElfSymbol& s : elf_symbols(elf))
        if (s.name == name) found = s.address;
    return found;
}

Session::Session(SessionOptions options) : options_(std::move(options)) {
    run_dir_ = build_dir() + "/runs/" + options_.name;
    std::filesystem::remove_all(run_dir_);
    std::filesystem::create_directories(run_dir_);
    QemuConfig config;
    config.medium = options_.medium;
    config.image = !options_.image.empty() ? options_.image
                   : options_.medium == BootMedium::Kernel ? build_dir() + "/kernel/modexlab.elf"
                                                            : build_dir() + "/modexlab.iso";
    config.append = options_.append;
    config.modules = options_.modules;
    if (options_.display) config.display = window_backend();
    config.icount = options_.icount;
    config.cpu = options_.cpu;
    config.memory_mib = options_.memory_mib;
    if (!options_.plugin.empty()) config.extra_args = {"-plugin", options_.plugin};
    config.run_dir = run_dir_;
    config.emulator = options_.emulator;
    config.firmware = options_.firmware;
    qemu_ = std::make_unique<QemuProcess>(config);
    link_ = KernelLink(qemu_->take_serial());
    if (options_.emulator == Emulator::Qemu) qmp_ = QmpClient(qemu_->take_qmp());
    try {
        if (options_.emulator == Emulator::Qemu) qmp_.handshake(std::chrono::seconds(20));
        boot_line_ = link_.wait_boot(options_.boot_timeout);
    } catch (const HarnessError& e) {
        fail(std::string("boot failed: ") + e.what());
    }
}

Session::~Session() = default;  // QemuProcess kills QEMU

std::string Session::context() const {
    std::string s = "\nlast serial lines (" + run_dir_ + "/serial.log):\n" + link_.transcript_tail();
    std::string log = qemu_ ? qemu_->log_tail() : "";
    if (!log.empty()) s += std::string(emulator_name()) + " said:\n" + log;
    return s;
}

void Session::fail(const std::string& what) {
    std::string status;
    if (qemu_) {
        auto e = qemu_->wait_exit(std::chrono::seconds(1));  // a closed line usually means QEMU is ending
        status = e ? "\n" + e->describe() : std::string("\n") + emulator_name() + " was still running: killed";
        qemu_->kill();
    }
    throw HarnessError(what + status + context());
}

json Session::guarded(const std::function<json()>& exchange) {
    try {
        return exchange();
    } catch (const KernelFault& f) {
        auto e = qemu_->wait_exit(std::chrono::seconds(5));
        std::string status = e ? e->describe() : std::string(emulator_name()) + " did not exit after the fault: killed";
        qemu_->kill();
        throw KernelFault(std::string(f.what()) + "\n" + status + context(), f.report());
    } catch (const HarnessError& e) {
        fail(e.what());
    }
}

json Session::command(const std::string& line, const KernelLink::EventFn& on_event) {
    return guarded([&] { return link_.request(line, options_.command_timeout, on_event); });
}

json Session::ok(const std::string& line, const KernelLink::EventFn& on_event) {
    json reply = command(line, on_event);
    if (!reply["ok"].get<bool>()) fail("'" + line + "' failed: " + reply.value("error", "(no error text)"));
    return reply;
}

void Session::send(const std::string& bytes) { link_.send_raw(bytes); }

json Session::raw(const std::string& bytes, const KernelLink::EventFn& on_event) {
    return guarded([&] {
        if (!bytes.empty()) link_.send_raw(bytes);
        return link_.read_reply("raw input", options_.command_timeout, on_event);
    });
}

json Session::upload_scene(const std::string& text) {
    char crc[16];
    std::snprintf(crc, sizeof crc, "0x%08x", lib::crc32(0, reinterpret_cast<const uint8_t*>(text.data()), text.size()));
    return guarded([&] { return link_.upload("scene " + std::to_string(text.size()) + " " + crc, text, options_.command_timeout); });
}

json Session::upload_file(const std::string& name, const std::string& bytes) {
    char crc[16];
    std::snprintf(crc, sizeof crc, "0x%08x", lib::crc32(0, reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()));
    return guarded([&] { return link_.upload("file " + name + " " + std::to_string(bytes.size()) + " " + crc, bytes, options_.command_timeout); });
}

void Session::send_key(const std::string& qcode) {
    if (options_.emulator != Emulator::Qemu) fail("send-key " + qcode + ": only QEMU has QMP");
    try {
        qmp_.execute("send-key", {{"keys", json::array({{{"type", "qcode"}, {"data", qcode}}})}});
    } catch (const HarnessError& e) {
        fail("send-key " + qcode + ": " + e.what());
    }
}

json Session::wait_event(const std::string& event, const KernelLink::EventFn& on_other) {
    return guarded([&] { return link_.wait_event(event, options_.command_timeout, on_other); });
}

RgbImage Session::screendump(const std::string& name, bool kept) {
    const std::string format = kept ? "png" : "ppm", path = run_dir_ + "/" + name + "." + format;
    if (options_.emulator != Emulator::Qemu) fail("screendump " + name + ": only QEMU has QMP (read pages back instead)");
    try {
        qmp_.execute("stop");
        qmp_.execute("screendump", {{"filename", path}, {"format", format}});
        qmp_.execute("cont");
        RgbImage image = load_image(path);
        if (!kept) std::filesystem::remove(path);
        return image;
    } catch (const HarnessError& e) {
        fail(std::string("screendump ") + name + ": " + e.what());
    }
}

IndexImage Session::screenshot(const std::string& name, ScreenMode mode, const raster::Palette& palette, bool kept) {
    RgbImage dump = screendump(name, kept);
    DecodeResult d = decode_screendump(dump, palette, mode);
    if (!d.ok) fail("screendump " + run_dir_ + "/" + name + (kept ? ".png: " : ": ") + d.error);
    return d.image;
}

IndexImage Session::readback(int page) {
    json reply = ok("readback " + std::to_string(page));
    try {
        return decode_readback(reply);
    } catch (const HarnessError& e) {
        // kept as received: a damaged page is a transport defect to hunt (docs/platform.md)
        const std::string kept = run_dir() + "/readback-damaged-" + std::to_string(reply.value("seq", 0)) + ".json";
        std::ofstream(kept) << reply.dump() << "\n";
        fail(std::string(e.what()) + " (kept: " + kept + ")");
    }
}

uint32_t Session::readback_crc(int page) {
    const json reply = ok("readback " + std::to_string(page) + " crc");
    const std::string crc = reply.value("crc32", "");
    if (crc.size() != 10 || crc.rfind("0x", 0) != 0 || crc.find_first_not_of("0123456789abcdef", 2) != std::string::npos)
        fail("readback " + std::to_string(page) + " crc: no crc32 of the form 0x%08x in " + reply.dump());
    return uint32_t(std::stoul(crc.substr(2), nullptr, 16));
}

ExitInfo Session::wait_exit(std::chrono::milliseconds timeout) {
    auto e = qemu_->wait_exit(timeout);
    if (!e) fail("QEMU still running " + std::to_string(timeout.count()) + " ms after the kernel was told to exit");
    return *e;
}

}  // namespace harness
