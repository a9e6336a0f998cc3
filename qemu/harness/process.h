// Starting qemu-system-i386 (TCG, headless, -no-reboot, isa-debug-exit, COM1 and QMP on Unix sockets),
// or Bochs (the ISO from its CD drive, COM1 on a TCP socket, no QMP), watching it, and always
// killing it.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "qemu/harness/channel.h"

namespace harness {

enum class BootMedium { Kernel, Cdrom, Usb };
enum class Emulator { Qemu, Bochs };
// QEMU's firmware: SeaBIOS (a PC with a BIOS), or OVMF, UEFI without a CSM: 64-bit (Debian's ovmf,
// qemu-system-x86_64, the pc machine) or 32-bit (ovmf-ia32, qemu-system-i386, q35 with SMM: its
// build has Secure Boot, off with the empty variable store).
enum class Firmware { Bios, Uefi64, Uefi32 };

struct QemuConfig {
    Emulator emulator = Emulator::Qemu;  // Bochs: the CD (an ISO) only, no icount, no display
    Firmware firmware = Firmware::Bios;  // QEMU's
    BootMedium medium = BootMedium::Kernel;
    std::string image;       // the ELF (-kernel) or the ISO (CD or USB stick)
    std::string append;      // multiboot command line, -kernel only
    std::vector<std::string> modules;  // -kernel only: Multiboot modules (-initrd), each "PATH" or "PATH NAME"
    std::string display;     // a window's display backend (window_backend()); empty: none
    bool icount = false;     // -icount shift=0,align=off,sleep=off: rdtsc counts guest instructions
    std::string cpu;         // -cpu MODEL (Bochs: cpu model=MODEL); empty: the emulator's default
    int memory_mib = 0;      // -m (Bochs: megs); 0: 128 MiB (QEMU's UEFI: 256)
    std::string run_dir;     // serial.log (written as the harness reads) and qemu.log go here (Bochs: bochsrc, bochs.log, bochs.out)
    std::vector<std::string> extra_args;
};

// How QEMU ended. isa-debug-exit makes the status (v << 1) | 1 for a value v the kernel wrote.
struct ExitInfo {
    bool exited = false;  // false: killed by a signal
    int status = 0;
    int signal = 0;
    Emulator emulator = Emulator::Qemu;
    std::string describe() const;  // what the status means for modexlab (docs/protocol.md)
};

// A shell command's standard output, and whether it exited 0.
bool command_output(const std::string& cmd, std::string* out);

// The display backend a QEMU window opens with: gtk where QEMU has it, else sdl. HarnessError, saying
// what to do, where no graphical session is named (DISPLAY, WAYLAND_DISPLAY) or QEMU has neither
// backend (Debian ships them in qemu-system-gui).
std::string window_backend();

// The argument vector (without the program name) for the given sockets.
std::vector<std::string> qemu_arguments(const QemuConfig& config, const std::string& serial_socket,
                                        const std::string& qmp_socket);
// Bochs's configuration (bochsrc) for the ISO, COM1 connecting to 127.0.0.1:port: Debian's ROM
// BIOS and LGPL VGA BIOS, 128 MiB, no sound (its mixer thread aborts where ALSA has no device),
// the RFB display library (the package's only one without X) never waiting for a viewer, emulated
// time by instructions (20 million a second: the GRUB menu's wait and the UART's pace pass in
// fewer instructions).
std::string bochs_configuration(const QemuConfig& config, int serial_port);

class QemuProcess {
public:
    // Listens on two fresh Unix sockets, starts QEMU as their client and accepts both connections.
    // Throws HarnessError (with QEMU's own messages) when it cannot.
    explicit QemuProcess(const QemuConfig& config);
    ~QemuProcess();
    QemuProcess(const QemuProcess&) = delete;
    QemuProcess& operator=(const QemuProcess&) = delete;

    LineChannel take_serial() { return std::move(serial_); }
    LineChannel take_qmp() { return std::move(qmp_); }

    std::optional<ExitInfo> poll_exit();
    std::optional<ExitInfo> wait_exit(std::chrono::milliseconds timeout);
    void kill();  // SIGKILL and reap; safe to call twice
    bool running() const { return pid_ > 0 && !exit_; }

    std::string log_tail(size_t lines = 10) const;  // QEMU's stderr/stdout

private:
    pid_t pid_ = -1;
    std::optional<ExitInfo> exit_;
    std::string socket_dir_;
    std::string log_path_;
    int stdin_fd_ = -1;  // Bochs: its debugger's input, "c" (continue) then kept open
    Emulator emulator_ = Emulator::Qemu;
    void start_bochs(const QemuConfig& config);
    LineChannel serial_;
    LineChannel qmp_;
};

}  // namespace harness
