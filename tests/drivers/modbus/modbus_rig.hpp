// SPDX-License-Identifier: Apache-2.0
// A Modbus driver against a peer in a child process: the [modbus] section is one INI file that
// both the driver (through modbus_params()) and ptu-sim (--config) read.
#pragma once
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "config/config_engine.hpp"
#include "drivers/modbus/modbus_ptu.hpp"
#include "sim_process.hpp"
#include "support/temp_dir.hpp"

namespace rays::test {

inline int free_tcp_port() {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address);
    socklen_t length = sizeof address;
    getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
    close(fd);
    return ntohs(address.sin_port);
}

// This test process's files (the simulator's INI files and records), removed when it ends.
inline std::string scratch_dir() {
    static const TempDir dir;
    return dir.path().string();
}

// Two slaves, 32 bit values high word first, status fault bit 0x08, enable, watchdog register 100.
inline std::string custom_map_ini(int watchdog_ms = 300) {
    std::string text = "preset = custom\ncomm_watchdog_register = 100\ncomm_watchdog_ms = " +
                       std::to_string(watchdog_ms) + "\n";
    for (const char* axis : {"pan", "tilt"}) {
        const std::string a = axis;
        text += a + "_slave = " + (a == "pan" ? "1" : "2") + "\n" + a + "_velocity_register = 0\n" + a +
                "_position_register = 2\n" + a + "_actual_position_register = 10\n" + a + "_status_register = 20\n" +
                a + "_fault_mask = 8\n" + a + "_enable_register = 30\n" + a + "_velocity_bits = 32\n" + a +
                "_position_bits = 32\n" + a + "_velocity_counts_per_rad_s = 1000\n" + a +
                "_position_counts_per_rad = 10000\n";
    }
    return text;
}

struct Rig {
    std::string ini_path, record_path, link;
    ptu::ModbusSettings settings;
    std::unique_ptr<SimProcess> sim;
    SteadyClock clock;
    std::unique_ptr<ptu::PtuDriver> driver;
    std::string error;

    // transport "tcp" or "rtu"; `map` is the INI text of the map (custom_map_ini() or "preset = ...").
    // A reply later than timeout_ms is none: short, so that the fault tests see one soon.
    Rig(const std::string& name, const std::string& transport, const std::string& map, const std::string& extra = "",
        int timeout_ms = 40) {
        const std::string dir = scratch_dir();
        ini_path = dir + "/" + name + ".ini";
        record_path = dir + "/" + name + ".csv";
        link = dir + "/" + name + ".pty";
        const int port = free_tcp_port();
        std::ofstream(ini_path) << "[modbus]\ntransport = " << transport << "\nport = " << port << "\ndevice = " << link
                                << "\ntimeout_ms = " << timeout_ms
                                << "\nretries = 1\nfault_after_failures = 2\ncommand_timeout_ms = 300\npoll_ms = 10\n"
                                << map << extra;
        if (auto problem = config::load_ini(ini_path, ptu::modbus_params(), settings)) error = problem->to_string();
        std::vector<std::string> args{RAYS_PTU_SIM, "--config", ini_path, "--record", record_path};
        if (transport == "tcp") {
            args.push_back("--tcp");
            args.push_back(std::to_string(port));
        } else {
            args.push_back("--rtu-pty");
            args.push_back(link);
        }
        if (error.empty()) sim = std::make_unique<SimProcess>(args);
        if (error.empty()) driver = ptu::make_modbus_driver(settings, clock, error);
    }
    ~Rig() {
        if (driver) driver->deactivate();
    }

    bool up() {
        if (!error.empty() || !sim || !sim->ready()) return false;
        ptu::DriverStatus status = driver->configure();
        if (status.ok) status = driver->activate();
        if (!status.ok) error = status.what();
        return status.ok;
    }
    std::vector<Received> received() const { return read_record(record_path); }
};

// Every 32-bit value the unit received at `address` of `slave` (high word first) in the rows after
// `after_s`, in the order received.
inline std::vector<std::int32_t> values32(const std::vector<Received>& rows, int slave, int address, double after_s = 0.0) {
    std::vector<std::int32_t> values;
    unsigned high = 0;
    for (const Received& r : rows) {
        if (r.slave != slave || r.time_s < after_s) continue;
        if (r.address == address) high = r.value;
        if (r.address == address + 1) values.push_back(static_cast<std::int32_t>((high << 16) | r.value));
    }
    return values;
}

// The last such value.
inline bool last_value32(const std::vector<Received>& rows, int slave, int address, double after_s, std::int32_t& out) {
    const std::vector<std::int32_t> values = values32(rows, slave, address, after_s);
    if (values.empty()) return false;
    out = values.back();
    return true;
}

}  // namespace rays::test
