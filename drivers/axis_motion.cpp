// SPDX-License-Identifier: Apache-2.0
#include "drivers/axis_motion.hpp"

#include <cmath>

namespace rays::ptu {
namespace {

// A braking distance this close to the distance left means the axis is on its braking curve: it
// absorbs the rounding of earlier phases instead of adding tiny corrective ones.
constexpr double kOnCurveRelative = 1e-9;
constexpr double kOnCurveAbsolute = 1e-12;  // rad

}  // namespace

MotionPhase velocity_phase(double velocity, double target_velocity, double max_accel) {
    if (velocity == target_velocity) return {0.0, std::numeric_limits<double>::infinity(), velocity, false};
    const double accel = target_velocity > velocity ? max_accel : -max_accel;
    return {accel, std::abs(target_velocity - velocity) / max_accel, target_velocity, false};
}

MotionPhase position_phase(double position, double velocity, double target, double max_velocity,
                           double max_accel) {
    const double offset = target - position;
    if (offset == 0.0) {
        if (velocity == 0.0) return {0.0, std::numeric_limits<double>::infinity(), 0.0, false};
        return velocity_phase(velocity, 0.0, max_accel);  // on the target but moving: brake, then return
    }
    // Work along the direction to the target: distance > 0, speed > 0 means approaching.
    const double direction = offset > 0.0 ? 1.0 : -1.0;
    const double distance = std::abs(offset);
    const double speed = direction * velocity;
    if (speed < 0.0) return {direction * max_accel, -speed / max_accel, 0.0, false};  // turn round first

    const double braking = speed * speed / (2.0 * max_accel);
    if (speed > 0.0 && std::abs(braking - distance) <= kOnCurveRelative * distance + kOnCurveAbsolute)
        return {-direction * speed * speed / (2.0 * distance), 2.0 * distance / speed, 0.0, true};
    if (braking > distance) return {-direction * max_accel, speed / max_accel, 0.0, false};  // overshoots
    if (speed > max_velocity)
        return {-direction * max_accel, (speed - max_velocity) / max_accel, direction * max_velocity, false};
    if (speed < max_velocity) {
        // Accelerate until the cruise speed or the braking curve, whichever comes first.
        const double peak = std::sqrt(0.5 * speed * speed + max_accel * distance);
        if (peak >= max_velocity)
            return {direction * max_accel, (max_velocity - speed) / max_accel, direction * max_velocity, false};
        return {direction * max_accel, (distance - braking) / (peak + speed), direction * peak, false};
    }
    return {0.0, (distance - braking) / max_velocity, velocity, false};  // cruise to the braking point
}

}  // namespace rays::ptu
