// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/homing.hpp"

#include <chrono>

namespace rays::gpio {

Homing::Homing(const AxisKinematics& kinematics, int home_side, double timeout_s)
    : kinematics_(kinematics),
      side_(home_side),
      timeout_(std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(timeout_s))) {}

void Homing::start(TimePoint now) {
    phase_ = Phase::Seek;
    started_ = now;
}

Homing::Step Homing::update(bool home_switch, bool opposite_switch, const StepAxis& axis, TimePoint now) {
    const double speed = kinematics_.homing_speed;
    const AxisGoal toward{AxisGoal::Kind::Velocity, side_ * speed, 0, speed};
    const AxisGoal away{AxisGoal::Kind::Velocity, -side_ * speed, 0, speed};
    if (phase_ == Phase::Idle) return {AxisGoal::stop()};
    if (now - started_ > timeout_) {
        phase_ = Phase::Idle;
        return {AxisGoal::halt(), false, "homing timed out"};
    }
    if (opposite_switch && phase_ == Phase::Seek) {
        phase_ = Phase::Idle;
        return {AxisGoal::halt(), false, "homing hit the opposite limit switch"};
    }
    switch (phase_) {
    case Phase::Seek:
        if (!home_switch) return {toward};
        phase_ = Phase::Release;
        return {AxisGoal::halt()};  // on the switch: stop at once (homing speed is slow)
    case Phase::Release:
        if (home_switch) return {away};
        phase_ = Phase::Backoff;
        backoff_target_ = axis.position() - side_ * kinematics_.backoff_steps;
        return {AxisGoal{AxisGoal::Kind::Position, 0.0, backoff_target_, speed}};
    case Phase::Backoff:
        if (!axis.at_rest() || axis.position() != backoff_target_)
            return {AxisGoal{AxisGoal::Kind::Position, 0.0, backoff_target_, speed}};
        phase_ = Phase::Idle;
        return {AxisGoal::stop(), true};
    case Phase::Idle:
        break;
    }
    return {AxisGoal::stop()};
}

}  // namespace rays::gpio
