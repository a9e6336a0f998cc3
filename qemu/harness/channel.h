// Line framing over a stream socket: LineSplitter cuts bytes into lines, LineChannel reads lines with deadlines.
#pragma once

#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace harness {

using Clock = std::chrono::steady_clock;

// Accumulates bytes and yields complete lines without their "\n" (a "\r" before it is dropped too).
class LineSplitter {
public:
    void feed(std::string_view bytes);
    std::optional<std::string> next();  // the oldest complete line, if any
    const std::string& pending() const { return buffer_; }  // bytes of an unfinished line

private:
    std::string buffer_;
    size_t scan_from_ = 0;
};

// A connected stream socket read line by line. Owns the descriptor.
class LineChannel {
public:
    LineChannel() = default;
    explicit LineChannel(int fd) : fd_(fd) {}
    LineChannel(LineChannel&& other) noexcept;
    LineChannel& operator=(LineChannel&& other) noexcept;
    LineChannel(const LineChannel&) = delete;
    LineChannel& operator=(const LineChannel&) = delete;
    ~LineChannel();


    // The next line, or nullopt when the deadline passed. Throws HarnessError on end of stream
    // (with whatever partial line was pending) or on a read error.
    std::optional<std::string> read_line(Clock::time_point deadline);

    // Writes all of `bytes`; throws HarnessError when the peer is gone.
    void write_all(std::string_view bytes);

    // From now on, every byte read is also appended to the file at `path` (created anew).
    void log_to(const std::string& path);

    void close();

private:
    int fd_ = -1;
    LineSplitter splitter_;
    std::FILE* log_ = nullptr;
};

}  // namespace harness
