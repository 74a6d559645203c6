// SPDX-License-Identifier: Apache-2.0
// Settings of the Modbus PTU driver, section [modbus] of raysd.ini (keys in modbus_params()).
// A preset names a drive family's register map; `custom` takes the map from the pan_* and tilt_*
// keys. Slave ids and scales always come from the keys: they depend on the wiring and the gearing.
#pragma once
#include <string>

#include "config/param_table.hpp"

namespace rays::ptu {

// One axis: where its registers are and how counts relate to radians. Register -1: not present.
struct ModbusAxisSettings {
    int slave = 0;                        // 0: the preset's default (custom needs 1..247)
    int velocity_register = -1;           // target velocity (custom map)
    int position_register = -1;           // target position (custom map)
    int actual_position_register = -1;    // measured position (custom map)
    int status_register = -1;             // status word (custom map)
    int fault_mask = 0;                   // status bits meaning "drive fault" (custom map)
    int enable_register = -1;             // written enable_value on activate, disable_value on deactivate
    int enable_value = 1;
    int disable_value = 0;
    int trigger_register = -1;            // written trigger_value after each target (drives that latch)
    int trigger_value = 1;
    int velocity_bits = 16;               // 16 or 32: width of the velocity target
    int position_bits = 32;               // 16 or 32: width of target and actual position
    std::string word_order = "high_first";  // 32 bit: which register holds the high word
    double velocity_counts_per_rad_s = 1000.0;
    double position_counts_per_rad = 10000.0;
};

struct ModbusSettings {
    std::string transport = "tcp";  // tcp|rtu
    std::string host = "127.0.0.1";
    int port = 502;
    std::string device = "/dev/ttyUSB0";
    int baud = 115200;
    std::string parity = "none";  // none|even|odd
    int stop_bits = 1;
    std::string preset = "custom";
    int timeout_ms = 50;             // per request
    int retries = 1;                 // further tries of a failed request
    int fault_after_failures = 3;    // consecutive failed cycles before the axis faults
    int comm_watchdog_ms = 300;      // drive-side: written to the preset's watchdog register
    int comm_watchdog_register = -1; // custom map: where comm_watchdog_ms goes (one per slave)
    double comm_watchdog_ms_per_count = 1.0;
    int command_timeout_ms = 500;    // driver-side: no write() for this long stops the axes
    int poll_ms = 10;                // I/O cycle when no new command wakes it
    ModbusAxisSettings pan{};
    ModbusAxisSettings tilt{};
};

const config::ParamTable<ModbusSettings>& modbus_params();

}  // namespace rays::ptu
