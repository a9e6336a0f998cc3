// QMP over a Unix socket: one JSON object per line in each direction.
#include "qemu/harness/qmp.h"

#include "qemu/lib/error.h"

namespace harness {

QmpMessage parse_qmp_line(const std::string& line) {
    json j = json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.is_object()) throw HarnessError("QMP: not a JSON object: " + line.substr(0, 200));
    json id = j.contains("id") ? j["id"] : json();
    if (j.contains("QMP")) return {QmpMessage::Kind::Greeting, j["QMP"], id};
    if (j.contains("return")) return {QmpMessage::Kind::Return, j["return"], id};
    if (j.contains("error")) return {QmpMessage::Kind::Error, j["error"], id};
    if (j.contains("event")) return {QmpMessage::Kind::Event, j, id};
    throw HarnessError("QMP: unknown message: " + line.substr(0, 200));
}

QmpMessage QmpClient::read_message(Clock::time_point deadline, const std::string& waiting_for) {
    std::optional<std::string> line;
    try {
        line = channel_.read_line(deadline);
    } catch (const HarnessError& e) {
        throw HarnessError("QMP connection lost while waiting for " + waiting_for + ": " + e.what());
    }
    if (!line) throw HarnessError("QMP: no answer within the timeout while waiting for " + waiting_for);
    return parse_qmp_line(*line);
}

void QmpClient::handshake(std::chrono::milliseconds timeout) {
    auto deadline = Clock::now() + timeout;
    QmpMessage greeting = read_message(deadline, "the greeting");
    if (greeting.kind != QmpMessage::Kind::Greeting) throw HarnessError("QMP: expected the greeting first");
    execute("qmp_capabilities", json::object(), timeout);
}

json QmpClient::execute(const std::string& command, const json& arguments, std::chrono::milliseconds timeout) {
    int id = next_id_++;
    json request = {{"execute", command}, {"id", id}};
    if (!arguments.empty()) request["arguments"] = arguments;
    channel_.write_all(request.dump() + "\n");
    auto deadline = Clock::now() + timeout;
    for (;;) {
        QmpMessage m = read_message(deadline, "'" + command + "'");
        switch (m.kind) {
        case QmpMessage::Kind::Event: events_.push_back(m.body); continue;
        case QmpMessage::Kind::Greeting: throw HarnessError("QMP: a second greeting");
        case QmpMessage::Kind::Return:
        case QmpMessage::Kind::Error:
            if (m.id != json(id)) throw HarnessError("QMP: reply id " + m.id.dump() + " for request " + std::to_string(id));
            if (m.kind == QmpMessage::Kind::Error)
                throw HarnessError("QMP '" + command + "' failed: " + m.body.value("desc", m.body.dump()));
            return m.body;
        }
    }
}

}  // namespace harness
