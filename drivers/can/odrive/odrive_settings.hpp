// SPDX-License-Identifier: Apache-2.0
// [odrive] in raysd.ini: two ODrive axes (pan, tilt) on one SocketCAN interface, CAN simple protocol.
//
// Set on each ODrive beforehand with odrivetool (not settable through CAN simple, then
// save_configuration()): axis.config.can.node_id, axis.config.can.heartbeat_rate_ms (≤ the
// heartbeat_timeout_ms here / 3), axis.config.can.encoder_rate_ms (e.g. 10), and the communication
// watchdog: axis.config.enable_watchdog = True, axis.config.watchdog_timeout (s, e.g. 0.2, well
// above cycle_ms). raysd feeds that watchdog: the firmware feeds it on every CAN message addressed
// to the axis (can_simple.cpp, do_command → axis.watchdog_feed()); there is no separate feed
// message, and raysd sends a set-point to each axis every cycle_ms. With the watchdog on, an axis
// goes idle (WATCHDOG_TIMER_EXPIRED) when raysd stops, also after SIGKILL.
#pragma once
#include <string>

#include "config/param_table.hpp"

namespace rays::odrive {

struct OdriveSettings {
    std::string interface = "can0";
    int pan_node_id = 0;
    int tilt_node_id = 1;
    double pan_motor_turns_per_axis_turn = 1.0;  // gear ratio
    double tilt_motor_turns_per_axis_turn = 1.0;
    int heartbeat_timeout_ms = 300;
    int cycle_ms = 10;                 // set-points (and so watchdog feeds) at least this often
    double command_timeout_s = 0.5;    // no write() this long → the I/O thread stops the axes
    double lifecycle_timeout_s = 3.0;  // configure()/activate() give up after this
    double max_velocity_deg_s = 120.0; // Set_Traj_Vel_Limit (position moves)
    double accel_deg_s2 = 600.0;       // Set_Traj_Accel_Limits
    bool absolute_encoders = true;     // positions are absolute: report homed
};

const config::ParamTable<OdriveSettings>& odrive_params();

}  // namespace rays::odrive
