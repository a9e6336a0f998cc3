// One booted kernel under the harness: QEMU, the serial protocol and QMP together, with every
// failure reported with its context (the last serial lines and QEMU's own messages).
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "qemu/lib/ordered_json.h"

#include "qemu/lib/host_image.h"
#include "qemu/lib/paths.h"
#include "qemu/harness/kernel_link.h"
#include "qemu/harness/process.h"
#include "qemu/harness/qmp.h"

namespace harness {


// An ELF's symbols with an address (nm -P): the name as nm gives it, its type letter, its address.
struct ElfSymbol {
    std::string name;
    char type;
    uint64_t address;
};
std::vector<ElfSymbol> elf_symbols(const std::string& elf);
// The address of a symbol in an ELF, or 0 where it has none.
uint64_t elf_symbol(const std::string& elf, const std::string& name);

struct SessionOptions {
    Emulator emulator = Emulator::Qemu;  // Bochs: medium Cdrom; no screendump, no send-key
    Firmware firmware = Firmware::Bios;  // QEMU's (UEFI: an ISO, medium Cdrom or Usb)
    BootMedium medium = BootMedium::Kernel;
    std::string image;                 // empty: build/kernel/modexlab.elf, or build/modexlab.iso for CD/USB
    std::string append = "boot=serve"; // -kernel only; an ISO boots its GRUB menu's default entry
    std::vector<std::string> modules;  // -kernel only: -initrd entries, each "PATH" or "PATH NAME"
    bool display = false;              // a QEMU window (for people watching)
    bool icount = false;
    std::string cpu;                   // QEMU's -cpu model (486, pentium, ...); empty: its default, a P6
    int memory_mib = 0;                // -m (Bochs: megs); 0: 128 MiB (QEMU's UEFI: 256)
    std::string plugin;                // QEMU's -plugin SPEC (the timing model's: docs/cycles.md); empty: none
    std::string name = "session";      // the run directory is build/runs/NAME
    std::chrono::milliseconds boot_timeout{60000};
    std::chrono::milliseconds command_timeout{30000};
};

class Session {
public:
    explicit Session(SessionOptions options);  // boots and waits for the boot line
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    const json& boot_line() const { return boot_line_; }

    // The reply to `line`, ok true or false. Throws KernelFault on a CPU exception (after QEMU has
    // exited, see exit_info()), HarnessError on any protocol failure, a timeout or QEMU's end.
    json command(const std::string& line, const KernelLink::EventFn& on_event = nullptr);
    // As command(), but an ok:false reply is a failure too.
    json ok(const std::string& line, const KernelLink::EventFn& on_event = nullptr);
    // Sends bytes as they are (malformed input tests) and reads one reply (events to `on_event`).
    json raw(const std::string& bytes, const KernelLink::EventFn& on_event = nullptr);
    // Sends bytes as they are and reads nothing (from an event callback: a line that interrupts the
    // command in progress).
    void send(const std::string& bytes);

    // `scene BYTES CRC32`, then the text once the kernel is ready for it: the reply (ok true or
    // false; a refused header's without the text sent).
    json upload_scene(const std::string& text);
    // `file NAME BYTES CRC32`, then the bytes, likewise.
    json upload_file(const std::string& name, const std::string& bytes);

    // A key pressed and released on the PS/2 keyboard (QMP send-key; `qcode` as QEMU names keys:
    // "spc", "h", "f1", "right", ...).
    void send_key(const std::string& qcode);
    // The next event the kernel sends unasked named `event` (KernelLink::wait_event); the events
    // before it go to on_other (without it, any other line is a failure).
    json wait_event(const std::string& event, const KernelLink::EventFn& on_other = {});

    // QMP stop, screendump (PNG, saved as RUN_DIR/NAME.png), cont. Not `kept`: a PPM, read and
    // removed, which spares QEMU the compression (for a comparison that saves its pictures only
    // where they differ).
    RgbImage screendump(const std::string& name, bool kept = true);
    // screendump, decoded to palette indices for `mode`; throws when it does not decode.
    IndexImage screenshot(const std::string& name, ScreenMode mode, const raster::Palette& palette, bool kept = true);
    // `readback PAGE`, decoded and checked.
    IndexImage readback(int page);
    // `readback PAGE crc`: the CRC-32 of the page's indices alone (as crc32_of computes a picture's).
    uint32_t readback_crc(int page);

    // Waits for QEMU to end (after `exit`); throws if it is still running after `timeout`.
    ExitInfo wait_exit(std::chrono::milliseconds timeout = std::chrono::seconds(10));
    std::optional<ExitInfo> exit_info() { return qemu_->poll_exit(); }

    const std::string& run_dir() const { return run_dir_; }
    std::string context() const;

private:
    [[noreturn]] void fail(const std::string& what);
    const char* emulator_name() const { return options_.emulator == Emulator::Bochs ? "Bochs" : "QEMU"; }
    // Runs one exchange with the kernel; failures get QEMU's fate and the context added.
    json guarded(const std::function<json()>& exchange);

    SessionOptions options_;
    std::string run_dir_;
    std::unique_ptr<QemuProcess> qemu_;
    KernelLink link_;
    QmpClient qmp_;
    json boot_line_;
};

}  // namespace harness
