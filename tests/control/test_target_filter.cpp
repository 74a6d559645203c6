// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "control/target_filter.hpp"

using namespace rays::control;

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kFrame = 0.04;  // 25 fps
}  // namespace

TEST_CASE("the filter recovers a constant angular velocity from noisy sightings") {
    TargetFilterSettings settings;
    settings.measurement_rad = 0.1 * kDeg;
    settings.accel_rad_s2 = 0.1;  // a steadily moving target
    TargetFilter filter(settings);
    std::mt19937 random(7);
    std::normal_distribution<double> noise(0.0, settings.measurement_rad);
    const double az_rate = 20 * kDeg, el_rate = -5 * kDeg;
    for (int k = 0; k <= 100; ++k) {
        double t = k * kFrame;
        filter.update({10 * kDeg + az_rate * t + noise(random), 3 * kDeg + el_rate * t + noise(random)}, t);
    }
    TargetEstimate now = filter.at(4.0);
    CHECK(now.azimuth_rate == Approx(az_rate).margin(0.5 * kDeg));
    CHECK(now.elevation_rate == Approx(el_rate).margin(0.5 * kDeg));
    CHECK(now.angles.azimuth == Approx(10 * kDeg + az_rate * 4.0).margin(0.1 * kDeg));
    // Extrapolation half a second ahead follows the motion.
    TargetEstimate ahead = filter.at(4.5);
    CHECK(ahead.angles.azimuth == Approx(10 * kDeg + az_rate * 4.5).margin(0.4 * kDeg));
    CHECK(ahead.angles.elevation == Approx(3 * kDeg + el_rate * 4.5).margin(0.4 * kDeg));
}

TEST_CASE("the filter follows a change of speed within a second") {
    TargetFilter filter;
    double az = 0;
    for (int k = 0; k <= 50; ++k) {  // 2 s at 10 deg/s, then 2 s at 40 deg/s
        filter.update({az, 0.0}, k * kFrame);
        az += 10 * kDeg * kFrame;
    }
    for (int k = 51; k <= 75; ++k) {
        az += 40 * kDeg * kFrame;
        filter.update({az, 0.0}, k * kFrame);
    }
    CHECK(filter.at(75 * kFrame).azimuth_rate == Approx(40 * kDeg).margin(4 * kDeg));
}

TEST_CASE("azimuth wraps at ±180° without a jump in the estimate") {
    TargetFilter filter;
    const double rate = 30 * kDeg;
    for (int k = 0; k <= 60; ++k) {
        double t = k * kFrame;
        double az = std::remainder(170 * kDeg + rate * t, 2 * 3.14159265358979323846);
        REQUIRE(filter.update({az, 0.0}, t) == (k > 0));  // never restarted by the wrap
    }
    CHECK(filter.at(60 * kFrame).azimuth_rate == Approx(rate).margin(0.5 * kDeg));
}

TEST_CASE("a sighting far outside the prediction restarts the filter there") {
    TargetFilter filter;
    for (int k = 0; k < 20; ++k) filter.update({0.01 * k, 0.0}, k * kFrame);
    CHECK_FALSE(filter.update({1.5, 0.4}, 20 * kFrame));
    TargetEstimate now = filter.at(20 * kFrame);
    CHECK(now.angles.azimuth == Approx(1.5));
    CHECK(now.angles.elevation == Approx(0.4));
    CHECK(now.azimuth_rate == 0.0);
}

TEST_CASE("the acceleration model predicts a swinging target where the velocity model overshoots") {
    // A target swinging as 80°·sin(3 t) (240 deg/s at the middle, 720 deg/s² at the ends), seen at
    // 25 fps; each filter predicts 0.15 s past its last sighting, as the loop does with camera latency.
    auto truth = [](double t) { return 80 * kDeg * std::sin(3.0 * t); };
    auto prediction_error = [&](TargetFilterSettings settings) {
        settings.measurement_rad = 0.05 * kDeg;
        TargetFilter filter(settings);
        std::mt19937 random(3);
        std::normal_distribution<double> noise(0.0, settings.measurement_rad);
        double worst = 0;
        for (int k = 0; k <= 250; ++k) {
            const double t = k * kFrame;
            filter.update({truth(t) + noise(random), 0.0}, t);
            if (k >= 50) worst = std::max(worst, std::abs(filter.at(t + 0.15).angles.azimuth - truth(t + 0.15)));
        }
        return worst;
    };
    TargetFilterSettings velocity;
    velocity.accel_rad_s2 = 720 * kDeg;
    TargetFilterSettings acceleration;
    acceleration.motion = TargetMotion::ConstantAcceleration;
    acceleration.jerk_rad_s3 = 2200 * kDeg;  // the swing's largest jerk, 80°·3³
    const double v = prediction_error(velocity), a = prediction_error(acceleration);
    INFO("worst error 0.15 s ahead: velocity model " << v / kDeg << " deg, acceleration model " << a / kDeg << " deg");
    CHECK(a < 5 * kDeg);
    CHECK(v > 2 * a);
}

TEST_CASE("the acceleration model recovers a constant acceleration, and at rest stays at rest") {
    TargetFilterSettings settings;
    settings.motion = TargetMotion::ConstantAcceleration;
    settings.jerk_rad_s3 = 0.5;
    settings.measurement_rad = 0.05 * kDeg;
    TargetFilter filter(settings);
    const double accel = 20 * kDeg;  // from 0, along azimuth
    for (int k = 0; k <= 75; ++k) {
        const double t = k * kFrame;
        filter.update({0.5 * accel * t * t, 2 * kDeg}, t);
    }
    const double t = 75 * kFrame;
    const TargetEstimate now = filter.at(t);
    CHECK(now.azimuth_rate == Approx(accel * t).margin(1 * kDeg));
    CHECK(filter.at(t + 0.5).angles.azimuth == Approx(0.5 * accel * (t + 0.5) * (t + 0.5)).margin(0.5 * kDeg));
    CHECK(now.elevation_rate == Approx(0.0).margin(0.1 * kDeg));
    CHECK(filter.at(t + 0.5).angles.elevation == Approx(2 * kDeg).margin(0.1 * kDeg));
}
