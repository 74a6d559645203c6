// From the image to the pan/tilt unit: a pixel's direction as angles off the optical axis (pinhole
// camera with the principal point at the frame's centre), and the paper's proportional controller
// (§4) that turns the target's angular offset into axis velocities.
#pragma once
#include "core/image.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::control {

struct FieldOfView {
    double horizontal_rad = 0.0;  // across the 128-pixel width
    double vertical_rad = 0.0;    // across the 128-pixel height
};

struct AngularOffset {
    double pan_rad = 0.0;   // positive: the point is right of the optical axis
    double tilt_rad = 0.0;  // positive: above it
};

AngularOffset pixel_to_angle(Point pixel, FieldOfView fov);

// Velocity command gain · offset per axis, zero on an axis whose offset is within the deadband.
ptu::PtuCommand proportional_command(AngularOffset offset, double gain_per_s, double deadband_rad);

}  // namespace rays::control
