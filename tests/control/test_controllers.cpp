// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>
#include <cmath>

#include "control/lost_policy.hpp"
#include "control/predictive_controller.hpp"
#include "control/proportional_controller.hpp"

using namespace rays;
using namespace rays::control;

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
const CameraModel kCamera = CameraModel::from_fov(60 * kDeg, 60 * kDeg);

ControllerSettings settings() {
    ControllerSettings s;
    s.gain_per_s = 3.0;
    s.deadband_rad = 0.5 * kDeg;
    s.max_velocity_rad_s = 90 * kDeg;
    s.lead_s = 0.05;
    return s;
}

UnitPose still_at(double t, double pan, double tilt) { return {t, pan, tilt, 0, 0}; }
}  // namespace

TEST_CASE("the proportional controller commands gain times the angular offset") {
    ProportionalController p(kCamera, settings());
    CHECK(p.command(still_at(0, 0, 0)).axes[0].value == 0.0);  // no target: stop
    Point right_and_up{63.5 + 20.0, 63.5 - 10.0};
    p.sighted(right_and_up, still_at(0, 0.2, 0.1));
    WorldAngles target = kCamera.world_angles(right_and_up, 0.2, 0.1);
    ptu::PtuCommand c = p.command(still_at(0.01, 0.2, 0.1));
    CHECK(c.axes[0].mode == ptu::CommandMode::Velocity);
    CHECK(c.axes[0].value == Approx(3.0 * (target.azimuth - 0.2)));
    CHECK(c.axes[1].value == Approx(3.0 * (target.elevation - 0.1)));
    CHECK(c.axes[0].value > 0);
    CHECK(c.axes[1].value > 0);
    CHECK_FALSE(p.expected_pixel(still_at(0.04, 0.2, 0.1)));
}

TEST_CASE("the deadband really stops an axis and commands stay within the velocity limit") {
    ProportionalController p(kCamera, settings());
    p.sighted({63.5 + 0.5, 63.5}, still_at(0, 0, 0));  // 0.23°: inside the 0.5° deadband
    CHECK(p.command(still_at(0, 0, 0)).axes[0].value == 0.0);
    p.sighted({127.0, 0.0}, still_at(0, 0, 0));
    ControllerSettings slow = settings();
    slow.max_velocity_rad_s = 0.2;
    ProportionalController limited(kCamera, slow);
    limited.sighted({127.0, 0.0}, still_at(0, 0, 0));
    CHECK(limited.command(still_at(0, 0, 0)).axes[0].value == Approx(0.2));
    CHECK(limited.command(still_at(0, 0, 0)).axes[1].value == Approx(0.2));
}

TEST_CASE("the predictive controller feeds the target's rate forward once it has seen it move") {
    PredictiveController c(kCamera, settings(), {});
    // The unit follows perfectly at 15 deg/s, so the target always sits at the frame's centre: a
    // proportional controller would command nothing, the predictive one commands the target's rate.
    const double rate = 15 * kDeg;
    for (int k = 0; k <= 50; ++k) {
        double t = k * 0.04;
        c.sighted({63.5, 63.5}, {t, rate * t, 0.0, rate, 0.0});
    }
    ptu::PtuCommand command = c.command({2.0, rate * 2.0, 0.0, rate, 0.0});
    CHECK(command.axes[0].value == Approx(rate).margin(0.3 * kDeg));
    CHECK(command.axes[1].value == Approx(0.0).margin(0.3 * kDeg));
    // And it expects the target at the centre of the next frame if the unit keeps going.
    std::optional<Point> next = c.expected_pixel({2.04, rate * 2.04, 0.0, rate, 0.0});
    REQUIRE(next);
    CHECK(next->x == Approx(63.5).margin(0.3));
    // Were the unit to stop, the target would move right by rate · 40 ms.
    std::optional<Point> if_stopped = c.expected_pixel({2.04, rate * 2.0, 0.0, 0.0, 0.0});
    REQUIRE(if_stopped);
    CHECK(if_stopped->x - 63.5 == Approx(kCamera.intrinsics().fx * std::tan(rate * 0.04)).margin(0.3));
}

TEST_CASE("the predictive controller is coasted on only once its estimate has settled") {
    PredictiveController c(kCamera, settings(), {});
    ProportionalController p(kCamera, settings());
    CHECK_FALSE(c.can_coast());
    // The first sighting starts the filter; ten more are folded in before it has settled.
    for (int k = 0; k < 10; ++k) c.sighted({63.5, 63.5}, still_at(k * 0.04, 0.1, 0.0));
    CHECK(c.has_target());
    CHECK_FALSE(c.can_coast());  // a rate made of too little
    c.sighted({63.5, 63.5}, still_at(0.40, 0.1, 0.0));
    CHECK(c.can_coast());
    c.lost();
    CHECK_FALSE(c.can_coast());
    p.sighted({63.5, 63.5}, still_at(0, 0.1, 0.0));
    CHECK_FALSE(p.can_coast());  // no prediction to follow
}

TEST_CASE("the predictive controller stops outright on a still target near the centre") {
    PredictiveController c(kCamera, settings(), {});
    for (int k = 0; k <= 30; ++k) c.sighted({63.8, 63.3}, still_at(k * 0.04, 0.1, 0.0));
    ptu::PtuCommand command = c.command(still_at(1.2, 0.1, 0.0));
    CHECK(command.axes[0].value == 0.0);
    CHECK(command.axes[1].value == 0.0);
    c.lost();
    CHECK_FALSE(c.has_target());
    CHECK(c.command(still_at(1.3, 0.1, 0.0)).axes[0].value == 0.0);
}

TEST_CASE("lost after coasting: go back to where the target was last seen and hold there, or search round it") {
    LostSettings s;
    s.timeout_s = 2.0;
    s.search_step_rad = 0.3;
    s.search_steps = 1;
    s.search_dwell_s = 1.0;
    LostPolicy policy;
    policy.set_settings(s);
    policy.lost_after_coasting(10.0, 0.4, -0.1);
    for (double t : {10.0, 11.5, 100.0}) {
        const ptu::PtuCommand c = policy.command(t);
        CHECK(c.axes[0].mode == ptu::CommandMode::Position);
        CHECK(c.axes[0].value == 0.4);
        CHECK(c.axes[1].value == -0.1);
    }
    s.action = LostAction::Search;
    policy.set_settings(s);
    CHECK(policy.command(11.5).axes[0].value == 0.4);
    CHECK(policy.command(13.5).axes[0].value == Approx(0.7));
    CHECK(policy.command(13.5).axes[1].value == -0.1);
    // A loss without coasting holds still where the unit is, as before.
    policy.lost_at(20.0, 1.0, 0.2);
    CHECK(policy.command(20.5).axes[0].mode == ptu::CommandMode::Velocity);
    CHECK(policy.command(20.5).axes[0].value == 0.0);
}

TEST_CASE("lost: hold, then search round the lost pose or go home") {
    LostSettings s;
    s.timeout_s = 2.0;
    s.search_step_rad = 0.3;
    s.search_steps = 2;
    s.search_dwell_s = 1.0;
    s.home_pan_rad = -0.5;
    s.home_tilt_rad = 0.1;
    LostPolicy policy;
    policy.lost_at(10.0, 1.0, 0.2);
    for (LostAction action : {LostAction::Hold, LostAction::Search, LostAction::Home}) {
        s.action = action;
        policy.set_settings(s);
        ptu::PtuCommand early = policy.command(11.5);
        CHECK(early.axes[0].mode == ptu::CommandMode::Velocity);
        CHECK(early.axes[0].value == 0.0);
    }
    s.action = LostAction::Hold;
    policy.set_settings(s);
    CHECK(policy.command(100.0).axes[0].value == 0.0);
    s.action = LostAction::Home;
    policy.set_settings(s);
    CHECK(policy.command(12.5).axes[0].mode == ptu::CommandMode::Position);
    CHECK(policy.command(12.5).axes[0].value == -0.5);
    CHECK(policy.command(12.5).axes[1].value == 0.1);
    s.action = LostAction::Search;
    policy.set_settings(s);
    const double expected[] = {1.0, 1.3, 0.7, 1.6, 0.4, 1.0, 1.3};
    for (int k = 0; k < 7; ++k) {
        ptu::PtuCommand c = policy.command(12.5 + k);
        CHECK(c.axes[0].mode == ptu::CommandMode::Position);
        CHECK(c.axes[0].value == Approx(expected[k]));
        CHECK(c.axes[1].value == Approx(0.2));
    }
}
