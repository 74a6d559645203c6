// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/odrive/odrive_axis.hpp"
#include "common/angles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "drivers/can/odrive/odrive_protocol.hpp"

namespace rays::odrive {
namespace {

constexpr auto kArmTimeout = std::chrono::milliseconds(500);

float turns(double deg, double turns_per_rad) {
    return static_cast<float>(deg * kRadPerDeg * turns_per_rad);
}

}  // namespace

OdriveAxis::OdriveAxis(const char* label, int node, double turns_per_rad, const OdriveSettings& settings)
    : label_(label),
      node_(node),
      turns_per_rad_(turns_per_rad),
      traj_velocity_(turns(settings.max_velocity_deg_s, turns_per_rad)),
      traj_accel_(turns(settings.accel_deg_s2, turns_per_rad)),
      heartbeat_timeout_(std::chrono::milliseconds(settings.heartbeat_timeout_ms)),
      absolute_(settings.absolute_encoders) {}

void OdriveAxis::start(TimePoint now) {
    phase_ = Phase::Waiting;
    heartbeat_seen_ = false;
    last_heartbeat_ = now;
}

void OdriveAxis::forget_faults() {
    status_ = ptu::DriverStatus::success();
    backoff_s_ = 0.5;
}

void OdriveAxis::fail(TimePoint now, const char* format, ...) {
    char text[120];
    const int used = std::snprintf(text, sizeof text, "odrive: %s (node %d): ", label_, node_);
    va_list args;
    va_start(args, format);
    std::vsnprintf(text + used, sizeof text - static_cast<std::size_t>(used), format, args);
    va_end(args);
    status_ = ptu::DriverStatus::failure(text);
    phase_ = Phase::Backoff;
    retry_at_ = now + std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(backoff_s_));
    backoff_s_ = std::min(backoff_s_ * 2.0, 8.0);
}

void OdriveAxis::lose(const char* why, TimePoint now) {
    fail(now, "%s", why);
    heartbeat_seen_ = false;
}

bool OdriveAxis::on_frame(const can_frame& frame, TimePoint now) {
    const std::uint32_t id = can::standard_id(frame);
    if (id == 0xFFFFFFFFu || node_of(id) != node_) return false;
    if (cmd_of(id) == Cmd::Heartbeat && frame.len >= 5) {
        const Heartbeat heartbeat = parse_heartbeat(frame);
        axis_error_ = heartbeat.axis_error;
        axis_state_ = heartbeat.axis_state;
        last_heartbeat_ = now;
        heartbeat_seen_ = true;
        if (phase_ == Phase::Waiting) phase_ = Phase::Ready;
        if (phase_ == Phase::Arming && axis_state_ == kAxisClosedLoop && axis_error_ == 0) {
            phase_ = Phase::Running;
            status_ = ptu::DriverStatus::success();
            backoff_s_ = 0.5;
        } else if (phase_ == Phase::Running && axis_error_ != 0) {
            fail(now, "axis error 0x%08X%s", axis_error_,
                 (axis_error_ & kErrorWatchdogExpired) != 0 ? " (watchdog expired)" : "");
        } else if (phase_ == Phase::Running && axis_state_ != kAxisClosedLoop) {
            fail(now, "left closed loop control (axis state %u)", axis_state_);
        }
    } else if (cmd_of(id) == Cmd::GetEncoderEstimates && frame.len >= 8) {
        position_turns_ = can::get_f32(frame, 0);
        velocity_turns_ = can::get_f32(frame, 4);
        stamp_ = now;
    }
    return true;
}

void OdriveAxis::arm(TimePoint now, can::FrameSink& bus) {
    bus.send_frame(clear_errors(node_));
    bus.send_frame(f32_pair(node_, Cmd::SetTrajVelLimit, traj_velocity_, 0.0f));
    bus.send_frame(f32_pair(node_, Cmd::SetTrajAccelLimits, traj_accel_, traj_accel_));
    bus.send_frame(set_controller_mode(node_, kVelocityControl, kInputPassthrough));
    bus.send_frame(set_input_vel(node_, 0.0f));
    bus.send_frame(set_axis_state(node_, kAxisClosedLoop));
    mode_ = ptu::CommandMode::Velocity;
    phase_ = Phase::Arming;
    arm_deadline_ = now + kArmTimeout;
}

void OdriveAxis::send_setpoint(const ptu::AxisCommand& command, bool moving, can::FrameSink& bus) {
    const ptu::CommandMode mode = moving ? command.mode : ptu::CommandMode::Velocity;
    if (mode != mode_) {
        bus.send_frame(mode == ptu::CommandMode::Position ? set_controller_mode(node_, kPositionControl, kInputTrapTraj)
                                                          : set_controller_mode(node_, kVelocityControl, kInputPassthrough));
        mode_ = mode;
    }
    const double value = moving && std::isfinite(command.value) ? command.value * turns_per_rad_ : 0.0;
    bus.send_frame(mode == ptu::CommandMode::Position ? set_input_pos(node_, static_cast<float>(value))
                                                      : set_input_vel(node_, static_cast<float>(value)));
}

void OdriveAxis::cycle(const ptu::AxisCommand& command, bool enable, TimePoint now, can::FrameSink& bus) {
    if (phase_ != Phase::Waiting && heartbeat_seen_ && now - last_heartbeat_ > heartbeat_timeout_) {
        fail(now, "heartbeat lost (none for %lld ms)",
             static_cast<long long>(std::chrono::duration_cast<std::chrono::milliseconds>(now - last_heartbeat_).count()));
        heartbeat_seen_ = false;
    }
    switch (phase_) {
        case Phase::Waiting:
            break;
        case Phase::Backoff:
            if (heartbeat_seen_ && enable && now >= retry_at_) arm(now, bus);
            break;
        case Phase::Ready:
            if (enable) arm(now, bus);
            break;
        case Phase::Arming:
            if (now > arm_deadline_)
                fail(now, "did not enter closed loop control (axis state %u, axis error 0x%08X)", axis_state_, axis_error_);
            else
                bus.send_frame(set_input_vel(node_, 0.0f));  // feeds the watchdog meanwhile
            break;
        case Phase::Running:
            send_setpoint(command, enable && status_.ok, bus);
            break;
    }
}

void OdriveAxis::stop(can::FrameSink& bus) {
    // Also an axis left in closed loop by an earlier run (raysd --stop-axes: configure, stop, deactivate).
    if (phase_ == Phase::Running || phase_ == Phase::Arming || axis_state_ == kAxisClosedLoop) {
        if (mode_ != ptu::CommandMode::Velocity)
            bus.send_frame(set_controller_mode(node_, kVelocityControl, kInputPassthrough));
        bus.send_frame(set_input_vel(node_, 0.0f));
        bus.send_frame(set_axis_state(node_, kAxisIdle));
    }
    phase_ = Phase::Waiting;
}

ptu::AxisState OdriveAxis::state() const {
    return ptu::AxisState{position_turns_ / turns_per_rad_, velocity_turns_ / turns_per_rad_, enabled(), faulted(),
                          absolute_};
}

}  // namespace rays::odrive
