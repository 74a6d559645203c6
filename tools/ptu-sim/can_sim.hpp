// SPDX-License-Identifier: Apache-2.0
// ptu-sim --can IFACE: the simulated CiA 402 drives of drivers/can/sim on a real SocketCAN
// interface (a vcan or a CAN adapter), for raysd's canopen driver in another process.
#pragma once
#include <atomic>
#include <string>

namespace rays::ptusim {

// Serves until `stop`; prints "ready" once the interface is open. Exit status for main().
int run_can_sim(const std::string& interface, int pan_node, int tilt_node, const std::atomic<bool>& stop);

}  // namespace rays::ptusim
