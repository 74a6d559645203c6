// SPDX-License-Identifier: Apache-2.0
// The ODrive "CAN simple" protocol (ODrive docs, "CAN Protocol"; firmware v0.5.x
// Firmware/communication/can/can_simple.hpp): 11-bit id = node_id << 5 | cmd_id, little-endian
// payloads, positions in turns and velocities in turns/s of the motor.
#pragma once
#include <linux/can.h>

#include <cstdint>

#include "drivers/can/can_frame_codec.hpp"

namespace rays::odrive {

enum class Cmd : std::uint32_t {
    Heartbeat = 0x001,            // ODrive → host, every config.can.heartbeat_rate_ms
    Estop = 0x002,
    SetAxisState = 0x007,         // u32 requested state
    GetEncoderEstimates = 0x009,  // ODrive → host, every config.can.encoder_rate_ms: f32 pos, f32 vel
    SetControllerMode = 0x00B,    // u32 control mode, u32 input mode
    SetInputPos = 0x00C,          // f32 pos, i16 vel_ff (0.001 turn/s), i16 torque_ff (0.001 Nm)
    SetInputVel = 0x00D,          // f32 vel, f32 torque_ff
    SetTrajVelLimit = 0x011,      // f32 turn/s
    SetTrajAccelLimits = 0x012,   // f32 accel, f32 decel (turn/s²)
    ClearErrors = 0x018,
};

// Enumerations (ODrive API reference: AxisState, ControlMode, InputMode).
constexpr std::uint32_t kAxisIdle = 1, kAxisClosedLoop = 8;
constexpr std::uint32_t kVelocityControl = 2, kPositionControl = 3;
constexpr std::uint32_t kInputPassthrough = 1, kInputTrapTraj = 5;
constexpr std::uint32_t kErrorWatchdogExpired = 0x00000800;  // Axis.Error.WATCHDOG_TIMER_EXPIRED (v0.5)

constexpr canid_t frame_id(int node, Cmd cmd) {
    return (static_cast<canid_t>(node) << 5) | static_cast<canid_t>(cmd);
}
constexpr int node_of(std::uint32_t id) { return static_cast<int>(id >> 5); }
constexpr Cmd cmd_of(std::uint32_t id) { return static_cast<Cmd>(id & 0x1F); }

inline can_frame u32_pair(int node, Cmd cmd, std::uint32_t a, std::uint32_t b) {
    can_frame frame = can::make_frame(frame_id(node, cmd), 8);
    can::put_u32(frame, 0, a);
    can::put_u32(frame, 4, b);
    return frame;
}

inline can_frame f32_pair(int node, Cmd cmd, float a, float b) {
    can_frame frame = can::make_frame(frame_id(node, cmd), 8);
    can::put_f32(frame, 0, a);
    can::put_f32(frame, 4, b);
    return frame;
}

inline can_frame set_axis_state(int node, std::uint32_t state) { return u32_pair(node, Cmd::SetAxisState, state, 0); }
inline can_frame set_controller_mode(int node, std::uint32_t control, std::uint32_t input) {
    return u32_pair(node, Cmd::SetControllerMode, control, input);
}
inline can_frame set_input_vel(int node, float turns_s) { return f32_pair(node, Cmd::SetInputVel, turns_s, 0.0f); }
inline can_frame set_input_pos(int node, float turns) {
    can_frame frame = can::make_frame(frame_id(node, Cmd::SetInputPos), 8);
    can::put_f32(frame, 0, turns);  // feed-forwards (bytes 4-7) zero
    return frame;
}
inline can_frame clear_errors(int node) { return can::make_frame(frame_id(node, Cmd::ClearErrors), 0); }

struct Heartbeat {
    std::uint32_t axis_error = 0;  // bytes 0-3
    std::uint8_t axis_state = 0;   // byte 4
};

inline Heartbeat parse_heartbeat(const can_frame& frame) { return {can::get_u32(frame, 0), frame.data[4]}; }

}  // namespace rays::odrive
