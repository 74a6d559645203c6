// SPDX-License-Identifier: Apache-2.0
// ptu-sim's Modbus side: a TCP server on loopback or an RTU slave on a serial device (one end of a
// pty pair), answering every slave of the map through libmodbus, with injectable faults.
#pragma once
#include <atomic>
#include <string>

#include "sim_unit.hpp"

namespace rays::ptusim {

struct Faults {
    std::atomic<bool> drop{false};         // requests are not answered (a dead line)
    std::atomic<int> slow_ms{0};           // replies come this late
    std::atomic<int> exception{0};         // every request is answered with this exception code
    std::atomic<bool> disconnect{false};   // tcp: the connection is closed and refused; rtu: silence
};

struct ServerOptions {
    int tcp_port = 0;        // > 0: Modbus TCP on 127.0.0.1
    std::string rtu_device;  // otherwise: RTU on this device (115200 8N1)
};

// Serves until `stop`; prints nothing. False with `error` when it cannot listen or open.
bool serve(const ServerOptions& options, SimUnit& unit, Faults& faults, const std::atomic<bool>& stop,
           std::atomic<bool>& ready, std::string& error);

}  // namespace rays::ptusim
