// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/odrive/odrive_settings.hpp"

namespace rays::odrive {
namespace {

config::ParamTable<OdriveSettings> build() {
    using config::ParamKind;
    using S = OdriveSettings;
    config::ParamTable<S> table;
    table.section("odrive", ParamKind::Capacity, [](S& s) -> S& { return s; })
        .add("interface", &S::interface, "SocketCAN interface the ODrives are on")
        .add("pan_node_id", &S::pan_node_id, "", 0, 62, "axis.config.can.node_id of the pan axis")
        .add("tilt_node_id", &S::tilt_node_id, "", 0, 62, "axis.config.can.node_id of the tilt axis")
        .add("pan_motor_turns_per_axis_turn", &S::pan_motor_turns_per_axis_turn, "", 0.001, 100000,
             "gear ratio of the pan axis: motor turns per turn of the axis")
        .add("tilt_motor_turns_per_axis_turn", &S::tilt_motor_turns_per_axis_turn, "", 0.001, 100000,
             "gear ratio of the tilt axis")
        .add("heartbeat_timeout_ms", &S::heartbeat_timeout_ms, "ms", 20, 60000,
             "an axis whose heartbeat is missing this long is a fault")
        .add("cycle_ms", &S::cycle_ms, "ms", 1, 1000,
             "set-points are re-sent (feeding the ODrive watchdog) at least this often")
        .add("command_timeout_s", &S::command_timeout_s, "s", 0.02, 10,
             "the axes stop when the frame loop sends no command this long")
        .add("lifecycle_timeout_s", &S::lifecycle_timeout_s, "s", 0.1, 60, "configure and activate give up after this")
        .add("max_velocity_deg_s", &S::max_velocity_deg_s, "deg/s", 0.1, 10000,
             "trajectory velocity limit of position moves (Set_Traj_Vel_Limit); raysd sends at most [ptu] max_velocity_deg_s")
        .add("accel_deg_s2", &S::accel_deg_s2, "deg/s^2", 0.1, 1000000,
             "trajectory acceleration and deceleration (Set_Traj_Accel_Limits)")
        .add("absolute_encoders", &S::absolute_encoders, "axis positions are absolute: axes count as homed");
    return table;
}

}  // namespace

const config::ParamTable<OdriveSettings>& odrive_params() {
    static const config::ParamTable<OdriveSettings> table = build();
    return table;
}

}  // namespace rays::odrive
