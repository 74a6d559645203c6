// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/canopen/canopen_settings.hpp"

namespace rays::canopen {
namespace {

config::ParamTable<CanopenSettings> build() {
    using config::ParamKind;
    using S = CanopenSettings;
    config::ParamTable<S> table;
    table.section("canopen", ParamKind::Capacity, [](S& s) -> S& { return s; })
        .add("interface", &S::interface, "SocketCAN interface the drives are on (ip link set can0 up type can bitrate ...)")
        .add("pan_node_id", &S::pan_node_id, "", 1, 127, "CANopen node id of the pan drive")
        .add("tilt_node_id", &S::tilt_node_id, "", 1, 127, "CANopen node id of the tilt drive")
        .add("master_id", &S::master_id, "", 1, 127, "raysd's node id; it sends heartbeats as 0x700 + master_id")
        .add("master_heartbeat_ms", &S::master_heartbeat_ms, "ms", 10, 10000, "period of raysd's heartbeat")
        .add("drive_consumer_timeout_ms", &S::drive_consumer_timeout_ms, "ms", 20, 65535,
             "drive stops (comm_loss_action) when raysd's heartbeat is missing this long (0x1016)")
        .add_choice("comm_loss_action", &S::comm_loss_action, "quick_stop|disable_voltage|fault",
                    "what the drive does on communication loss (0x6007 abort connection option code)")
        .add("drive_heartbeat_ms", &S::drive_heartbeat_ms, "ms", 10, 10000, "drives' heartbeat period (0x1017)")
        .add("drive_heartbeat_timeout_ms", &S::drive_heartbeat_timeout_ms, "ms", 20, 60000,
             "an axis whose heartbeat is missing this long is a fault")
        .add("tpdo_period_ms", &S::tpdo_period_ms, "ms", 1, 1000, "drives send statusword, position, velocity this often")
        .add("cycle_ms", &S::cycle_ms, "ms", 1, 1000, "targets are re-sent at least this often")
        .add("sdo_timeout_ms", &S::sdo_timeout_ms, "ms", 5, 5000, "an SDO transfer without reply fails after this")
        .add("command_timeout_s", &S::command_timeout_s, "s", 0.02, 10,
             "the axes stop when the frame loop sends no command this long")
        .add("lifecycle_timeout_s", &S::lifecycle_timeout_s, "s", 0.1, 60, "configure and activate give up after this")
        .add("pan_counts_per_turn", &S::pan_counts_per_turn, "counts", 1, 2000000000,
             "drive position units per turn of the pan axis (encoder counts times gear ratio)")
        .add("tilt_counts_per_turn", &S::tilt_counts_per_turn, "counts", 1, 2000000000,
             "drive position units per turn of the tilt axis")
        .add("max_velocity_deg_s", &S::max_velocity_deg_s, "deg/s", 0.1, 10000,
             "drives' max profile velocity (0x607F) and profile position speed (0x6081); raysd writes at most [ptu] max_velocity_deg_s")
        .add("accel_deg_s2", &S::accel_deg_s2, "deg/s^2", 0.1, 1000000, "drives' profile acceleration and deceleration")
        .add("quick_stop_decel_deg_s2", &S::quick_stop_decel_deg_s2, "deg/s^2", 0.1, 1000000,
             "drives' quick stop deceleration (0x6085), also used on communication loss")
        .add("absolute_encoders", &S::absolute_encoders, "drive positions are absolute: axes count as homed");
    table.add_rule(config::less_than("canopen.master_heartbeat_ms", "canopen.drive_consumer_timeout_ms"));
    table.add_rule(config::less_than("canopen.drive_heartbeat_ms", "canopen.drive_heartbeat_timeout_ms"));
    return table;
}

}  // namespace

const config::ParamTable<CanopenSettings>& canopen_params() {
    static const config::ParamTable<CanopenSettings> table = build();
    return table;
}

}  // namespace rays::canopen
