// SPDX-License-Identifier: Apache-2.0
#include "control/proportional_controller.hpp"

#include <algorithm>
#include <cmath>

namespace rays::control {

ptu::PtuCommand velocity_command(double pan_rate, double tilt_rate, const ControllerSettings& settings) {
    auto held = [&](double rate) { return std::clamp(rate, -settings.max_velocity_rad_s, settings.max_velocity_rad_s); };
    ptu::PtuCommand command;
    command.axes[0] = {ptu::CommandMode::Velocity, held(pan_rate)};
    command.axes[1] = {ptu::CommandMode::Velocity, held(tilt_rate)};
    return command;
}

void ProportionalController::sighted(Point pixel, const UnitPose& unit, double) {
    WorldAngles target = camera_.world_angles(pixel, unit.pan, unit.tilt);
    pan_error_ = angle_difference(target.azimuth, unit.pan);
    tilt_error_ = target.elevation - unit.tilt;
    has_target_ = true;
}

ptu::PtuCommand ProportionalController::command(const UnitPose&) const {
    if (!has_target_) return ptu::PtuCommand::stop();
    auto rate = [&](double error) { return std::abs(error) <= settings_.deadband_rad ? 0.0 : settings_.gain_per_s * error; };
    return velocity_command(rate(pan_error_), rate(tilt_error_), settings_);
}

}  // namespace rays::control
