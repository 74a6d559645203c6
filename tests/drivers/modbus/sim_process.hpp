// SPDX-License-Identifier: Apache-2.0
// Runs tools/ptu-sim (or the pymodbus peer) as a child process for a test: waits for its "ready"
// line, sends control commands on its stdin, reads its state and the CSV of what it received.
#pragma once
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "drivers/ptu_driver.hpp"
#include "support/emulator.hpp"
#include "support/eventually.hpp"

extern char** environ;

namespace rays::test {

struct Received {
    double time_s = 0.0;
    int slave = 0;
    int address = 0;
    unsigned value = 0;
    std::string note;
};

inline double monotonic_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

class SimProcess {
public:
    // wait_ready: read the child's first line and expect "ready".
    explicit SimProcess(const std::vector<std::string>& args, bool wait_ready = true) {
        int to_child[2], from_child[2];
        if (pipe(to_child) != 0 || pipe(from_child) != 0) return;
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, to_child[0], 0);
        posix_spawn_file_actions_adddup2(&actions, from_child[1], 1);
        posix_spawn_file_actions_addclose(&actions, to_child[1]);
        posix_spawn_file_actions_addclose(&actions, from_child[0]);
        std::vector<char*> argv;
        std::vector<std::string> command = emulated(args);
        for (const std::string& a : command) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        if (posix_spawnp(&pid_, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
        posix_spawn_file_actions_destroy(&actions);
        close(to_child[0]);
        close(from_child[1]);
        in_ = fdopen(to_child[1], "w");
        out_ = fdopen(from_child[0], "r");
        ready_ = pid_ > 0 && (!wait_ready || line() == "ready");
    }
    ~SimProcess() {
        if (in_ != nullptr) {
            send("quit");
            std::fclose(in_);
        }
        if (pid_ > 0) {
            for (int i = 0; i < 100 && waitpid(pid_, nullptr, WNOHANG) == 0; ++i)
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
            if (kill(pid_, SIGKILL) == 0) waitpid(pid_, nullptr, 0);
        }
        if (out_ != nullptr) std::fclose(out_);
    }
    SimProcess(const SimProcess&) = delete;
    SimProcess& operator=(const SimProcess&) = delete;

    bool ready() const { return ready_; }
    void send(const std::string& command) {
        std::fprintf(in_, "%s\n", command.c_str());
        std::fflush(in_);
    }
    std::string line() {
        char buffer[512];
        if (out_ == nullptr || std::fgets(buffer, sizeof buffer, out_) == nullptr) return {};
        std::string text = buffer;
        while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
        return text;
    }
    // Pan and tilt velocity (rad/s) and position (rad) as the simulated unit has them now.
    struct State {
        double position[2]{}, velocity[2]{};
        bool enabled[2]{};
    };
    State state() {
        send("state");
        std::istringstream words(line());
        std::string tag;
        State s;
        words >> tag >> s.position[0] >> s.velocity[0] >> s.position[1] >> s.velocity[1] >> s.enabled[0] >> s.enabled[1];
        return s;
    }

private:
    pid_t pid_ = -1;
    FILE* in_ = nullptr;
    FILE* out_ = nullptr;
    bool ready_ = false;
};

inline std::vector<Received> read_record(const std::string& path) {
    std::vector<Received> rows;
    std::ifstream in(path);
    std::string text;
    std::getline(in, text);  // header
    while (std::getline(in, text)) {
        std::replace(text.begin(), text.end(), ',', ' ');
        std::istringstream words(text);
        Received r;
        words >> r.time_s >> r.slave >> r.address >> r.value;
        words >> r.note;
        rows.push_back(r);
    }
    return rows;
}

inline ptu::PtuCommand velocities(double pan, double tilt) {
    ptu::PtuCommand command;
    command.axes[0] = {ptu::CommandMode::Velocity, pan};
    command.axes[1] = {ptu::CommandMode::Velocity, tilt};
    return command;
}

}  // namespace rays::test
