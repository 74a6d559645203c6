// SPDX-License-Identifier: Apache-2.0
// raysctl's connection to raysd: a Unix stream socket, one JSON object per line each way, every
// wait bounded by a timeout.
#pragma once
#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace rays::ctl {

class SocketClient {
public:
    // Connects and reads the banner; nullopt with `error` when nobody answers.
    static std::optional<SocketClient> connect(const std::string& path, std::chrono::milliseconds timeout,
                                               std::string& error);
    SocketClient(SocketClient&& other) noexcept;
    SocketClient& operator=(SocketClient&&) = delete;
    ~SocketClient();

    bool send(const nlohmann::json& request, std::string& error);
    // The next object the server sends; nullopt with `error` on timeout, EOF or bad JSON.
    std::optional<nlohmann::json> receive(std::chrono::milliseconds timeout, std::string& error);

    const nlohmann::json& banner() const { return banner_; }

private:
    explicit SocketClient(int fd) : fd_(fd) {}
    int fd_;
    std::string buffer_;
    nlohmann::json banner_;
};

}  // namespace rays::ctl
