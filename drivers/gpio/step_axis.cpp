// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/step_axis.hpp"

#include <algorithm>
#include <cmath>

namespace rays::gpio {
namespace {

constexpr double kSlowest = 0.01;  // steps/s; slower wanted speeds are zero

// The speed one step of braking leaves; 0 when that is rounding (w² = 2·accel up to the last bits).
double braked(double speed, double accel) {
    const double rest = speed * speed - 2.0 * accel;
    return rest > 1e-9 * speed * speed ? std::sqrt(rest) : 0.0;
}

TimePoint::duration seconds(double s) {
    return std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(s));
}

}  // namespace

double speed_toward(double speed, double wanted, double accel) {
    const double up = std::sqrt(speed * speed + 2.0 * accel);
    const double down = braked(speed, accel);
    if (wanted < kSlowest) return down;
    if (speed < wanted) return std::min(up, wanted);
    if (speed > wanted) return std::max(down, wanted);
    return speed;
}

double speed_to_target(double speed, long remaining, double max_speed, double accel) {
    const double down = braked(speed, accel);
    if (remaining <= 0) return down;  // on or past the target: brake, come back from rest
    const double up = std::sqrt(speed * speed + 2.0 * accel);
    // From w at the next step, stopping within `remaining` steps needs w² ≤ 2·accel·remaining.
    const double braking = std::sqrt(2.0 * accel * static_cast<double>(remaining));
    return std::max(down, std::min({up, max_speed, braking}));
}

StepAxis::StepAxis(const AxisKinematics& kinematics, double max_step_rate_hz, double dir_setup_s)
    : kinematics_(kinematics),
      min_interval_(seconds(1.0 / max_step_rate_hz)),
      dir_setup_(seconds(dir_setup_s)),
      start_interval_(std::max(min_interval_, seconds(std::sqrt(2.0 / kinematics.accel)))) {}

double StepAxis::next_speed(const AxisGoal& goal) const {
    switch (goal.kind) {
    case AxisGoal::Kind::Halt:
        return 0.0;
    case AxisGoal::Kind::Stop:
        return speed_toward(speed_, 0.0, kinematics_.accel);
    case AxisGoal::Kind::Velocity:
        return speed_toward(speed_, std::min(goal.velocity * travel_, goal.max_speed), kinematics_.accel);
    case AxisGoal::Kind::Position:
        return speed_to_target(speed_, (goal.target - position_) * travel_, goal.max_speed, kinematics_.accel);
    }
    return 0.0;
}

int StepAxis::start_direction(const AxisGoal& goal) const {
    if (goal.kind == AxisGoal::Kind::Velocity && std::abs(goal.velocity) >= kSlowest && goal.max_speed >= kSlowest)
        return goal.velocity > 0.0 ? 1 : -1;
    if (goal.kind == AxisGoal::Kind::Position && goal.target != position_) return goal.target > position_ ? 1 : -1;
    return 0;
}

void StepAxis::plan(const AxisGoal& goal, TimePoint now) {
    action_ = Action::None;
    due_ = TimePoint::max();
    if (moving_) {
        next_speed_ = next_speed(goal);
        if (next_speed_ > 0.0) {
            interval_ = std::max(min_interval_, seconds(2.0 / (speed_ + next_speed_)));
            action_ = Action::Step;
            due_ = last_step_ + interval_;
            return;
        }
        halt();
    }
    const int direction = start_direction(goal);
    if (direction == 0) return;
    if (direction != direction_) {
        action_ = Action::SetDir;
        wanted_direction_ = direction;
        due_ = now;
        return;
    }
    action_ = Action::Step;
    due_ = std::max(now, dir_time_ + dir_setup_);
    if (stepped_before_) due_ = std::max(due_, last_step_ + start_interval_);
}

void StepAxis::dir_set(int direction, TimePoint at) {
    direction_ = direction;
    dir_time_ = at;
}

void StepAxis::stepped(TimePoint at) {
    const double speed_before = speed_;
    if (!moving_) {
        moving_ = true;
        travel_ = direction_;
        speed_ = 0.0;
    } else {
        speed_ = next_speed_;
        if (at > due_) lost_steps_ += std::chrono::duration<double>(at - due_) / interval_;
        if (at - due_ > kJitter) {
            // Late beyond jitter: the speed the axis had over the interval it made (less the jitter
            // allowed), not the one planned.
            const double made = std::chrono::duration<double>(at - last_step_ - kJitter).count();
            speed_ = std::min(speed_, std::max(1.0 / made, 2.0 / made - speed_before));
            ++late_edges_;
        }
    }
    position_ += travel_;
    last_step_ = at;
    stepped_before_ = true;
}

void StepAxis::halt() {
    moving_ = false;
    speed_ = 0.0;
    next_speed_ = 0.0;
    action_ = Action::None;
    due_ = TimePoint::max();
}

double StepAxis::velocity() const { return moving_ ? travel_ * 0.5 * (speed_ + next_speed_) : 0.0; }

}  // namespace rays::gpio
