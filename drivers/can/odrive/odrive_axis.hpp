// SPDX-License-Identifier: Apache-2.0
// One ODrive axis as raysd runs it, on the driver's I/O thread: its heartbeat watched, armed by
// Clear_Errors, trajectory limits, Set_Controller_Mode and Set_Axis_State(CLOSED_LOOP_CONTROL),
// then a set-point every cycle (Set_Input_Vel, or Set_Input_Pos with the trapezoidal trajectory),
// which also feeds the ODrive's watchdog. Axis errors and a lost heartbeat are faults; the axis is
// re-armed with backoff (0.5 s doubling to 8 s) once it reports again. No allocation.
#pragma once
#include <cstdint>

#include "core/clock.hpp"
#include "drivers/can/can_transport.hpp"
#include "drivers/can/odrive/odrive_settings.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::odrive {

class OdriveAxis {
public:
    OdriveAxis(const char* label, int node, double turns_per_rad, const OdriveSettings& settings);

    void start(TimePoint now);  // wait for its heartbeat
    void forget_faults();
    bool on_frame(const can_frame& frame, TimePoint now);
    void lose(const char* why, TimePoint now);
    void cycle(const ptu::AxisCommand& command, bool enable, TimePoint now, can::FrameSink& bus);
    void stop(can::FrameSink& bus);  // zero velocity, then idle (an axis in closed loop, whoever armed it)

    bool configured() const { return phase_ != Phase::Waiting; }
    bool enabled() const { return phase_ == Phase::Running && status_.ok; }
    bool faulted() const { return !status_.ok; }
    ptu::AxisState state() const;
    TimePoint stamp() const { return stamp_; }
    const ptu::DriverStatus& status() const { return status_; }

private:
    enum class Phase { Waiting, Ready, Arming, Running, Backoff };

    void fail(TimePoint now, const char* format, ...) __attribute__((format(printf, 3, 4)));
    void arm(TimePoint now, can::FrameSink& bus);
    void send_setpoint(const ptu::AxisCommand& command, bool moving, can::FrameSink& bus);

    const char* label_;
    const int node_;
    const double turns_per_rad_;
    const float traj_velocity_, traj_accel_;  // turns/s, turns/s²
    const TimePoint::duration heartbeat_timeout_;
    const bool absolute_;

    Phase phase_ = Phase::Waiting;
    ptu::DriverStatus status_;
    double backoff_s_ = 0.5;
    TimePoint retry_at_{}, arm_deadline_{}, last_heartbeat_{}, stamp_{};
    bool heartbeat_seen_ = false;
    std::uint32_t axis_error_ = 0;
    std::uint8_t axis_state_ = 0;
    float position_turns_ = 0.0f, velocity_turns_ = 0.0f;
    ptu::CommandMode mode_ = ptu::CommandMode::Velocity;
};

}  // namespace rays::odrive
