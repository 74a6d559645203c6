// SPDX-License-Identifier: Apache-2.0
// Runs the real raysd binary for a test: a temporary directory with its config and socket, stderr
// captured to a file, and helpers to talk to it and to stop it.
#pragma once
#include <chrono>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rays::test {

class DaemonProcess {
public:
    // Starts `argv` (argv[0] a path) with extra environment variables, stderr to `log_path`.
    DaemonProcess(const std::vector<std::string>& argv, const std::map<std::string, std::string>& env,
                  const std::filesystem::path& log_path);
    ~DaemonProcess();  // SIGKILL if still running

    int pid() const { return pid_; }
    void signal(int signo) const;
    // The exit status (or 128 + signal), nullopt if still running after `timeout`.
    std::optional<int> wait(std::chrono::milliseconds timeout);
    std::string log() const;
    // Polls until the log holds `text`; false after `timeout`.
    bool wait_for_log(const std::string& text, std::chrono::milliseconds timeout) const;

private:
    int pid_ = -1;
    std::filesystem::path log_path_;
    std::optional<int> status_;
};

// Waits until `path` accepts connections.
bool wait_for_socket(const std::filesystem::path& path, std::chrono::milliseconds timeout);

// A raw connection: send lines, read lines.
class LineConnection {
public:
    explicit LineConnection(const std::filesystem::path& socket_path);
    ~LineConnection();
    bool connected() const { return fd_ >= 0; }
    void send_raw(const std::string& bytes);
    std::optional<std::string> read_line(std::chrono::milliseconds timeout = std::chrono::seconds(5));
    std::optional<nlohmann::json> read_json(std::chrono::milliseconds timeout = std::chrono::seconds(5));
    // Sends `request` as one line and returns the next reply that is not a watch `frame` record.
    nlohmann::json request(const nlohmann::json& request);
    int fd() const { return fd_; }

private:
    int fd_ = -1;
    std::string buffer_;
};

std::filesystem::path raysd_binary();
std::filesystem::path raysctl_binary();

// A fresh directory under the build tree for one test.
std::filesystem::path fresh_dir(const std::string& name);

// Writes a short generated sequence (a disc moving across clutter) as YUV4MPEG2.
void write_test_sequence(const std::filesystem::path& path, int frames);

// Writes dir/seq.y4m (100 frames) and dir/raysd.ini replaying it in a loop at its rate, with the
// socket dir/raysd.sock, followed by `sections`; returns the INI file's path.
std::filesystem::path write_replay_config(const std::filesystem::path& dir, const std::string& sections);

}  // namespace rays::test
