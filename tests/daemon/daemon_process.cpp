// SPDX-License-Identifier: Apache-2.0
#include "daemon_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "io/y4m_writer.hpp"
#include "scenes/scene.hpp"
#include "support/emulator.hpp"

namespace rays::test {

DaemonProcess::DaemonProcess(const std::vector<std::string>& argv, const std::map<std::string, std::string>& env,
                             const std::filesystem::path& log_path)
    : log_path_(log_path) {
    std::vector<std::string> command = emulated(argv);
    std::vector<char*> args;
    for (const std::string& arg : command) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    pid_ = fork();
    if (pid_ == 0) {
        int log_fd = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(log_fd, STDERR_FILENO);
        dup2(log_fd, STDOUT_FILENO);
        for (const auto& [name, value] : env) {
            // WATCHDOG_PID must name the child itself.
            std::string text = value == "$PID" ? std::to_string(getpid()) : value;
            setenv(name.c_str(), text.c_str(), 1);
        }
        sigset_t none;
        sigemptyset(&none);
        sigprocmask(SIG_SETMASK, &none, nullptr);
        execvp(args[0], args.data());
        _exit(127);
    }
}

DaemonProcess::~DaemonProcess() {
    if (pid_ > 0 && !status_) {
        kill(pid_, SIGKILL);
        waitpid(pid_, nullptr, 0);
    }
}

void DaemonProcess::signal(int signo) const { kill(pid_, signo); }

std::optional<int> DaemonProcess::wait(std::chrono::milliseconds timeout) {
    if (status_) return status_;
    auto give_up = std::chrono::steady_clock::now() + timeout;
    do {
        int raw = 0;
        if (waitpid(pid_, &raw, WNOHANG) == pid_) {
            status_ = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
            return status_;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    } while (std::chrono::steady_clock::now() < give_up);
    return std::nullopt;
}

std::string DaemonProcess::log() const {
    std::ifstream file(log_path_);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

bool DaemonProcess::wait_for_log(const std::string& text, std::chrono::milliseconds timeout) const {
    auto give_up = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < give_up) {
        if (log().find(text) != std::string::npos) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
}

namespace {

int connect_to(const std::filesystem::path& path) {
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::strncpy(address.sun_path, path.c_str(), sizeof address.sun_path - 1);
    int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0) return fd;
    close(fd);
    return -1;
}

}  // namespace

bool wait_for_socket(const std::filesystem::path& path, std::chrono::milliseconds timeout) {
    auto give_up = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < give_up) {
        if (int fd = connect_to(path); fd >= 0) {
            close(fd);
            return true;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
}

LineConnection::LineConnection(const std::filesystem::path& socket_path) : fd_(connect_to(socket_path)) {}

LineConnection::~LineConnection() {
    if (fd_ >= 0) close(fd_);
}

void LineConnection::send_raw(const std::string& bytes) {
    std::size_t sent = 0;
    while (sent < bytes.size()) {
        ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
        if (n <= 0) return;
        sent += static_cast<std::size_t>(n);
    }
}

std::optional<std::string> LineConnection::read_line(std::chrono::milliseconds timeout) {
    auto give_up = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        if (std::size_t newline = buffer_.find('\n'); newline != std::string::npos) {
            std::string line = buffer_.substr(0, newline);
            buffer_.erase(0, newline + 1);
            return line;
        }
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(give_up - std::chrono::steady_clock::now());
        if (left.count() <= 0) return std::nullopt;
        pollfd pfd{fd_, POLLIN, 0};
        if (poll(&pfd, 1, static_cast<int>(left.count())) <= 0) continue;
        char chunk[65536];
        ssize_t got = recv(fd_, chunk, sizeof chunk, 0);
        if (got <= 0) return std::nullopt;
        buffer_.append(chunk, static_cast<std::size_t>(got));
    }
}

std::optional<nlohmann::json> LineConnection::read_json(std::chrono::milliseconds timeout) {
    std::optional<std::string> line = read_line(timeout);
    if (!line) return std::nullopt;
    return nlohmann::json::parse(*line);
}

nlohmann::json LineConnection::request(const nlohmann::json& request) {
    send_raw(request.dump() + "\n");
    for (;;) {
        std::optional<nlohmann::json> reply = read_json();
        if (!reply) return nlohmann::json{{"class", "no reply"}};
        if (reply->value("class", "") != "frame") return *reply;
    }
}

std::filesystem::path raysd_binary() { return RAYSD_BINARY; }
std::filesystem::path raysctl_binary() { return RAYSCTL_BINARY; }

std::filesystem::path fresh_dir(const std::string& name) {
    std::filesystem::path dir = std::filesystem::path(RAYS_BINARY_DIR) / "test-daemon" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

void write_test_sequence(const std::filesystem::path& path, int frames) {
    auto scene = scenes::make_scene("clutter");
    io::Y4mWriter writer;
    writer.open(path.string(), kFrameSize, kFrameSize, 25, 1);
    scenes::SceneFrame frame;
    for (int i = 0; i < frames; ++i) {
        scene->render(i % scene->frame_count(), frame);
        writer.write(frame.image.px.data());
    }
    writer.close();
}

std::filesystem::path write_replay_config(const std::filesystem::path& dir, const std::string& sections) {
    write_test_sequence(dir / "seq.y4m", 100);
    std::filesystem::path ini = dir / "raysd.ini";
    std::ofstream(ini) << "[camera]\nsource = replay\nreplay_path = " << (dir / "seq.y4m").string()
                       << "\nreplay_loop = true\n\n[socket]\npath = " << (dir / "raysd.sock").string() << "\n\n"
                       << sections;
    return ini;
}

}  // namespace rays::test
