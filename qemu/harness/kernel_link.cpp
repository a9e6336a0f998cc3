// Serial protocol checks: boot line, reply sequence numbers, faults and panics.
#include "qemu/harness/kernel_link.h"

namespace harness {

namespace {
constexpr size_t TRANSCRIPT_LINES = 200;
constexpr size_t SHOWN_CHARS = 300;
}  // namespace

KernelLine classify_kernel_line(const std::string& line) {
    if (line.find_first_not_of(" \t") == std::string::npos) return {KernelLine::Kind::Blank, json()};
    json j = json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.is_object()) throw HarnessError("garbled line from the kernel (not a JSON object): " + line.substr(0, SHOWN_CHARS));
    if (j.contains("seq")) {
        if (!j["seq"].is_number_unsigned()) throw HarnessError("reply with a bad \"seq\": " + line.substr(0, SHOWN_CHARS));
        if (!j.contains("ok") || !j["ok"].is_boolean()) throw HarnessError("reply without a boolean \"ok\": " + line.substr(0, SHOWN_CHARS));
        if (j.value("fault", false)) return {KernelLine::Kind::Fault, j};
        return {KernelLine::Kind::Reply, j};
    }
    std::string event = j.value("event", "");
    if (event == "boot") return {KernelLine::Kind::BootEvent, j};
    if (event == "panic") return {KernelLine::Kind::PanicEvent, j};
    if (!event.empty()) return {KernelLine::Kind::OtherEvent, j};
    throw HarnessError("line from the kernel is neither a reply nor an event: " + line.substr(0, SHOWN_CHARS));
}

void KernelLink::remember(const std::string& prefix, const std::string& line) {
    transcript_.push_back(prefix + (line.size() > SHOWN_CHARS ? line.substr(0, SHOWN_CHARS) + "..." : line));
    if (transcript_.size() > TRANSCRIPT_LINES) transcript_.pop_front();
}

std::string KernelLink::transcript_tail(size_t lines) const {
    std::string out;
    size_t start = transcript_.size() > lines ? transcript_.size() - lines : 0;
    for (size_t i = start; i < transcript_.size(); ++i) out += "  " + transcript_[i] + "\n";
    return out.empty() ? "  (nothing)\n" : out;
}

json KernelLink::wait_boot(std::chrono::milliseconds timeout) {
    auto deadline = Clock::now() + timeout;
    for (;;) {
        auto line = channel_.read_line(deadline);
        if (!line) throw HarnessError("no boot line from the kernel within " + std::to_string(timeout.count()) + " ms");
        remember("< ", *line);
        // Loader noise may come before the kernel speaks, even on the kernel's first line.
        std::optional<std::string> object;
        for (size_t at = line->find('{'); at != std::string::npos && !object; at = line->find('{', at + 1)) {
            json j = json::parse(line->substr(at), nullptr, false);
            if (!j.is_discarded() && j.is_object()) object = line->substr(at);
        }
        if (!object) continue;
        KernelLine k = classify_kernel_line(*object);
        if (k.kind == KernelLine::Kind::BootEvent) return k.body;
        if (k.kind == KernelLine::Kind::PanicEvent) throw HarnessError("kernel panic at boot: " + k.body.value("error", "?"));
        if (k.kind == KernelLine::Kind::Fault) throw KernelFault("CPU exception at boot: " + k.body.value("error", "?"), k.body);
        throw HarnessError("unexpected line before the boot line: " + line->substr(0, SHOWN_CHARS));
    }
}

void KernelLink::send_raw(const std::string& bytes) {
    remember("> ", bytes);
    channel_.write_all(bytes);
}

json KernelLink::request(const std::string& command, std::chrono::milliseconds timeout, const EventFn& on_event) {
    send_raw(command + "\n");
    return read_reply("'" + command + "'", timeout, on_event);
}

// The next line that is not blank, classified; throws on a timeout ("no WHAT within N ms"), a
// reboot and a panic, which no caller waits for.
KernelLine KernelLink::next_line(Clock::time_point deadline, std::chrono::milliseconds timeout, const std::string& what) {
    for (;;) {
        auto line = channel_.read_line(deadline);
        if (!line) throw HarnessError("no " + what + " within " + std::to_string(timeout.count()) + " ms");
        remember("< ", *line);
        KernelLine k = classify_kernel_line(*line);
        if (k.kind == KernelLine::Kind::Blank) continue;
        if (k.kind == KernelLine::Kind::BootEvent) throw HarnessError("the kernel rebooted while waiting for " + what);
        if (k.kind == KernelLine::Kind::PanicEvent) throw HarnessError("kernel panic: " + k.body.value("error", "?"));
        return k;
    }
}

json KernelLink::read_reply(const std::string& what, std::chrono::milliseconds timeout, const EventFn& on_event) {
    auto deadline = Clock::now() + timeout;
    for (;;) {
        KernelLine k = next_line(deadline, timeout, "reply to " + what);
        if (k.kind == KernelLine::Kind::OtherEvent) {
            if (!on_event && (k.body.value("event", "") == "ready" || k.body.value("event", "") == "progress")) {
                deadline = Clock::now() + timeout;  // alive: the command is making progress
                continue;
            }
            if (!on_event) throw HarnessError("unexpected event while waiting for the reply to " + what + ": " + k.body.dump());
            on_event(k.body);
            deadline = Clock::now() + timeout;
            continue;
        }
        uint32_t seq = k.body["seq"].get<uint32_t>();
        if (seq != next_seq_)
            throw HarnessError("reply to " + what + " has seq " + std::to_string(seq) + ", expected " + std::to_string(next_seq_) +
                               ": a reply was lost or duplicated");
        ++next_seq_;
        if (k.kind == KernelLine::Kind::Fault)
            throw KernelFault("kernel fault during " + what + ": " + k.body.value("error", "?"), k.body);
        return k.body;
    }
}

json KernelLink::wait_event(const std::string& event, std::chrono::milliseconds timeout, const EventFn& on_other) {
    for (;;) {  // (each other event restarts the timeout: the kernel is at work)
        KernelLine k = next_line(Clock::now() + timeout, timeout, "'" + event + "' event");
        const bool an_event = k.kind == KernelLine::Kind::OtherEvent;
        if (an_event && k.body.value("event", "") == event) return k.body;
        if (!an_event || !on_other) throw HarnessError("while waiting for a '" + event + "' event: " + k.body.dump());
        on_other(k.body);
    }
}

json KernelLink::upload(const std::string& header, const std::string& bytes, std::chrono::milliseconds timeout) {
    send_raw(header + "\n");
    bool sent = false;
    return read_reply("'" + header + "'", timeout, [&](const json& e) {
        if (e.value("event", "") != "ready" || sent) throw HarnessError("unexpected event during an upload: " + e.dump());
        if (e.value("bytes", uint64_t(0)) != bytes.size())
            throw HarnessError("the kernel is ready for " + e["bytes"].dump() + " bytes, the upload has " + std::to_string(bytes.size()));
        send_raw(bytes);
        sent = true;
    });
}

}  // namespace harness
