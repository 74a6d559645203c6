// SPDX-License-Identifier: Apache-2.0
// The command socket's requests (docs/protocol.md): one JSON line in, one JSON reply out. Runs on the
// socket thread; reaches the frame loop only through LoopChannels. Never throws: every bad input
// becomes an error reply.
#pragma once
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "core/clock.hpp"
#include "daemon/daemon_config.hpp"
#include "daemon/loop_channels.hpp"

namespace rays::daemon {

constexpr int kProtocolMajor = 1;
constexpr int kProtocolMinor = 1;  // 1: track takes a box (w, h)

// Facts fixed at start that status reports.
struct DaemonFacts {
    std::string driver;
    std::string priority = "not requested";  // what became of loop.rt_priority
    std::string affinity = "not requested";
    std::string memory_lock = "not requested";
    TimePoint started{};
};

struct ClientSession {
    bool watching = false;
};

class RequestHandler {
public:
    // `config` holds the current settings (owned by the socket thread); set and reload change it.
    RequestHandler(DaemonConfig& config, LoopChannels& channels, DaemonFacts facts,
                   std::function<std::string()> camera_status, const Clock& clock);

    nlohmann::json handle(std::string_view line, ClientSession& session);

    // Sends the tunables of `config` to the frame loop and applies the log settings; false if the
    // loop's command queue is full.
    bool push_tunables();

    static nlohmann::json banner();
    static nlohmann::json error(std::string_view code, std::string_view message);

private:
    nlohmann::json dispatch(const nlohmann::json& request, ClientSession& session);
    nlohmann::json status() const;
    nlohmann::json stats() const;
    nlohmann::json get(const nlohmann::json& request) const;
    nlohmann::json set(const nlohmann::json& request);
    nlohmann::json track(const nlohmann::json& request);
    nlohmann::json ptu(const nlohmann::json& request);
    nlohmann::json snapshot() const;
    nlohmann::json watch(const nlohmann::json& request, ClientSession& session);
    nlohmann::json send(const LoopCommand& command, std::string_view name);

    DaemonConfig& config_;
    LoopChannels& channels_;
    DaemonFacts facts_;
    std::function<std::string()> camera_status_;
    const Clock& clock_;
};

// A frame record for watching clients.
nlohmann::json frame_record(const FrameTelemetry& frame);

}  // namespace rays::daemon
