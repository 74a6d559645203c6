// SPDX-License-Identifier: Apache-2.0
// Benches "modbus-tcp" and "modbus-rtu": the real Modbus driver against ptu-sim's unit served from a
// thread in this process (loopback TCP; RTU over a socat pty pair at 115200 baud). Latency is from
// PtuDriver::write() to the simulator receiving the pan velocity write, both on the steady clock.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "drivers/modbus/modbus_ptu.hpp"
#include "latency_bench.hpp"
#include "sim_server.hpp"
#include "sim_unit.hpp"

extern char** environ;

namespace rays::bench {
namespace {

ptu::ModbusSettings bench_settings() {
    ptu::ModbusSettings settings;
    settings.timeout_ms = 100;
    settings.comm_watchdog_ms = 0;
    for (ptu::ModbusAxisSettings* axis : {&settings.pan, &settings.tilt}) {
        axis->slave = axis == &settings.pan ? 1 : 2;
        axis->velocity_register = 0;
        axis->actual_position_register = 10;
        axis->velocity_bits = 32;
    }
    return settings;
}

std::vector<double> run_against_sim(ptu::ModbusSettings settings, const ptusim::ServerOptions& server, int commands,
                                    std::string& error) {
    auto map = ptu::build_register_map(settings, error);
    if (!map) return {};
    std::mutex mutex;
    std::vector<TimePoint> received(static_cast<std::size_t>(commands) + 1);
    ptusim::SimUnit unit(*map, [&](const ptusim::WriteRecord& r) {
        // The low word of pan's 32-bit velocity carries the command's number (1 count = 1 mrad/s).
        if (r.slave != 1 || r.address != 1 || r.value == 0 || r.value > static_cast<unsigned>(commands)) return;
        std::lock_guard lock(mutex);
        if (received[r.value] == TimePoint{}) received[r.value] = r.time;
    });
    ptusim::Faults faults;
    std::atomic<bool> stop{false}, ready{false};
    std::string server_error;
    std::thread thread([&] { ptusim::serve(server, unit, faults, stop, ready, server_error); });
    while (!ready && server_error.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    SteadyClock clock;
    auto driver = ptu::make_modbus_driver(settings, clock, error);
    std::vector<double> latencies;
    ptu::DriverStatus status = driver ? driver->configure() : ptu::DriverStatus::failure(error.c_str());
    if (status.ok) status = driver->activate();
    if (!status.ok) error = status.what();
    std::vector<TimePoint> sent(static_cast<std::size_t>(commands) + 1);
    for (int i = 1; status.ok && i <= commands; ++i) {
        ptu::PtuCommand command;
        command.axes[0] = {ptu::CommandMode::Velocity, i / 1000.0};
        sent[static_cast<std::size_t>(i)] = clock.now();
        driver->write(command, sent[static_cast<std::size_t>(i)]);
        std::this_thread::sleep_for(std::chrono::milliseconds(settings.transport == "rtu" ? 8 : 3));
    }
    if (driver) driver->deactivate();
    stop = true;
    thread.join();
    for (int i = 1; status.ok && i <= commands; ++i)
        if (received[static_cast<std::size_t>(i)] != TimePoint{})
            latencies.push_back(std::chrono::duration<double, std::micro>(received[static_cast<std::size_t>(i)] -
                                                                          sent[static_cast<std::size_t>(i)])
                                    .count());
    if (latencies.empty() && error.empty()) error = server_error.empty() ? "no command reached the simulator" : server_error;
    return latencies;
}

std::vector<double> run_tcp(int commands, std::string& error) {
    ptu::ModbusSettings settings = bench_settings();
    settings.port = 15000 + getpid() % 20000;
    ptusim::ServerOptions server;
    server.tcp_port = settings.port;
    return run_against_sim(settings, server, commands, error);
}

std::vector<double> run_rtu(int commands, std::string& error) {
    const std::string link = "/tmp/ptu-bench-modbus-" + std::to_string(getpid());
    std::string a = "pty,raw,echo=0,link=" + link, b = "pty,raw,echo=0,link=" + link + ".sim";
    const char* argv[] = {"socat", a.c_str(), b.c_str(), nullptr};
    pid_t socat = -1;
    if (posix_spawnp(&socat, "socat", nullptr, nullptr, const_cast<char**>(argv), environ) != 0) {
        error = "socat is not installed (tools/install-deps installs it)";
        return {};
    }
    for (int i = 0; i < 200 && (access(link.c_str(), F_OK) != 0 || access((link + ".sim").c_str(), F_OK) != 0); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ptu::ModbusSettings settings = bench_settings();
    settings.transport = "rtu";
    settings.device = link;
    ptusim::ServerOptions server;
    server.rtu_device = link + ".sim";
    std::vector<double> latencies = run_against_sim(settings, server, commands, error);
    kill(socat, SIGTERM);
    waitpid(socat, nullptr, 0);
    return latencies;
}

const bool registered_tcp = register_bench(
    {"modbus-tcp", "Modbus driver -> in-process ptu-sim over loopback TCP: write() to the velocity write received",
     run_tcp});
const bool registered_rtu = register_bench(
    {"modbus-rtu", "Modbus driver -> in-process ptu-sim over a socat pty pair (RTU 115200 8N1): write() to receipt",
     run_rtu});

}  // namespace
}  // namespace rays::bench
