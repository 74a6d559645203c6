// SPDX-License-Identifier: Apache-2.0
#include "control/camera_model.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace rays::control {
namespace {

constexpr double kCentre = (kFrameSize - 1) / 2.0;  // pixel centres at integers
constexpr double kMinDepth = 1e-9;

double focal_px(double fov_rad) { return (kFrameSize / 2.0) / std::tan(fov_rad / 2.0); }

}  // namespace

CameraModel CameraModel::from_fov(double horizontal_rad, double vertical_rad) {
    return CameraModel({focal_px(horizontal_rad), focal_px(vertical_rad), kCentre, kCentre});
}

CameraModel CameraModel::from_intrinsics(const Intrinsics& intrinsics) { return CameraModel(intrinsics); }

Eigen::Vector3d CameraModel::ray(Point pixel) const {
    return Eigen::Vector3d((pixel.x - k_.cx) / k_.fx, (pixel.y - k_.cy) / k_.fy, 1.0).normalized();
}

std::optional<Point> CameraModel::project(const Eigen::Vector3d& direction) const {
    if (direction.z() <= kMinDepth) return std::nullopt;
    return Point{k_.cx + k_.fx * direction.x() / direction.z(), k_.cy + k_.fy * direction.y() / direction.z()};
}

WorldAngles CameraModel::world_angles(Point pixel, double pan_rad, double tilt_rad) const {
    return angles_of(camera_to_world(pan_rad, tilt_rad) * ray(pixel));
}

std::optional<Point> CameraModel::pixel_of(WorldAngles target, double pan_rad, double tilt_rad) const {
    return project(camera_to_world(pan_rad, tilt_rad).transpose() * direction_of(target));
}

Eigen::Matrix3d camera_to_world(double pan_rad, double tilt_rad) {
    // Pan about the world's vertical (y, pointing down, so +pan turns the axis toward +x); tilt
    // about the pan-rotated x axis, turning the optical axis toward −y (up).
    Eigen::Matrix3d pan = Eigen::AngleAxisd(pan_rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
    Eigen::Matrix3d tilt = Eigen::AngleAxisd(tilt_rad, Eigen::Vector3d::UnitX()).toRotationMatrix();
    return pan * tilt;
}

Eigen::Vector3d direction_of(WorldAngles a) {
    return {std::cos(a.elevation) * std::sin(a.azimuth), -std::sin(a.elevation),
            std::cos(a.elevation) * std::cos(a.azimuth)};
}

WorldAngles angles_of(const Eigen::Vector3d& d) {
    return {std::atan2(d.x(), d.z()), std::atan2(-d.y(), std::hypot(d.x(), d.z()))};
}

double angle_difference(double a, double b) {
    double d = std::remainder(a - b, 2.0 * std::numbers::pi);
    return d <= -std::numbers::pi ? d + 2.0 * std::numbers::pi : d;
}

std::optional<Point> CameraModel::view_shift(double pan0_rad, double tilt0_rad, double pan1_rad, double tilt1_rad) const {
    const std::optional<Point> p = pixel_of(world_angles({kCentre, kCentre}, pan0_rad, tilt0_rad), pan1_rad, tilt1_rad);
    if (!p) return std::nullopt;
    return Point{p->x - kCentre, p->y - kCentre};
}

}  // namespace rays::control
