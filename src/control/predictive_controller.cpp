// SPDX-License-Identifier: Apache-2.0
#include "control/predictive_controller.hpp"

#include <algorithm>
#include <cmath>

namespace rays::control {

void PredictiveController::sighted(Point pixel, const UnitPose& unit, double confidence) {
    filter_.update(camera_.world_angles(pixel, unit.pan, unit.tilt), unit.t_s, 1.0 / std::max(confidence, 1e-3));
}

namespace {

constexpr int kSettledSightings = 10;  // sightings folded in after the start before the prediction is trusted

}  // namespace

bool PredictiveController::can_coast() const { return filter_.started() && filter_.updates() >= kSettledSightings; }

bool PredictiveController::consistent(Point pixel, const UnitPose& unit) const {
    if (!filter_.started() || filter_.updates() < kSettledSightings) return true;
    const double gate = filter_.settings().gate_sigma;
    return filter_.distance2(camera_.world_angles(pixel, unit.pan, unit.tilt), unit.t_s) <= gate * gate;
}

ptu::PtuCommand PredictiveController::command(const UnitPose& unit) const {
    if (!filter_.started()) return ptu::PtuCommand::stop();
    const double ahead = unit.t_s + settings_.lead_s;
    const TargetEstimate target = filter_.at(ahead);
    const UnitPose will_be = unit.at(ahead);
    const double rates[2] = {target.azimuth_rate, target.elevation_rate};
    const double errors[2] = {angle_difference(target.angles.azimuth, will_be.pan),
                              target.angles.elevation - will_be.tilt};
    double command[2];
    for (int axis = 0; axis < 2; ++axis) {
        const bool settled = std::abs(errors[axis]) <= settings_.deadband_rad &&
                             std::abs(rates[axis]) <= settings_.still_rate_rad_s;
        command[axis] = settled ? 0.0 : rates[axis] + settings_.gain_per_s * errors[axis];
    }
    return velocity_command(command[0], command[1], settings_);
}

std::optional<Point> PredictiveController::expected_pixel(const UnitPose& unit) const {
    if (!filter_.started()) return std::nullopt;
    return camera_.pixel_of(filter_.at(unit.t_s).angles, unit.pan, unit.tilt);
}

}  // namespace rays::control
