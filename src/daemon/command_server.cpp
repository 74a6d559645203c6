// SPDX-License-Identifier: Apache-2.0
#include "daemon/command_server.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/signalfd.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <systemd/sd-daemon.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>

#include "daemon/log.hpp"

namespace rays::daemon {
namespace {

constexpr int kPollTimeoutMs = 200;
constexpr int kBacklog = 16;

std::string errno_text(const std::string& what) { return what + ": " + std::strerror(errno); }

std::string serialise(const nlohmann::json& message) {
    return message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

// Another raysd answers on `path`: then it must not be removed.
bool socket_in_use(const sockaddr_un& address) {
    int probe = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (probe < 0) return false;
    bool in_use = connect(probe, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
    close(probe);
    return in_use;
}

}  // namespace

std::optional<ListeningSocket> ListeningSocket::open(const std::string& path, std::string& error) {
    int passed = sd_listen_fds(1);
    if (passed > 1) {
        error = "systemd passed " + std::to_string(passed) + " sockets; raysd takes one";
        return std::nullopt;
    }
    if (passed == 1) {
        if (sd_is_socket_unix(SD_LISTEN_FDS_START, SOCK_STREAM, 1, nullptr, 0) <= 0) {
            error = "the socket systemd passed is not a listening Unix stream socket";
            return std::nullopt;
        }
        fcntl(SD_LISTEN_FDS_START, F_SETFL, fcntl(SD_LISTEN_FDS_START, F_GETFL) | O_NONBLOCK);
        return ListeningSocket(SD_LISTEN_FDS_START, "");
    }
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    if (path.empty() || path.size() >= sizeof address.sun_path) {
        error = "socket.path '" + path + "' is empty or longer than " + std::to_string(sizeof address.sun_path - 1);
        return std::nullopt;
    }
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    if (socket_in_use(address)) {
        error = path + ": another process is serving this socket";
        return std::nullopt;
    }
    unlink(path.c_str());  // a stale socket from a crashed run
    int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (fd < 0) {
        error = errno_text("socket");
        return std::nullopt;
    }
    if (bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0 || chmod(path.c_str(), 0660) != 0 ||
        listen(fd, kBacklog) != 0) {
        error = errno_text(path);
        close(fd);
        return std::nullopt;
    }
    return ListeningSocket(fd, path);
}

ListeningSocket::ListeningSocket(ListeningSocket&& other) noexcept
    : fd_(other.fd_), owned_path_(std::move(other.owned_path_)) {
    other.fd_ = -1;
    other.owned_path_.clear();
}

ListeningSocket::~ListeningSocket() {
    if (fd_ < 0) return;
    close(fd_);
    if (!owned_path_.empty()) unlink(owned_path_.c_str());
}

std::string ListeningSocket::describe() const {
    return from_systemd() ? "socket from systemd" : "socket " + owned_path_;
}

CommandServer::CommandServer(const SocketSettings& settings, ListeningSocket& socket, int signal_fd,
                             LoopChannels& channels, RequestHandler& handler, std::function<void()> reload,
                             std::function<void()> housekeeping)
    : settings_(settings),
      socket_(socket),
      signal_fd_(signal_fd),
      channels_(channels),
      handler_(handler),
      reload_(std::move(reload)),
      housekeeping_(std::move(housekeeping)) {
    clients_.reserve(static_cast<std::size_t>(settings.max_clients));
}

void CommandServer::run() {
    std::vector<pollfd> fds;
    while (!channels_.stop.load()) {
        fds.clear();
        fds.push_back({socket_.fd(), POLLIN, 0});
        fds.push_back({signal_fd_, POLLIN, 0});
        fds.push_back({channels_.wake_fd, POLLIN, 0});
        for (const Client& client : clients_)
            fds.push_back({client.fd, static_cast<short>(POLLIN | (client.out.empty() ? 0 : POLLOUT)), 0});
        if (poll(fds.data(), fds.size(), kPollTimeoutMs) < 0 && errno != EINTR) {
            log(Priority::Err, "poll failed: %s", std::strerror(errno));
            break;
        }
        if (fds[1].revents & POLLIN && !take_signals()) break;
        if (fds[2].revents & POLLIN) channels_.clear_wake();
        channels_.log.drain();
        fan_out_telemetry();
        for (std::size_t i = 0; i < clients_.size(); ++i) {
            short events = fds[i + 3].revents;
            if (events & (POLLIN | POLLHUP | POLLERR) && clients_[i].fd >= 0) read_client(clients_[i]);
            if (events & POLLOUT && clients_[i].fd >= 0) flush(clients_[i]);
        }
        std::erase_if(clients_, [](const Client& client) { return client.fd < 0; });
        if (fds[0].revents & POLLIN) accept_clients();
        housekeeping_();
    }
    channels_.stop.store(true);
    channels_.frames.wake();
    for (Client& client : clients_) close(client.fd);
    clients_.clear();
    channels_.log.drain();
}

bool CommandServer::take_signals() {
    signalfd_siginfo info{};
    while (read(signal_fd_, &info, sizeof info) == static_cast<ssize_t>(sizeof info)) {
        if (info.ssi_signo == SIGHUP) {
            reload_();
            continue;
        }
        log(Priority::Notice, "signal %s: stopping", strsignal(static_cast<int>(info.ssi_signo)));
        return false;
    }
    return true;
}

void CommandServer::accept_clients() {
    for (;;) {
        int fd = accept4(socket_.fd(), nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
        if (fd < 0) return;
        if (clients_.size() >= static_cast<std::size_t>(settings_.max_clients)) reap_hung_up_clients();
        if (clients_.size() >= static_cast<std::size_t>(settings_.max_clients)) {
            std::string refusal = serialise(RequestHandler::error(
                "too_many_clients", "the server has " + std::to_string(settings_.max_clients) + " clients already"));
            [[maybe_unused]] ssize_t sent = ::send(fd, refusal.data(), refusal.size(), MSG_NOSIGNAL);
            close(fd);
            log(Priority::Warning, "refused a client: %d clients connected already", settings_.max_clients);
            continue;
        }
        clients_.push_back(Client{fd, {}, {}, false, {}});
        send(clients_.back(), RequestHandler::banner());
    }
}

// A client that connected and closed while the server was busy (a probe, a raysctl that timed out)
// still holds a place until its end is read; when connections arrive together, it would turn one
// away. Its hang-up (POLLHUP: closed, not merely shut down for writing, as a client still waiting
// for replies may be) is looked for here; what it sent before is still handled, nothing is lost.
void CommandServer::reap_hung_up_clients() {
    for (Client& client : clients_) {
        pollfd hang_up{client.fd, 0, 0};  // POLLHUP and POLLERR are reported whatever is asked for
        if (poll(&hang_up, 1, 0) == 1 && (hang_up.revents & (POLLHUP | POLLERR)) != 0) read_client(client);
    }
    std::erase_if(clients_, [](const Client& client) { return client.fd < 0; });
}

void CommandServer::read_client(Client& client) {
    char buffer[4096];
    for (;;) {
        ssize_t got = recv(client.fd, buffer, sizeof buffer, 0);
        if (got == 0) return drop(client);
        if (got < 0) {
            if (errno == EAGAIN || errno == EWOULDBLOCK) break;
            if (errno != ECONNRESET) log(Priority::Warning, "dropped a client after a read error: %s", std::strerror(errno));
            return drop(client);
        }
        client.in.append(buffer, static_cast<std::size_t>(got));
        handle_lines(client);
        if (client.fd < 0) return;
    }
}

void CommandServer::handle_lines(Client& client) {
    const std::size_t max_line = static_cast<std::size_t>(settings_.max_line_bytes);
    std::size_t start = 0;
    for (;;) {
        std::size_t newline = client.in.find('\n', start);
        if (newline == std::string::npos) break;
        std::string_view line(client.in.data() + start, newline - start);
        start = newline + 1;
        if (client.discarding) {
            client.discarding = false;
            continue;
        }
        if (line.size() > max_line) {
            send(client, RequestHandler::error("line_too_long", "a request line is at most " +
                                                                    std::to_string(max_line) + " bytes"));
            continue;
        }
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
        send(client, handler_.handle(line, client.session));
        if (client.fd < 0) return;
    }
    client.in.erase(0, start);
    if (client.in.size() > max_line && !client.discarding) {
        send(client, RequestHandler::error("line_too_long",
                                           "a request line is at most " + std::to_string(max_line) + " bytes"));
        client.discarding = true;
    }
    if (client.discarding) client.in.clear();
}

void CommandServer::send(Client& client, const nlohmann::json& message) {
    if (client.fd < 0) return;
    client.out += serialise(message);
    flush(client);
    if (client.fd >= 0 && client.out.size() > static_cast<std::size_t>(settings_.max_output_kib) * 1024) {
        log(Priority::Warning, "dropped a client: it does not read its replies");
        drop(client);
    }
}

void CommandServer::flush(Client& client) {
    while (!client.out.empty()) {
        ssize_t sent = ::send(client.fd, client.out.data(), client.out.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
        if (sent < 0) {
            if (errno == EAGAIN || errno == EWOULDBLOCK) return;
            if (errno != EPIPE && errno != ECONNRESET)
                log(Priority::Warning, "dropped a client after a write error: %s", std::strerror(errno));
            return drop(client);
        }
        client.out.erase(0, static_cast<std::size_t>(sent));
    }
}

void CommandServer::drop(Client& client) {
    close(client.fd);
    client.fd = -1;
    client.in.clear();
    client.out.clear();
}

void CommandServer::fan_out_telemetry() {
    FrameTelemetry frame;
    while (channels_.telemetry.pop(frame)) {
        bool watched = false;
        for (const Client& client : clients_) watched = watched || (client.fd >= 0 && client.session.watching);
        if (!watched) continue;
        nlohmann::json record = frame_record(frame);
        for (Client& client : clients_)
            if (client.fd >= 0 && client.session.watching) send(client, record);
    }
}

}  // namespace rays::daemon
