// The kernel's side of COM1 as the harness sees it: the boot line, then command lines answered by
// JSON replies whose "seq" must count 1, 2, 3... (a lost, duplicated or garbled line is a failure).
#pragma once

#include <chrono>
#include <deque>
#include <functional>
#include <string>

#include "qemu/lib/ordered_json.h"

#include "qemu/harness/channel.h"
#include "qemu/lib/error.h"

namespace harness {



// The kernel reported a CPU exception (the reply line with "fault":true).
class KernelFault : public HarnessError {
public:
    KernelFault(const std::string& what, json report) : HarnessError(what), report_(std::move(report)) {}
    const json& report() const { return report_; }

private:
    json report_;
};

// What one line from the kernel is, checked against the protocol (docs/protocol.md).
struct KernelLine {
    enum class Kind { Blank, Reply, Fault, BootEvent, PanicEvent, OtherEvent } kind;
    json body;
};

// Classifies one line; throws HarnessError when it is not JSON, not an object, or a reply whose
// "seq" or "ok" is missing or of the wrong type.
KernelLine classify_kernel_line(const std::string& line);

class KernelLink {
public:
    KernelLink() = default;
    explicit KernelLink(LineChannel channel) : channel_(std::move(channel)) {}

    // Waits for {"event":"boot",...}; lines before it that are not JSON (a loader's noise) are kept
    // in the transcript and skipped. Throws on a panic line, a timeout or the end of the stream.
    json wait_boot(std::chrono::milliseconds timeout);

    // Events a command may send before its reply (the frames of `play`): each goes to the callback,
    // and each restarts the timeout (the command is making progress).
    using EventFn = std::function<void(const json&)>;

    // Sends one command line and returns its reply (ok true or false). Throws KernelFault on a CPU
    // exception, HarnessError on a timeout, a wrong seq, a garbled line, a panic, an unexpected boot,
    // or an event when `on_event` is empty.
    json request(const std::string& command, std::chrono::milliseconds timeout, const EventFn& on_event = nullptr);

    // Sends raw bytes (tests of malformed input); no reply is awaited.
    void send_raw(const std::string& bytes);

    // Reads the reply to a command sent with send_raw. Without `on_event`, an upload's `ready` event
    // (raw uploads that send their bytes at once) and a long drawing's `progress` events are
    // skipped (each restarts the timeout); any other event is an error.
    json read_reply(const std::string& what, std::chrono::milliseconds timeout, const EventFn& on_event = nullptr);

    // An upload as the protocol has it: the header line, then, once the kernel says `ready`, the
    // bytes; a refused header's reply comes instead of `ready`, and the bytes are not sent.
    json upload(const std::string& header, const std::string& bytes, std::chrono::milliseconds timeout);

    // Waits for an event line named `event` that the kernel sends on its own (the show's `key`
    // events) and returns it; the other events before it go to on_other, each restarting the
    // timeout. Throws on a reply, a
    // panic, a reboot, a timeout, or another event where there is no on_other.
    json wait_event(const std::string& event, std::chrono::milliseconds timeout, const EventFn& on_other = {});

    uint32_t next_seq() const { return next_seq_; }

    // The last lines sent ("> ") and received ("< "), long lines shortened, for failure messages.
    std::string transcript_tail(size_t lines = 20) const;

private:
    void remember(const std::string& prefix, const std::string& line);
    KernelLine next_line(Clock::time_point deadline, std::chrono::milliseconds timeout, const std::string& what);

    LineChannel channel_;
    uint32_t next_seq_ = 1;
    std::deque<std::string> transcript_;
};

}  // namespace harness
