// SPDX-License-Identifier: Apache-2.0
// The SDO writes that configure one CiA 402 drive for raysd, in order: quick stop, heartbeats and
// the communication watchdog (CiA 301 §7.5.2.32-33, CiA 402-2 §6.2.6), modes and profile limits
// (CiA 402-2 §6.2.3, §12.4, §14.4), PDO mappings (CiA 301 §7.4.8: disable the PDO, clear the
// mapping count, write the entries, set the count, re-enable), and a statusword read at the end.
#pragma once
#include <array>
#include <cstddef>

#include "drivers/can/canopen/canopen_settings.hpp"
#include "drivers/can/canopen/sdo.hpp"

namespace rays::canopen {

struct ConfigurationPlan {
    static constexpr std::size_t kCapacity = 48;
    std::array<SdoRequest, kCapacity> steps{};
    std::size_t count = 0;
};

// RPDO1: controlword, modes of operation, target velocity. RPDO2: controlword, modes of operation,
// target position. TPDO1: statusword, position actual. TPDO2: velocity actual, modes display.
ConfigurationPlan configuration_plan(const CanopenSettings& settings, int node, double counts_per_rad);

std::int16_t abort_connection_code(const std::string& action);  // comm_loss_action → 0x6007

}  // namespace rays::canopen
