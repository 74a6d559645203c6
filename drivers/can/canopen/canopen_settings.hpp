// SPDX-License-Identifier: Apache-2.0
// [canopen] in raysd.ini: two CiA 402 drives (pan, tilt) on one SocketCAN interface.
// Drive units: positions in counts of the axis (after any gearing), velocities in counts/s (the
// CiA 402 default factor group: velocity unit = position unit per second).
#pragma once
#include <string>

#include "config/param_table.hpp"

namespace rays::canopen {

struct CanopenSettings {
    std::string interface = "can0";
    int pan_node_id = 1;
    int tilt_node_id = 2;
    int master_id = 127;                   // raysd's own node id: its heartbeat is 0x700 + master_id
    int master_heartbeat_ms = 100;         // raysd's heartbeat period (0x1017 on the master side)
    int drive_consumer_timeout_ms = 350;   // drive's 0x1016: no master heartbeat this long → 0x6007 action
    std::string comm_loss_action = "quick_stop";  // 0x6007: quick_stop | disable_voltage | fault
    int drive_heartbeat_ms = 100;          // drive's 0x1017
    int drive_heartbeat_timeout_ms = 350;  // raysd faults an axis whose heartbeat stops this long
    int tpdo_period_ms = 10;               // TPDO event timer (0x1800:5, 0x1801:5)
    int cycle_ms = 10;                     // RPDOs are sent on every write() and at least this often
    int sdo_timeout_ms = 100;
    double command_timeout_s = 0.5;        // no write() this long → the I/O thread stops the axes
    double lifecycle_timeout_s = 3.0;      // configure()/activate() give up after this
    int pan_counts_per_turn = 131072;      // encoder counts per turn of the pan axis
    int tilt_counts_per_turn = 131072;
    double max_velocity_deg_s = 120.0;     // 0x607F max profile velocity and 0x6081 profile velocity
    double accel_deg_s2 = 600.0;           // 0x6083 profile acceleration and 0x6084 deceleration
    double quick_stop_decel_deg_s2 = 1200.0;  // 0x6085
    bool absolute_encoders = true;         // positions are absolute: report homed
};

const config::ParamTable<CanopenSettings>& canopen_params();

}  // namespace rays::canopen
