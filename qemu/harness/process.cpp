// fork/exec of QEMU (or Bochs) with a death signal tied to the harness, socket rendezvous, exit decoding.
#include "qemu/harness/process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <netinet/in.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "qemu/lib/error.h"

namespace harness {

namespace {

std::string errno_text(const std::string& what) { return what + ": " + std::strerror(errno); }

constexpr const char* OVMF64 = "/usr/share/ovmf/OVMF.fd";
constexpr const char* OVMF32_CODE = "/usr/share/OVMF/OVMF32_CODE_4M.secboot.fd";
constexpr const char* OVMF32_VARS = "/usr/share/OVMF/OVMF32_VARS_4M.fd";

int listen_unix(const std::string& path) {
    int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) throw HarnessError(errno_text("socket"));
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    if (path.size() >= sizeof addr.sun_path) throw HarnessError("socket path too long: " + path);
    std::memcpy(addr.sun_path, path.c_str(), path.size() + 1);
    if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) < 0 || ::listen(fd, 1) < 0) {
        std::string e = errno_text("bind/listen " + path);
        ::close(fd);
        throw HarnessError(e);
    }
    return fd;
}

// A TCP socket on 127.0.0.1, at a port the kernel picks (*port).
int listen_tcp(int* port) {
    int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) throw HarnessError(errno_text("socket"));
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof addr;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) < 0 || ::listen(fd, 1) < 0 ||
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &length) < 0) {
        std::string e = errno_text("bind/listen 127.0.0.1");
        ::close(fd);
        throw HarnessError(e);
    }
    *port = ntohs(addr.sin_port);
    return fd;
}

ExitInfo exit_from_wait_status(int status) {
    ExitInfo e;
    e.exited = WIFEXITED(status);
    e.status = e.exited ? WEXITSTATUS(status) : 0;
    e.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    return e;
}

}  // namespace

std::string ExitInfo::describe() const {
    if (emulator == Emulator::Bochs) return exited ? "Bochs exit status " + std::to_string(status) : "Bochs killed by signal " + std::to_string(signal);
    if (!exited) return "QEMU killed by signal " + std::to_string(signal);
    if (status == 0) return "QEMU exit status 0: reset or triple fault under -no-reboot (never a pass)";
    if (status % 2 == 0) return "QEMU exit status " + std::to_string(status) + " (not from isa-debug-exit)";
    int value = status >> 1;
    std::string s = "QEMU exit status " + std::to_string(status) + ": ";
    if (value <= 0x3F) return s + "kernel exit code " + std::to_string(value);
    if (value < 0x60) return s + "CPU exception, vector " + std::to_string(value - 0x40);
    if (value == 0x60) return s + "kernel panic";
    return s + "unknown isa-debug-exit value " + std::to_string(value);
}

bool command_output(const std::string& cmd, std::string* out) {
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return false;
    out->clear();
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out->append(buf, n);
    return pclose(p) == 0;
}

std::string window_backend() {
    const char* x = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if (!(x && *x) && !(wayland && *wayland))
        throw HarnessError("no display for a window: neither DISPLAY nor WAYLAND_DISPLAY is set (run it from a graphical "
                           "session, or without the window: make run, modexlab run without --display)");
    std::string text;
    command_output("qemu-system-i386 -display help 2>/dev/null", &text);  // (what it lists, whatever its status)
    for (const char* backend : {"gtk", "sdl"})
        if (text.find(std::string("\n") + backend + "\n") != std::string::npos) return backend;
    throw HarnessError("QEMU has no window display (gtk or sdl): Debian ships them in qemu-system-gui "
                       "(make run DISPLAY=1 installs it, or apt-get install qemu-system-gui)");
}

std::vector<std::string> qemu_arguments(const QemuConfig& c, const std::string& serial_socket,
                                        const std::string& qmp_socket) {
    std::vector<std::string> a = {
        // (UEFI: 256 MiB, OVMF keeping much of a small machine for itself)
        "-machine", c.firmware == Firmware::Uefi32 ? "q35,smm=on,accel=tcg" : "pc,accel=tcg",
        "-m", c.memory_mib ? std::to_string(c.memory_mib) : c.firmware == Firmware::Bios ? "128" : "256",
        "-vga", "std", "-no-reboot",
        "-device", "isa-debug-exit,iobase=0xf4,iosize=0x04",
        "-chardev", "socket,id=com1,path=" + serial_socket,
        "-serial", "chardev:com1",
        "-chardev", "socket,id=qmp,path=" + qmp_socket,
        "-mon", "chardev=qmp,mode=control",
        "-parallel", "none", "-net", "none",
    };
    a.insert(a.end(), {"-display", c.display.empty() ? "none" : c.display});
    if (c.icount) a.insert(a.end(), {"-icount", "shift=0,align=off,sleep=off"});
    if (!c.cpu.empty()) a.insert(a.end(), {"-cpu", c.cpu});
    if (c.firmware == Firmware::Uefi64) a.insert(a.end(), {"-bios", OVMF64});
    if (c.firmware == Firmware::Uefi32)  // (the variable store copied: the firmware writes it)
        a.insert(a.end(), {"-global", "driver=cfi.pflash01,property=secure,value=on", "-drive",
                           std::string("if=pflash,format=raw,unit=0,readonly=on,file=") + OVMF32_CODE, "-drive",
                           "if=pflash,format=raw,unit=1,file=" + c.run_dir + "/ovmf32-vars.fd"});
    switch (c.medium) {
    case BootMedium::Kernel:
        a.insert(a.end(), {"-kernel", c.image});
        if (!c.append.empty()) a.insert(a.end(), {"-append", c.append});
        if (!c.modules.empty()) {
            std::string list;  // QEMU splits -initrd at commas; a comma in a path is written twice
            for (const std::string& m : c.modules) {
                if (!list.empty()) list += ",";
                for (char ch : m) list += ch == ',' ? std::string(",,") : std::string(1, ch);
            }
            a.insert(a.end(), {"-initrd", list});
        }
        break;
    case BootMedium::Cdrom: a.insert(a.end(), {"-cdrom", c.image, "-boot", "d"}); break;
    case BootMedium::Usb:
        a.insert(a.end(), {"-drive", "if=none,id=stick,format=raw,file=" + c.image, "-device", "nec-usb-xhci,id=xhci",
                           "-device", "usb-storage,bus=xhci.0,drive=stick,bootindex=0"});
        break;
    }
    a.insert(a.end(), c.extra_args.begin(), c.extra_args.end());
    return a;
}

std::string bochs_configuration(const QemuConfig& c, int serial_port) {
    return "# written by the modexlab harness (qemu/harness/process.cpp)\n"
           "megs: " + std::to_string(c.memory_mib ? c.memory_mib : 128) + "\n" +
           "romimage: file=/usr/share/bochs/BIOS-bochs-latest\n"
           "vgaromimage: file=/usr/share/bochs/VGABIOS-lgpl-latest\n"
           "ata0-master: type=cdrom, path=\"" + c.image + "\", status=inserted\n"
           "boot: cdrom\n"
           "display_library: rfb, options=\"timeout=0\"\n"
           "com1: enabled=1, mode=socket-client, dev=127.0.0.1:" + std::to_string(serial_port) + "\n"
           "speaker: enabled=0\n"
           "sound: driver=dummy\n"
           "clock: sync=none, time0=local\n"
           "cpu: count=1, ips=20000000, reset_on_triple_fault=0" + (c.cpu.empty() ? std::string() : ", model=" + c.cpu) + "\n"
           "log: " + c.run_dir + "/bochs.log\n"
           "panic: action=fatal\n"
           "error: action=report\n"
           "info: action=ignore\n";
}

QemuProcess::QemuProcess(const QemuConfig& config) {
    if (!std::filesystem::exists(config.image)) throw HarnessError("boot image not found: " + config.image);
    std::filesystem::create_directories(config.run_dir);
    log_path_ = config.run_dir + "/qemu.log";
    emulator_ = config.emulator;
    if (config.emulator == Emulator::Bochs) {
        start_bochs(config);
        return;
    }

    // Socket paths must be short (108 bytes): a private directory under /tmp.
    char dir_template[] = "/tmp/modexlab-XXXXXX";
    if (!::mkdtemp(dir_template)) throw HarnessError(errno_text("mkdtemp"));
    socket_dir_ = dir_template;
    std::string serial_path = socket_dir_ + "/com1", qmp_path = socket_dir_ + "/qmp";
    int serial_listen = listen_unix(serial_path);
    int qmp_listen = listen_unix(qmp_path);

    std::vector<std::string> args = qemu_arguments(config, serial_path, qmp_path);
    args.insert(args.begin(), config.firmware == Firmware::Uefi64 ? "qemu-system-x86_64" : "qemu-system-i386");
    if (config.firmware == Firmware::Uefi32)
        std::filesystem::copy_file(OVMF32_VARS, config.run_dir + "/ovmf32-vars.fd", std::filesystem::copy_options::overwrite_existing);
    std::vector<char*> argv;
    for (auto& s : args) argv.push_back(s.data());
    argv.push_back(nullptr);

    int log_fd = ::open(log_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    pid_t parent = ::getpid();
    pid_ = ::fork();
    if (pid_ < 0) throw HarnessError(errno_text("fork"));
    if (pid_ == 0) {
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // QEMU never outlives the harness
        if (::getppid() != parent) ::_exit(127);
        if (log_fd >= 0) {
            ::dup2(log_fd, 1);
            ::dup2(log_fd, 2);
        }
        int null_fd = ::open("/dev/null", O_RDONLY);
        if (null_fd >= 0) ::dup2(null_fd, 0);
        ::execvp(argv[0], argv.data());
        ::dprintf(2, "exec %s: %s\n", argv[0], std::strerror(errno));
        ::_exit(127);
    }
    if (log_fd >= 0) ::close(log_fd);

    auto accept_one = [&](int listen_fd, const char* what) {
        auto deadline = Clock::now() + std::chrono::seconds(20);
        while (Clock::now() < deadline) {
            if (poll_exit()) break;
            pollfd p{listen_fd, POLLIN, 0};
            if (::poll(&p, 1, 50) > 0) {
                int fd = ::accept4(listen_fd, nullptr, nullptr, SOCK_CLOEXEC);
                if (fd >= 0) return fd;
            }
        }
        ::close(serial_listen);
        ::close(qmp_listen);
        std::string why = exit_ ? exit_->describe() : std::string("timeout");
        kill();
        throw HarnessError(std::string("QEMU did not connect its ") + what + " socket (" + why + ")\n" + log_tail());
    };
    int serial_fd = accept_one(serial_listen, "serial");
    int qmp_fd = accept_one(qmp_listen, "QMP");
    ::close(serial_listen);
    ::close(qmp_listen);
    serial_ = LineChannel(serial_fd);
    serial_.log_to(config.run_dir + "/serial.log");
    qmp_ = LineChannel(qmp_fd);
}

void QemuProcess::start_bochs(const QemuConfig& config) {
    if (config.medium != BootMedium::Cdrom) throw HarnessError("Bochs boots the ISO from its CD drive only");
    log_path_ = config.run_dir + "/bochs.out";
    int port = 0;
    const int serial_listen = listen_tcp(&port);
    const std::string rc = config.run_dir + "/bochsrc";
    {
        std::ofstream out(rc);
        out << bochs_configuration(config, port);
        if (!out) throw HarnessError(rc + ": cannot write");
    }
    int to_stdin[2];
    if (::pipe2(to_stdin, O_CLOEXEC) < 0) throw HarnessError(errno_text("pipe"));
    int log_fd = ::open(log_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    pid_t parent = ::getpid();
    pid_ = ::fork();
    if (pid_ < 0) throw HarnessError(errno_text("fork"));
    if (pid_ == 0) {
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (::getppid() != parent) ::_exit(127);
        if (log_fd >= 0) ::dup2(log_fd, 1), ::dup2(log_fd, 2);
        ::dup2(to_stdin[0], 0);
        ::execlp("bochs-bin", "bochs-bin", "-q", "-f", rc.c_str(), static_cast<char*>(nullptr));
        ::dprintf(2, "exec bochs-bin: %s\n", std::strerror(errno));
        ::_exit(127);
    }
    if (log_fd >= 0) ::close(log_fd);
    ::close(to_stdin[0]);
    stdin_fd_ = to_stdin[1];
    // Debian's Bochs has its debugger built in and stops before the first instruction: continue
    if (::write(stdin_fd_, "c\n", 2) != 2) throw HarnessError(errno_text("write to Bochs"));
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    while (Clock::now() < deadline && !poll_exit()) {
        pollfd p{serial_listen, POLLIN, 0};
        if (::poll(&p, 1, 50) > 0) {
            int fd = ::accept4(serial_listen, nullptr, nullptr, SOCK_CLOEXEC);
            if (fd >= 0) {
                ::close(serial_listen);
                serial_ = LineChannel(fd);
                serial_.log_to(config.run_dir + "/serial.log");
                return;
            }
        }
    }
    ::close(serial_listen);
    std::string why = exit_ ? exit_->describe() : std::string("timeout");
    kill();
    throw HarnessError("Bochs did not connect its serial socket (" + why + ")\n" + log_tail());
}

QemuProcess::~QemuProcess() {
    kill();
    if (stdin_fd_ >= 0) ::close(stdin_fd_);
    std::error_code ec;
    if (!socket_dir_.empty()) std::filesystem::remove_all(socket_dir_, ec);
}

std::optional<ExitInfo> QemuProcess::poll_exit() {
    if (exit_ || pid_ <= 0) return exit_;
    int status = 0;
    pid_t r = ::waitpid(pid_, &status, WNOHANG);
    if (r == pid_) exit_ = exit_from_wait_status(status), exit_->emulator = emulator_;
    return exit_;
}

std::optional<ExitInfo> QemuProcess::wait_exit(std::chrono::milliseconds timeout) {
    auto deadline = Clock::now() + timeout;
    while (!poll_exit() && Clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return exit_;
}

void QemuProcess::kill() {
    if (pid_ <= 0 || exit_) return;
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    exit_ = exit_from_wait_status(status);
    exit_->emulator = emulator_;
}

std::string QemuProcess::log_tail(size_t lines) const {
    std::ifstream in(log_path_);
    std::vector<std::string> all;
    for (std::string line; std::getline(in, line);) all.push_back(line);
    std::string out;
    const char* who = emulator_ == Emulator::Bochs ? "  bochs: " : "  qemu: ";
    for (size_t i = all.size() > lines ? all.size() - lines : 0; i < all.size(); ++i) out += who + all[i] + "\n";
    return out;
}

}  // namespace harness
