// SPDX-License-Identifier: Apache-2.0
// The socket thread: a Unix stream socket with one JSON request per line (docs/protocol.md), bounded
// clients and buffers, `watch` records fanned out from the frame loop's telemetry ring, the frame
// loop's log lines written out, and the signals (SIGHUP reload, SIGTERM/SIGINT stop) taken through a
// signalfd. A slow client is dropped; nothing here ever makes the frame loop wait.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "daemon/loop_channels.hpp"
#include "daemon/request_handler.hpp"

namespace rays::daemon {

// The listening socket: bound by raysd (and removed at exit) or passed in by systemd (kept).
class ListeningSocket {
public:
    // Takes a socket from systemd (LISTEN_FDS) if there is one, else binds `path` with mode 0660.
    static std::optional<ListeningSocket> open(const std::string& path, std::string& error);
    ListeningSocket(ListeningSocket&& other) noexcept;
    ListeningSocket& operator=(ListeningSocket&&) = delete;
    ~ListeningSocket();

    int fd() const { return fd_; }
    bool from_systemd() const { return owned_path_.empty(); }
    std::string describe() const;

private:
    ListeningSocket(int fd, std::string owned_path) : fd_(fd), owned_path_(std::move(owned_path)) {}
    int fd_;
    std::string owned_path_;  // removed at exit; empty for a socket systemd passed in
};

class CommandServer {
public:
    // `reload` re-reads the config file (SIGHUP); `signal_fd` delivers SIGHUP, SIGTERM and SIGINT;
    // `housekeeping` runs after every wake-up (at least every 200 ms).
    CommandServer(const SocketSettings& settings, ListeningSocket& socket, int signal_fd, LoopChannels& channels,
                  RequestHandler& handler, std::function<void()> reload, std::function<void()> housekeeping);

    // Serves until SIGTERM/SIGINT or channels.stop; sets channels.stop on the way out.
    void run();

private:
    struct Client {
        int fd = -1;
        std::string in;
        std::string out;
        bool discarding = false;  // inside an over-long line, until its newline
        ClientSession session;
    };

    void accept_clients();
    void read_client(Client& client);
    void handle_lines(Client& client);
    void send(Client& client, const nlohmann::json& message);
    void flush(Client& client);
    void drop(Client& client);
    // At the client limit: reads, then drops, the clients that have hung up since the last poll.
    void reap_hung_up_clients();
    void fan_out_telemetry();
    bool take_signals();  // false when asked to stop

    SocketSettings settings_;
    ListeningSocket& socket_;
    int signal_fd_;
    LoopChannels& channels_;
    RequestHandler& handler_;
    std::function<void()> reload_;
    std::function<void()> housekeeping_;
    std::vector<Client> clients_;
};

}  // namespace rays::daemon
