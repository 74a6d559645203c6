// SPDX-License-Identifier: Apache-2.0
// ptu-sim: a simulated pan/tilt unit on Modbus (or CANopen, --can) for tests, benches and trying raysd
// without hardware.
//
//   ptu-sim (--tcp PORT | --rtu-pty LINK) [--preset NAME | --config FILE] [--record FILE.csv]
//           [--drop] [--slow-ms N] [--exception CODE] [--fault pan|tilt] [--disconnect]
//
// The register map is the driver's: a preset, or the [modbus] section of a raysd-style INI file
// (--config; slave ids and scales are read from it too). --rtu-pty starts `socat` for a pty pair,
// LINK for raysd (modbus.device) and LINK.sim for the simulator. --record writes every register
// write received: time_s (steady clock), slave, register, value, note (events have slave -1).
// Once serving it prints "ready"; then it reads commands on stdin, one per line:
//   drop on|off, slow MS, exception CODE (0: off), fault pan|tilt on|off, disconnect on|off,
//   state (prints "state PAN_RAD PAN_RAD_S TILT_RAD TILT_RAD_S PAN_EN TILT_EN"), quit.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>

#include "config/config_engine.hpp"
#include "drivers/modbus/presets.hpp"
#include "drivers/modbus/register_map.hpp"
#include "can_sim.hpp"
#include "sim_server.hpp"
#include "sim_unit.hpp"

extern char** environ;

namespace {

using namespace rays;
using namespace rays::ptusim;

double seconds(TimePoint t) { return std::chrono::duration<double>(t.time_since_epoch()).count(); }

int usage() {
    std::fprintf(stderr,
                 "usage: ptu-sim (--tcp PORT | --rtu-pty LINK) [--preset NAME | --config FILE] [--record FILE]\n"
                 "               [--drop] [--slow-ms N] [--exception CODE] [--fault pan|tilt] [--disconnect]\n"
                 "       ptu-sim --can IFACE [--can-nodes PAN,TILT]   (CiA 402 drives, default nodes 1,2)\n");
    return 2;
}

pid_t start_socat(const std::string& link) {
    std::string a = "pty,raw,echo=0,link=" + link, b = "pty,raw,echo=0,link=" + link + ".sim";
    const char* argv[] = {"socat", a.c_str(), b.c_str(), nullptr};
    pid_t pid = -1;
    if (posix_spawnp(&pid, "socat", nullptr, nullptr, const_cast<char**>(argv), environ) != 0) return -1;
    for (int i = 0; i < 200 && (access(link.c_str(), F_OK) != 0 || access((link + ".sim").c_str(), F_OK) != 0); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return pid;
}

void control(std::istream& in, SimUnit& unit, Faults& faults) {
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string what, arg, arg2;
        words >> what >> arg >> arg2;
        if (what == "quit") return;
        if (what == "drop") faults.drop = arg == "on";
        else if (what == "slow") faults.slow_ms = std::atoi(arg.c_str());
        else if (what == "exception") faults.exception = std::atoi(arg.c_str());
        else if (what == "disconnect") faults.disconnect = arg == "on";
        else if (what == "fault" && (arg == "pan" || arg == "tilt"))
            unit.set_drive_fault(arg == "pan" ? 0 : 1, arg2 == "on", MonoClock::now());
        else if (what == "state") {
            const AxisView pan = unit.view(0, MonoClock::now()), tilt = unit.view(1, MonoClock::now());
            std::printf("state %.6f %.6f %.6f %.6f %d %d\n", pan.position_rad, pan.velocity_rad_s, tilt.position_rad,
                        tilt.velocity_rad_s, pan.enabled, tilt.enabled);
        } else {
            std::printf("error unknown command: %s\n", line.c_str());
        }
        std::fflush(stdout);
    }
}

}  // namespace

int main(int argc, char** argv) {
    ServerOptions options;
    std::string preset = "custom", config_path, record_path, rtu_link;
    Faults faults;
    std::string fault_axis, can_interface;
    int can_nodes[2] = {1, 2};
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        if (arg == "--tcp" && has_value) options.tcp_port = std::atoi(argv[++i]);
        else if (arg == "--rtu-pty" && has_value) rtu_link = argv[++i];
        else if (arg == "--preset" && has_value) preset = argv[++i];
        else if (arg == "--config" && has_value) config_path = argv[++i];
        else if (arg == "--record" && has_value) record_path = argv[++i];
        else if (arg == "--drop") faults.drop = true;
        else if (arg == "--slow-ms" && has_value) faults.slow_ms = std::atoi(argv[++i]);
        else if (arg == "--exception" && has_value) faults.exception = std::atoi(argv[++i]);
        else if (arg == "--fault" && has_value) fault_axis = argv[++i];
        else if (arg == "--disconnect") faults.disconnect = true;
        else if (arg == "--can" && has_value) can_interface = argv[++i];
        else if (arg == "--can-nodes" && has_value && std::sscanf(argv[++i], "%d,%d", &can_nodes[0], &can_nodes[1]) == 2) {
        } else return usage();
    }
    if (!can_interface.empty()) {  // until stdin closes or says quit
        std::atomic<bool> stop_can{false};
        std::thread stdin_watch([&] {
            std::string line;
            while (std::getline(std::cin, line) && line != "quit") {
            }
            stop_can = true;
        });
        int status = run_can_sim(can_interface, can_nodes[0], can_nodes[1], stop_can);
        if (status != 0) std::_Exit(status);  // stdin_watch may still be blocked in getline
        stdin_watch.join();
        return 0;
    }
    if ((options.tcp_port > 0) == !rtu_link.empty()) return usage();

    ptu::ModbusSettings settings;
    if (!config_path.empty()) {
        if (auto error = config::load_ini(config_path, ptu::modbus_params(), settings)) {
            std::fprintf(stderr, "ptu-sim: %s:%d: %s\n", error->file.c_str(), error->line, error->message.c_str());
            return 78;
        }
    } else {
        settings.preset = preset;
        if (preset != "custom" && !ptu::find_preset(preset)) {
            std::fprintf(stderr, "ptu-sim: unknown preset %s\n", preset.c_str());
            return 2;
        }
    }
    std::string error;
    auto map = ptu::build_register_map(settings, error);
    if (!map) {
        std::fprintf(stderr, "ptu-sim: %s\n", error.c_str());
        return 2;
    }
    FILE* record = record_path.empty() ? nullptr : std::fopen(record_path.c_str(), "w");
    if (!record_path.empty() && record == nullptr) {
        std::fprintf(stderr, "ptu-sim: cannot write %s: %s\n", record_path.c_str(), std::strerror(errno));
        return 1;
    }
    if (record != nullptr) std::fprintf(record, "time_s,slave,register,value,note\n");
    SimUnit unit(*map, [record](const WriteRecord& r) {
        if (record == nullptr) return;
        std::fprintf(record, "%.6f,%d,%d,%u,%s\n", seconds(r.time), r.slave, r.address, r.value, r.note);
        std::fflush(record);
    });
    if (fault_axis == "pan" || fault_axis == "tilt") unit.set_drive_fault(fault_axis == "pan" ? 0 : 1, true, MonoClock::now());

    pid_t socat = -1;
    if (!rtu_link.empty()) {
        socat = start_socat(rtu_link);
        if (socat < 0 || access((rtu_link + ".sim").c_str(), F_OK) != 0) {
            std::fprintf(stderr, "ptu-sim: socat could not make the pty pair %s\n", rtu_link.c_str());
            return 1;
        }
        options.rtu_device = rtu_link + ".sim";
    }
    std::atomic<bool> stop{false}, ready{false}, failed{false};
    std::thread server([&] {
        if (!serve(options, unit, faults, stop, ready, error)) failed = true;
    });
    while (!ready && !failed) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    if (ready) {
        std::printf("ready\n");
        std::fflush(stdout);
        control(std::cin, unit, faults);
    }
    stop = true;
    server.join();
    if (socat > 0) {
        kill(socat, SIGTERM);
        waitpid(socat, nullptr, 0);
    }
    if (record != nullptr) std::fclose(record);
    if (failed) std::fprintf(stderr, "ptu-sim: %s\n", error.c_str());
    return failed ? 1 : 0;
}
