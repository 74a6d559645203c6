// SPDX-License-Identifier: Apache-2.0
// AxisDynamics: ramps, speed limit, latency, exact position moves, end stops, slicing of time.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "drivers/axis_dynamics.hpp"
#include "manual_clock.hpp"

namespace {

using rays::test::at_seconds;
using namespace rays::ptu;

constexpr double kVmax = 2.0;
constexpr double kAmax = 8.0;

AxisDynamicsConfig config(double latency_s = 0.0) { return {kVmax, kAmax, latency_s, -10.0, 10.0}; }

AxisCommand velocity(double v) { return {CommandMode::Velocity, v}; }
AxisCommand position(double x) { return {CommandMode::Position, x}; }

}  // namespace

TEST_CASE("AxisDynamics ramps velocity at max_accel and integrates the ramp exactly", "[dynamics]") {
    AxisDynamics axis(config());
    axis.command(velocity(1.0), at_seconds(0.0));
    for (double t : {0.01, 0.05, 0.1, 0.125}) {
        axis.advance(at_seconds(t));
        INFO("t " << t);
        CHECK(axis.velocity() == Approx(kAmax * t).margin(1e-12));
        CHECK(axis.position() == Approx(0.5 * kAmax * t * t).margin(1e-12));
    }
    axis.advance(at_seconds(1.0));  // reached 1 rad/s at 0.125 s, then held it
    CHECK(axis.velocity() == 1.0);
    CHECK(axis.position() == Approx(0.0625 + 0.875).margin(1e-12));
}

TEST_CASE("AxisDynamics never exceeds max_velocity", "[dynamics]") {
    AxisDynamics axis(config());
    axis.command(velocity(50.0), at_seconds(0.0));
    double peak = 0.0;
    for (int i = 1; i <= 200; ++i) {
        axis.advance(at_seconds(0.01 * i));
        peak = std::max(peak, std::abs(axis.velocity()));
    }
    CHECK(peak == kVmax);
    axis.command(velocity(-50.0), at_seconds(2.0));
    axis.advance(at_seconds(4.0));
    CHECK(axis.velocity() == -kVmax);
}

TEST_CASE("AxisDynamics acts on a command exactly latency_s after it is given", "[dynamics]") {
    AxisDynamics axis(config(0.2));
    axis.command(velocity(1.0), at_seconds(1.0));
    axis.advance(at_seconds(1.199));
    CHECK(axis.velocity() == 0.0);
    CHECK(axis.position() == 0.0);
    axis.advance(at_seconds(1.25));
    CHECK(axis.velocity() == Approx(kAmax * 0.05).margin(1e-12));
    // Commands queue in order and each keeps its own delay.
    axis.command(velocity(-1.0), at_seconds(1.3));
    axis.advance(at_seconds(1.49));
    CHECK(axis.velocity() == 1.0);
    axis.advance(at_seconds(1.55));
    CHECK(axis.velocity() == Approx(1.0 - kAmax * 0.05).margin(1e-12));
}

TEST_CASE("AxisDynamics keeps the newest command when more are in flight than it holds", "[dynamics]") {
    AxisDynamics axis(config(1.0));
    const auto extra = 5;
    for (std::size_t i = 0; i < AxisDynamics::kPendingCapacity + extra; ++i)
        axis.command(velocity(0.01 * static_cast<double>(i)), at_seconds(0.001 * static_cast<double>(i)));
    CHECK(axis.dropped_commands() == extra);
    axis.advance(at_seconds(3.0));
    CHECK(axis.velocity() == Approx(0.01 * (AxisDynamics::kPendingCapacity + extra - 1)));
}

TEST_CASE("AxisDynamics position moves reach the target exactly without overshoot", "[dynamics]") {
    for (double target : {2.5, -0.3, 1e-4, 7.0}) {
        AxisDynamics axis(config());
        axis.command(position(target), at_seconds(0.0));
        double furthest = 0.0;
        double last_velocity = 0.0;
        double worst_accel = 0.0;
        constexpr double kStep = 1e-3;
        for (int i = 1; i <= 6000; ++i) {
            axis.advance(at_seconds(kStep * i));
            furthest = std::max(furthest, axis.position() * (target > 0 ? 1.0 : -1.0));
            worst_accel = std::max(worst_accel, std::abs(axis.velocity() - last_velocity) / kStep);
            last_velocity = axis.velocity();
            REQUIRE(std::abs(axis.velocity()) <= kVmax);
        }
        INFO("target " << target);
        CHECK(furthest <= std::abs(target) + 1e-6);
        CHECK(axis.position() == Approx(target).margin(1e-12));
        CHECK(axis.velocity() == 0.0);
        CHECK(worst_accel <= kAmax * (1 + 1e-6));
    }
}

TEST_CASE("AxisDynamics position moves cruise at the position velocity, velocity commands at max_velocity", "[dynamics]") {
    AxisDynamicsConfig slow_profile = config();
    slow_profile.position_velocity_rad_s = 0.5;  // a drive's profile velocity below its top speed
    AxisDynamics axis(slow_profile);
    axis.command(position(3.0), at_seconds(0.0));
    double fastest = 0.0;
    for (int i = 1; i <= 8000; ++i) {
        axis.advance(at_seconds(1e-3 * i));
        fastest = std::max(fastest, std::abs(axis.velocity()));
    }
    CHECK(fastest == Approx(0.5));
    CHECK(axis.position() == Approx(3.0).margin(1e-12));
    axis.command(velocity(-kVmax), at_seconds(8.0));  // velocity commands are the limiter's business
    axis.advance(at_seconds(9.0));
    CHECK(axis.velocity() == -kVmax);
}

TEST_CASE("AxisDynamics settles on a target it is too fast to stop at, after one pass", "[dynamics]") {
    AxisDynamics axis(config());
    axis.command(velocity(kVmax), at_seconds(0.0));
    axis.command(position(0.5), at_seconds(1.0));  // at 1 s: 1.75 rad, moving at 2 rad/s
    int reversals = 0;
    double previous = axis.velocity();
    for (int i = 1; i <= 4000; ++i) {
        axis.advance(at_seconds(1.0 + 1e-3 * i));
        if ((axis.velocity() > 0) != (previous > 0) && axis.velocity() != 0 && previous != 0) ++reversals;
        if (axis.velocity() != 0) previous = axis.velocity();
    }
    CHECK(reversals == 1);
    CHECK(axis.position() == Approx(0.5).margin(1e-12));
    CHECK(axis.velocity() == 0.0);
}

TEST_CASE("AxisDynamics stops dead at an end stop and can leave it again", "[dynamics]") {
    AxisDynamics axis({kVmax, kAmax, 0.0, -0.5, 0.5});
    axis.command(velocity(kVmax), at_seconds(0.0));
    axis.advance(at_seconds(3.0));
    CHECK(axis.position() == 0.5);
    CHECK(axis.velocity() == 0.0);
    axis.command(position(2.0), at_seconds(3.0));  // a target beyond the stop presses against it
    axis.advance(at_seconds(4.0));
    CHECK(axis.position() == 0.5);
    CHECK(axis.velocity() == 0.0);
    axis.command(velocity(-1.0), at_seconds(4.0));
    axis.advance(at_seconds(4.5));
    CHECK(axis.velocity() == -1.0);
    CHECK(axis.position() < 0.5);
    axis.advance(at_seconds(10.0));
    CHECK(axis.position() == -0.5);
}

TEST_CASE("AxisDynamics gives the same motion however time is sliced", "[dynamics]") {
    auto run = [](auto&& step_times) {
        AxisDynamics axis({kVmax, kAmax, 0.05, -1.2, 3.0});
        axis.command(velocity(1.5), at_seconds(0.0));
        axis.command(position(-2.0), at_seconds(0.7));
        axis.command(velocity(0.4), at_seconds(1.9));
        axis.command(position(0.25), at_seconds(2.6));
        for (double t : step_times) axis.advance(at_seconds(t));
        axis.advance(at_seconds(5.0));
        return std::pair{axis.position(), axis.velocity()};
    };
    std::vector<double> none;
    std::vector<double> tiny;
    for (int i = 0; i < 500000; ++i) tiny.push_back(1e-5 * i);
    std::vector<double> uneven;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> gap(0.0, 0.05);
    for (double t = 0.0; t < 5.0; t += gap(rng)) uneven.push_back(t);
    const auto whole = run(none);
    for (const auto& sliced : {run(tiny), run(uneven)}) {
        CHECK(sliced.first == Approx(whole.first).margin(1e-9));
        CHECK(sliced.second == Approx(whole.second).margin(1e-9));
    }
    CHECK(whole.first == Approx(0.25).margin(1e-12));
}

TEST_CASE("AxisDynamics halt ramps to rest and forgets the commands in flight", "[dynamics]") {
    AxisDynamics axis(config(0.1));
    axis.command(velocity(kVmax), at_seconds(0.0));
    axis.command(velocity(-kVmax), at_seconds(0.9));
    axis.halt(at_seconds(1.0));
    CHECK(axis.velocity() == kVmax);
    axis.advance(at_seconds(1.0 + kVmax / kAmax));
    CHECK(axis.velocity() == Approx(0.0).margin(1e-12));
    const double rest = axis.position();
    axis.advance(at_seconds(3.0));
    CHECK(axis.position() == rest);
}

TEST_CASE("AxisDynamics treats a non-finite command as a stop", "[dynamics]") {
    AxisDynamics axis(config());
    axis.command(velocity(1.0), at_seconds(0.0));
    axis.command(position(std::nan("")), at_seconds(1.0));
    axis.advance(at_seconds(2.0));
    CHECK(axis.velocity() == 0.0);
    CHECK(std::isfinite(axis.position()));
}

TEST_CASE("AxisDynamics reset places the axis in a moving state under a command", "[dynamics]") {
    AxisDynamics axis(config(0.3));
    axis.command(velocity(-2.0), at_seconds(0.0));  // in flight, then dropped by the reset
    axis.reset(1.0, 0.5, velocity(1.0), at_seconds(0.1));
    axis.advance(at_seconds(0.1 + 0.5 / kAmax));
    CHECK(axis.velocity() == 1.0);
    CHECK(axis.position() == Approx(1.0 + 0.75 * 0.5 / kAmax).margin(1e-12));
    axis.advance(at_seconds(2.0));
    CHECK(axis.velocity() == 1.0);
}
