// SPDX-License-Identifier: Apache-2.0
// One RC servo as the driver sees it, without I/O: the angle range its pulse range maps to (linear),
// the commanded angle, and the estimated angle — moving toward the command at the rated speed, as a
// servo gives no feedback. Angles in radians. Time comes in as arguments.
#pragma once
#include "core/clock.hpp"

namespace rays::gpio {

struct ServoRange {
    double min_pulse_ns = 1e6;
    double max_pulse_ns = 2e6;
    double min_rad = -1.5708;
    double max_rad = 1.5708;
    double speed_rad_s = 5.0;
};

class ServoModel {
public:
    ServoModel(const ServoRange& range, double start_rad, TimePoint start);

    double clamp(double rad) const;
    long pulse_ns(double rad) const;  // of the clamped angle
    // The command from `now` on (clamped); the estimate first advances to `now`.
    void command(double rad, TimePoint now);
    void advance(TimePoint now);

    double target() const { return target_; }
    double estimate() const { return estimate_; }
    double velocity() const { return velocity_; }  // of the estimate at the last advance
    TimePoint time() const { return time_; }

private:
    ServoRange range_;
    double target_;
    double estimate_;
    double velocity_ = 0.0;
    TimePoint time_;
};

}  // namespace rays::gpio
