// A QMP client: greeting, capabilities negotiation, commands matched to replies by id, events set aside.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "qemu/lib/ordered_json.h"

#include "qemu/harness/channel.h"

namespace harness {



// What one QMP line is: the greeting, a command's return or error, or an asynchronous event.
struct QmpMessage {
    enum class Kind { Greeting, Return, Error, Event } kind;
    json body;
    json id;  // null when the message carries none
};

// Parses one QMP line; throws HarnessError on anything that is not one of the four kinds.
QmpMessage parse_qmp_line(const std::string& line);

class QmpClient {
public:
    QmpClient() = default;
    explicit QmpClient(LineChannel channel) : channel_(std::move(channel)) {}

    // Reads the greeting and leaves negotiation mode (qmp_capabilities).
    void handshake(std::chrono::milliseconds timeout);

    // Runs a command and returns its "return" value; throws HarnessError with QMP's error
    // description, on a timeout, or when the connection ends.
    json execute(const std::string& command, const json& arguments = json::object(),
                 std::chrono::milliseconds timeout = std::chrono::seconds(30));

    const std::vector<json>& events() const { return events_; }

private:
    QmpMessage read_message(Clock::time_point deadline, const std::string& waiting_for);

    LineChannel channel_;
    std::vector<json> events_;
    int next_id_ = 1;
};

}  // namespace harness
