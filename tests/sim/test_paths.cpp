// SPDX-License-Identifier: Apache-2.0
// Target paths: keyframes with Hermite interpolation, and sums of (chirped) sine waves.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "common/angles.hpp"
#include "sim/paths.hpp"

using namespace rays;
using namespace rays::sim;

namespace {

// Central differences of the position, to compare with the rates a path reports (a keyframe's jump
// in acceleration costs the difference about h/4 of it).
void check_rates_match_positions(const Path& path, double t) {
    constexpr double h = 1e-5;
    const PathPoint before = path.at(t - h), after = path.at(t + h), at = path.at(t);
    CHECK(at.azimuth_rate == Approx((after.position.azimuth - before.position.azimuth) / (2 * h)).margin(1e-5));
    CHECK(at.elevation_rate == Approx((after.position.elevation - before.position.elevation) / (2 * h)).margin(1e-5));
}

KeyframePath square_walk() {
    return KeyframePath({{0.0, {0.0, 0.0}, 0.0, 0.0},
                         {2.0, {0.2, 0.0}, 0.15, 0.0},
                         {4.0, {0.5, 0.1}, 0.0, 0.05},
                         {6.0, {0.5, 0.1}, 0.0, 0.0},
                         {8.0, {0.0, 0.0}, 0.0, 0.0}});
}

}  // namespace

TEST_CASE("a keyframe path passes through its keyframes with their rates and repeats with its period") {
    const KeyframePath path = square_walk();
    CHECK(path.period_s() == 8.0);
    const PathPoint k1 = path.at(2.0);
    CHECK(k1.position.azimuth == Approx(0.2));
    CHECK(k1.azimuth_rate == Approx(0.15));
    CHECK(path.at(4.0).elevation_rate == Approx(0.05));
    const PathPoint pause = path.at(5.0);  // between two equal stops
    CHECK(pause.position.azimuth == Approx(0.5));
    CHECK(pause.azimuth_rate == 0.0);
    CHECK(path.at(8.0 * 3 + 2.0).position.azimuth == Approx(0.2));
    CHECK(path.at(7.999999).position.azimuth == Approx(0.0).margin(1e-6));
}

TEST_CASE("a keyframe path's velocity is continuous and its rates are its positions' derivatives") {
    const KeyframePath path = square_walk();
    for (double t : {0.5, 1.999, 2.0, 2.001, 3.3, 3.999, 4.0, 4.001, 6.5, 7.9, 8.0, 10.0})
        check_rates_match_positions(path, t);
}

TEST_CASE("a chirped wave's phase rate ramps linearly, then holds, with the phase continuous") {
    const Wave w{1.0, 0.5, 4.5, 10.0, 0.3};
    CHECK(w.rate_at(0.0) == Approx(0.5));
    CHECK(w.rate_at(5.0) == Approx(2.5));
    CHECK(w.rate_at(10.0) == Approx(4.5));
    CHECK(w.rate_at(100.0) == Approx(4.5));
    CHECK(w.phase_at(0.0) == Approx(0.3));
    CHECK(w.phase_at(10.0) == Approx(0.3 + 0.5 * 10 + 0.5 * 4.0 * 10));
    for (double t : {1.0, 9.999, 10.0, 10.001, 30.0}) {
        constexpr double h = 1e-6;
        CHECK(w.rate_at(t) == Approx((w.phase_at(t + h) - w.phase_at(t - h)) / (2 * h)).epsilon(1e-5));
    }
    const Wave steady = steady_wave(2.0, 4.0, 0.0);
    CHECK(steady.rate_at(3.0) == Approx(std::numbers::pi / 2));
}

TEST_CASE("a wave path sums its waves about its centre, rates included") {
    const WavePath path({0.1, 0.2}, {steady_wave(0.3, 10, 0), {0.1, 0.2, 2.0, 50, 1.0}}, {steady_wave(0.05, 3, 0.5)});
    const PathPoint at = path.at(2.5);
    CHECK(at.position.azimuth == Approx(0.1 + 0.3 * std::sin(2 * std::numbers::pi * 0.25) + 0.1 * std::sin(1.0 + 0.5 + 0.1125)));
    for (double t : {0.0, 1.0, 25.0, 49.9, 50.0, 80.0}) check_rates_match_positions(path, t);
}

TEST_CASE("angular speed shrinks the azimuth rate with the cosine of the elevation") {
    CHECK(angular_speed({{0.3, 0.0}, 2.0, 0.0}) == Approx(2.0));
    CHECK(angular_speed({{0.3, std::numbers::pi / 3}, 2.0, 0.0}) == Approx(1.0));
    CHECK(angular_speed({{0.3, 0.0}, 3.0, 4.0}) == Approx(5.0));
}
