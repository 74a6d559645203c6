// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>
#include <cmath>

#include "control/camera_model.hpp"

using namespace rays;
using namespace rays::control;

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
}

TEST_CASE("the frame's centre looks along the optical axis, wherever the unit points") {
    CameraModel camera = CameraModel::from_fov(60 * kDeg, 45 * kDeg);
    for (double pan : {-150.0, -20.0, 0.0, 35.0, 170.0})
        for (double tilt : {-30.0, 0.0, 10.0, 80.0}) {
            WorldAngles a = camera.world_angles({63.5, 63.5}, pan * kDeg, tilt * kDeg);
            CHECK(a.azimuth == Approx(pan * kDeg).margin(1e-12));
            CHECK(a.elevation == Approx(tilt * kDeg).margin(1e-12));
        }
}

TEST_CASE("the frame's edges are half the field of view off the axis") {
    CameraModel camera = CameraModel::from_fov(60 * kDeg, 45 * kDeg);
    // The left edge of pixel 0 is at x = -0.5, the right edge of pixel 127 at 127.5.
    CHECK(camera.world_angles({127.5, 63.5}, 0, 0).azimuth == Approx(30 * kDeg));
    CHECK(camera.world_angles({-0.5, 63.5}, 0, 0).azimuth == Approx(-30 * kDeg));
    CHECK(camera.world_angles({63.5, -0.5}, 0, 0).elevation == Approx(22.5 * kDeg));  // image top is up
    CHECK(camera.world_angles({63.5, 127.5}, 0, 0).elevation == Approx(-22.5 * kDeg));
}

TEST_CASE("pixel to world angles and back is the identity, for FOV and calibrated intrinsics") {
    CameraModel fov = CameraModel::from_fov(50 * kDeg, 40 * kDeg);
    CameraModel calibrated = CameraModel::from_intrinsics({150.0, 140.0, 60.2, 66.9});
    for (const CameraModel* camera : {&fov, &calibrated})
        for (double x : {0.0, 17.3, 63.5, 127.0})
            for (double y : {0.0, 40.0, 127.0}) {
                double pan = 25 * kDeg, tilt = -12 * kDeg;
                WorldAngles a = camera->world_angles({x, y}, pan, tilt);
                std::optional<Point> back = camera->pixel_of(a, pan, tilt);
                REQUIRE(back);
                CHECK(back->x == Approx(x).margin(1e-9));
                CHECK(back->y == Approx(y).margin(1e-9));
            }
}

TEST_CASE("turning the unit toward a target brings it to the frame's centre") {
    CameraModel camera = CameraModel::from_fov(60 * kDeg, 60 * kDeg);
    Point target{100.0, 20.0};  // right of and above the centre
    WorldAngles a = camera.world_angles(target, 10 * kDeg, 5 * kDeg);
    CHECK(a.azimuth > 10 * kDeg);
    CHECK(a.elevation > 5 * kDeg);
    std::optional<Point> centred = camera.pixel_of(a, a.azimuth, a.elevation);
    REQUIRE(centred);
    CHECK(centred->x == Approx(63.5).margin(1e-9));
    CHECK(centred->y == Approx(63.5).margin(1e-9));
}

TEST_CASE("a direction behind the camera has no pixel") {
    CameraModel camera = CameraModel::from_fov(60 * kDeg, 60 * kDeg);
    CHECK_FALSE(camera.pixel_of({180 * kDeg, 0}, 0, 0));
    CHECK_FALSE(camera.project(Eigen::Vector3d(0, 0, -1)));
}

TEST_CASE("angle differences take the short way round") {
    CHECK(angle_difference(170 * kDeg, -170 * kDeg) == Approx(-20 * kDeg));
    CHECK(angle_difference(-170 * kDeg, 170 * kDeg) == Approx(20 * kDeg));
    CHECK(angle_difference(0.3, 0.1) == Approx(0.2));
}
