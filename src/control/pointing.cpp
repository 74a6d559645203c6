#include "control/pointing.hpp"

#include <cmath>

namespace rays::control {
namespace {

constexpr double kCentre = (kFrameSize - 1) / 2.0;  // pixel centres at integers

// Focal length in pixels for a field of view across the frame.
double focal_px(double fov_rad) { return (kFrameSize / 2.0) / std::tan(fov_rad / 2.0); }

double velocity(double offset_rad, double gain_per_s, double deadband_rad) {
    return std::abs(offset_rad) <= deadband_rad ? 0.0 : gain_per_s * offset_rad;
}

}  // namespace

AngularOffset pixel_to_angle(Point pixel, FieldOfView fov) {
    return {std::atan((pixel.x - kCentre) / focal_px(fov.horizontal_rad)),
            -std::atan((pixel.y - kCentre) / focal_px(fov.vertical_rad))};  // image y grows downward
}

ptu::PtuCommand proportional_command(AngularOffset offset, double gain_per_s, double deadband_rad) {
    ptu::PtuCommand command;
    command.axes[0] = {ptu::CommandMode::Velocity, velocity(offset.pan_rad, gain_per_s, deadband_rad)};
    command.axes[1] = {ptu::CommandMode::Velocity, velocity(offset.tilt_rad, gain_per_s, deadband_rad)};
    return command;
}

}  // namespace rays::control
