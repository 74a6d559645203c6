// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/servo_model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace rays::gpio {

ServoModel::ServoModel(const ServoRange& range, double start_rad, TimePoint start)
    : range_(range), target_(clamp(start_rad)), estimate_(target_), time_(start) {}

double ServoModel::clamp(double rad) const {
    if (!std::isfinite(rad)) return std::clamp(estimate_, range_.min_rad, range_.max_rad);
    return std::clamp(rad, range_.min_rad, range_.max_rad);
}

long ServoModel::pulse_ns(double rad) const {
    const double fraction = (clamp(rad) - range_.min_rad) / (range_.max_rad - range_.min_rad);
    return std::lround(range_.min_pulse_ns + fraction * (range_.max_pulse_ns - range_.min_pulse_ns));
}

void ServoModel::command(double rad, TimePoint now) {
    advance(now);
    target_ = clamp(rad);
}

void ServoModel::advance(TimePoint now) {
    if (now <= time_) return;
    const double dt = std::chrono::duration<double>(now - time_).count();
    const double step = range_.speed_rad_s * dt;
    const double before = estimate_;
    estimate_ = target_ > estimate_ ? std::min(target_, estimate_ + step) : std::max(target_, estimate_ - step);
    velocity_ = (estimate_ - before) / dt;
    time_ = now;
}

}  // namespace rays::gpio
