// Line framing and deadline-bounded socket reads (poll).
#include "qemu/harness/channel.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "qemu/lib/error.h"

namespace harness {

namespace {
constexpr useconds_t LINE_GATHER_US = 500;
}  // namespace

void LineSplitter::feed(std::string_view bytes) { buffer_.append(bytes); }

std::optional<std::string> LineSplitter::next() {
    size_t nl = buffer_.find('\n', scan_from_);
    if (nl == std::string::npos) {
        scan_from_ = buffer_.size();
        return std::nullopt;
    }
    size_t end = (nl > 0 && buffer_[nl - 1] == '\r') ? nl - 1 : nl;
    std::string line = buffer_.substr(0, end);
    buffer_.erase(0, nl + 1);
    scan_from_ = 0;
    return line;
}

LineChannel::LineChannel(LineChannel&& other) noexcept : fd_(other.fd_), splitter_(std::move(other.splitter_)), log_(other.log_) {
    other.fd_ = -1;
    other.log_ = nullptr;
}

LineChannel& LineChannel::operator=(LineChannel&& other) noexcept {
    if (this != &other) {
        close();
        fd_ = other.fd_;
        splitter_ = std::move(other.splitter_);
        log_ = other.log_;
        other.fd_ = -1;
        other.log_ = nullptr;
    }
    return *this;
}

LineChannel::~LineChannel() { close(); }

void LineChannel::close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (log_) std::fclose(log_);
    log_ = nullptr;
}

void LineChannel::log_to(const std::string& path) {
    if (log_) std::fclose(log_);
    log_ = std::fopen(path.c_str(), "wb");
    if (!log_) throw HarnessError(path + ": " + std::strerror(errno));
}

std::optional<std::string> LineChannel::read_line(Clock::time_point deadline) {
    for (;;) {
        if (auto line = splitter_.next()) return line;
        if (fd_ < 0) throw HarnessError("read from a closed channel");
        auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) return std::nullopt;
        pollfd p{fd_, POLLIN, 0};
        int r = ::poll(&p, 1, int(std::min<long long>(left, 1000)));
        if (r < 0) {
            if (errno == EINTR) continue;
            throw HarnessError(std::string("poll: ") + std::strerror(errno));
        }
        if (r == 0) continue;
        char buf[65536];
        ssize_t n = ::read(fd_, buf, sizeof buf);
        if (n < 0) {
            if (errno == EINTR || errno == EAGAIN) continue;
            throw HarnessError(std::string("read: ") + std::strerror(errno));
        }
        if (n == 0) {
            std::string partial = splitter_.pending();
            throw HarnessError(partial.empty() ? "end of stream" : "end of stream after a partial line: " + partial.substr(0, 200));
        }
        const std::string_view got(buf, size_t(n));
        splitter_.feed(got);
        if (log_) std::fwrite(buf, 1, size_t(n), log_), std::fflush(log_);
        // QEMU passes a guest's serial bytes on one at a time: within a line, let some gather
        // before the next read, rather than a poll and a read a byte
        if (got.find('\n') == std::string_view::npos && size_t(n) < sizeof buf / 64) ::usleep(LINE_GATHER_US);
    }
}

void LineChannel::write_all(std::string_view bytes) {
    while (!bytes.empty()) {
        if (fd_ < 0) throw HarnessError("write to a closed channel");
        ssize_t n = ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw HarnessError(std::string("write: ") + std::strerror(errno));
        }
        bytes.remove_prefix(size_t(n));
    }
}

}  // namespace harness
