// SPDX-License-Identifier: Apache-2.0
// Camera geometry (Eigen): a pinhole camera on a pan/tilt unit. Pixel ↔ viewing ray from the field
// of view or from calibrated intrinsics, and the rig's rotation, so a contour's centre becomes the
// target's direction in world angles — what the controller and the Kalman filter work in.
//
// Frames: the camera's is x right, y down, z along the optical axis; the world's equals it at pan =
// tilt = 0. Pan turns about the vertical axis, positive to the right; tilt turns about the pan-rotated
// horizontal axis, positive up (the tilt axis rides on the pan axis). World angles: azimuth positive
// right, elevation positive up, both rad. Pixels: processing frame (128×128), centres at integers.
#pragma once
#include <Eigen/Core>
#include <optional>

#include "core/image.hpp"

namespace rays::control {

struct Intrinsics {
    double fx = 0, fy = 0;  // focal lengths, processing px
    double cx = 0, cy = 0;  // principal point, processing px
};

struct WorldAngles {
    double azimuth = 0;    // rad, positive right
    double elevation = 0;  // rad, positive up
};

class CameraModel {
public:
    // Fields of view across the 128-pixel width and height, principal point at the frame's centre.
    static CameraModel from_fov(double horizontal_rad, double vertical_rad);
    static CameraModel from_intrinsics(const Intrinsics& intrinsics);

    const Intrinsics& intrinsics() const { return k_; }

    Eigen::Vector3d ray(Point pixel) const;  // unit viewing ray in the camera frame
    // The pixel a camera-frame direction lands on; nullopt for directions at or behind the camera.
    std::optional<Point> project(const Eigen::Vector3d& direction) const;

    // Where the pixel looks, in world angles, with the unit at (pan, tilt).
    WorldAngles world_angles(Point pixel, double pan_rad, double tilt_rad) const;
    // The pixel showing a world direction with the unit at (pan, tilt); nullopt when behind.
    std::optional<Point> pixel_of(WorldAngles target, double pan_rad, double tilt_rad) const;
    // How far turning the unit from (pan0, tilt0) to (pan1, tilt1) moves the view, px: where the
    // direction seen at the frame's centre before is seen after (this(x) = before(x − shift) near
    // the centre; a turn about the lens shows no parallax). nullopt when it is then behind the camera.
    std::optional<Point> view_shift(double pan0_rad, double tilt0_rad, double pan1_rad, double tilt1_rad) const;

private:
    explicit CameraModel(const Intrinsics& k) : k_(k) {}
    Intrinsics k_;
};

// Rotation taking camera-frame vectors to world-frame vectors with the unit at (pan, tilt).
Eigen::Matrix3d camera_to_world(double pan_rad, double tilt_rad);
Eigen::Vector3d direction_of(WorldAngles angles);  // unit vector, world frame
WorldAngles angles_of(const Eigen::Vector3d& world_direction);

// a − b wrapped into (−π, π]: the short way round.
double angle_difference(double a, double b);

}  // namespace rays::control
