// SPDX-License-Identifier: Apache-2.0
#include "socket_client.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace rays::ctl {

std::optional<SocketClient> SocketClient::connect(const std::string& path, std::chrono::milliseconds timeout,
                                                  std::string& error) {
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    if (path.size() >= sizeof address.sun_path) {
        error = path + ": socket path too long";
        return std::nullopt;
    }
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0 || ::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
        error = path + ": " + std::strerror(errno) + " (is raysd running? --socket PATH names another socket)";
        if (fd >= 0) close(fd);
        return std::nullopt;
    }
    SocketClient client(fd);
    std::optional<nlohmann::json> banner = client.receive(timeout, error);
    if (!banner) return std::nullopt;
    if (banner->value("class", "") != "version") {
        error = path + ": the server did not send a raysd banner";
        return std::nullopt;
    }
    client.banner_ = *banner;
    return client;
}

SocketClient::SocketClient(SocketClient&& other) noexcept
    : fd_(other.fd_), buffer_(std::move(other.buffer_)), banner_(std::move(other.banner_)) {
    other.fd_ = -1;
}

SocketClient::~SocketClient() {
    if (fd_ >= 0) close(fd_);
}

bool SocketClient::send(const nlohmann::json& request, std::string& error) {
    std::string line = request.dump() + "\n";
    std::size_t sent = 0;
    while (sent < line.size()) {
        ssize_t n = ::send(fd_, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
        if (n < 0) {
            if (errno == EINTR) continue;
            error = std::string("send: ") + std::strerror(errno);
            return false;
        }
        sent += static_cast<std::size_t>(n);
    }
    return true;
}

std::optional<nlohmann::json> SocketClient::receive(std::chrono::milliseconds timeout, std::string& error) {
    auto give_up = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        if (std::size_t newline = buffer_.find('\n'); newline != std::string::npos) {
            nlohmann::json message = nlohmann::json::parse(buffer_.substr(0, newline), nullptr, false);
            buffer_.erase(0, newline + 1);
            if (message.is_discarded() || !message.is_object()) {
                error = "the server sent a line that is not a JSON object";
                return std::nullopt;
            }
            return message;
        }
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(give_up - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            error = "no reply within " + std::to_string(timeout.count()) + " ms";
            return std::nullopt;
        }
        pollfd pfd{fd_, POLLIN, 0};
        if (poll(&pfd, 1, static_cast<int>(left.count())) <= 0) continue;
        char chunk[65536];
        ssize_t got = recv(fd_, chunk, sizeof chunk, 0);
        if (got <= 0) {
            error = got == 0 ? "the server closed the connection" : std::string("recv: ") + std::strerror(errno);
            return std::nullopt;
        }
        buffer_.append(chunk, static_cast<std::size_t>(got));
    }
}

}  // namespace rays::ctl
