// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/sim/odrive_sim_axis.hpp"

#include "drivers/can/can_frame_codec.hpp"
#include "drivers/can/odrive/odrive_protocol.hpp"

namespace rays::odrive {

OdriveSimAxis::OdriveSimAxis(const OdriveSimConfig& config) : config_(config), axis_(config.dynamics) {
    received_.reserve(config.record_capacity);
}

void OdriveSimAxis::go_idle(TimePoint now) {
    if (state_ == kAxisClosedLoop) axis_.halt(now);
    state_ = kAxisIdle;
}

void OdriveSimAxis::on_frame(const can_frame& frame, TimePoint now, can::FrameSink& bus) {
    (void)bus;
    std::lock_guard lock(mutex_);
    const std::uint32_t id = can::standard_id(frame);
    if (id == 0xFFFFFFFFu || node_of(id) != config_.node) return;
    const Cmd cmd = cmd_of(id);
    if (cmd == Cmd::Heartbeat || cmd == Cmd::GetEncoderEstimates) return;  // another node's echo, not for us
    if (received_.size() < received_.capacity()) received_.push_back({now, frame});
    axis_.advance(now);
    last_feed_ = now;  // can_simple.cpp do_command: axis.watchdog_feed() on every message to the axis
    fed_ = true;
    switch (cmd) {
        case Cmd::SetAxisState: {
            const std::uint32_t requested = can::get_u32(frame, 0);
            if (requested == kAxisClosedLoop && error_ == 0) state_ = kAxisClosedLoop;
            else if (requested == kAxisIdle) go_idle(now);
            break;
        }
        case Cmd::SetControllerMode:
            control_mode_ = can::get_u32(frame, 0);
            input_mode_ = can::get_u32(frame, 4);
            break;
        case Cmd::SetInputVel:
            if (state_ == kAxisClosedLoop && control_mode_ == kVelocityControl)
                axis_.command({ptu::CommandMode::Velocity, can::get_f32(frame, 0) / config_.turns_per_rad}, now);
            break;
        case Cmd::SetInputPos:
            if (state_ == kAxisClosedLoop && control_mode_ == kPositionControl)
                axis_.command({ptu::CommandMode::Position, can::get_f32(frame, 0) / config_.turns_per_rad}, now);
            break;
        case Cmd::SetTrajVelLimit:  // the trapezoidal trajectory's cruise speed
            axis_.set_position_velocity(can::get_f32(frame, 0) / config_.turns_per_rad);
            break;
        case Cmd::ClearErrors:
            if (!fault_condition_) error_ = 0;
            break;
        case Cmd::Estop:
            error_ |= 0x00000040;  // ESTOP_REQUESTED (v0.5)
            go_idle(now);
            break;
        default:
            break;
    }
}

void OdriveSimAxis::tick(TimePoint now, can::FrameSink& bus) {
    std::lock_guard lock(mutex_);
    axis_.advance(now);
    if (config_.enable_watchdog && fed_ && state_ == kAxisClosedLoop &&
        now - last_feed_ > std::chrono::duration<double>(config_.watchdog_timeout_s)) {
        error_ |= kErrorWatchdogExpired;
        go_idle(now);
    }
    if (fault_condition_ && state_ == kAxisClosedLoop) go_idle(now);
    if (muted_) return;
    if (!heartbeat_stopped_ && now >= next_heartbeat_) {
        can_frame frame = can::make_frame(frame_id(config_.node, Cmd::Heartbeat), 8);
        can::put_u32(frame, 0, error_);
        frame.data[4] = static_cast<std::uint8_t>(state_);
        bus.send_frame(frame);
        next_heartbeat_ = now + std::chrono::milliseconds(config_.heartbeat_ms);
    }
    if (now >= next_encoder_) {
        bus.send_frame(f32_pair(config_.node, Cmd::GetEncoderEstimates,
                                static_cast<float>(axis_.position() * config_.turns_per_rad),
                                static_cast<float>(axis_.velocity() * config_.turns_per_rad)));
        next_encoder_ = now + std::chrono::milliseconds(config_.encoder_ms);
    }
}

double OdriveSimAxis::position_rad() const { std::lock_guard lock(mutex_); return axis_.position(); }
double OdriveSimAxis::velocity_rad_s() const { std::lock_guard lock(mutex_); return axis_.velocity(); }
std::uint32_t OdriveSimAxis::axis_state() const { std::lock_guard lock(mutex_); return state_; }
std::uint32_t OdriveSimAxis::axis_error() const { std::lock_guard lock(mutex_); return error_; }
std::vector<canopen::ReceivedFrame> OdriveSimAxis::received() const { std::lock_guard lock(mutex_); return received_; }

void OdriveSimAxis::inject_error(std::uint32_t error) {
    std::lock_guard lock(mutex_);
    fault_condition_ = true;
    error_ |= error;
}

void OdriveSimAxis::clear_fault() { std::lock_guard lock(mutex_); fault_condition_ = false; }
void OdriveSimAxis::stop_heartbeat(bool stopped) { std::lock_guard lock(mutex_); heartbeat_stopped_ = stopped; }
void OdriveSimAxis::mute(bool muted) { std::lock_guard lock(mutex_); muted_ = muted; }

}  // namespace rays::odrive
