// gpio-stepper against FakeGpioLines: what the lines received (edges with their times, the steps a
// motor would have made), not the driver's own account.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstring>

#include "drivers/gpio/step_axis.hpp"
#include "gpio_rig.hpp"

using namespace rays;
using namespace rays::test;
using ptu::CommandMode;

TEST_CASE("gpio-stepper: position moves make the commanded steps in the commanded directions", "[gpio]") {
    StepperRig rig;
    CHECK(rig.lines.level(kEnable) == false);  // enable_active_low: enabled
    REQUIRE(rig.drive(command(CommandMode::Position, deg(10.0), deg(-5.0)), 1.0));
    CHECK(rig.lines.steps(kPanStep) == std::lround(10.0 * kStepsPerDeg));
    CHECK(rig.lines.steps(kTiltStep) == -std::lround(5.0 * kStepsPerDeg));
    CHECK(rig.lines.edges_of(kPanDir).size() == 1);  // no overshoot and return
    CHECK(rig.lines.edges_of(kTiltDir).empty());
    CHECK(rig.lines.level(kPanDir) == true);
    CHECK(rig.lines.level(kTiltDir) == false);
    ptu::PtuState state;
    REQUIRE(rig.read(state).ok);
    CHECK(state.axes[0].position_rad == Approx(std::lround(10.0 * kStepsPerDeg) / kStepsPerRad));
    CHECK(state.axes[1].position_rad == Approx(-std::lround(5.0 * kStepsPerDeg) / kStepsPerRad));
    // Back the other way: the count follows.
    REQUIRE(rig.drive(command(CommandMode::Position, deg(-3.0), 0.0), 1.0));
    CHECK(rig.lines.steps(kPanStep) == std::lround(-3.0 * kStepsPerDeg));
    CHECK(rig.lines.steps(kTiltStep) == 0);
    rig.driver->deactivate();
    CHECK(rig.lines.level(kEnable) == true);  // disabled after deactivate
}

TEST_CASE("gpio-stepper: step rate stays under the maximum and ramps within max accel", "[gpio]") {
    StepperRig rig;
    REQUIRE(rig.drive(command(CommandMode::Velocity, deg(180.0), deg(90.0)), 0.6));
    REQUIRE(rig.drive(command(CommandMode::Velocity, deg(-180.0), deg(-90.0)), 0.8));
    REQUIRE(rig.drive(command(CommandMode::Velocity, 0.0, 0.0), 0.4));
    const double max_rate = rig_settings().max_step_rate_hz;
    const double accel = 720.0 * kStepsPerDeg;
    for (int line : {kPanStep, kTiltStep}) {
        const std::vector<gpio::Edge> edges = rig.lines.edges_of(line);
        const std::vector<TimePoint> steps = rising(edges);
        REQUIRE(steps.size() > 1000);
        double shortest = 1.0;
        for (std::size_t i = 1; i < steps.size(); ++i) shortest = std::min(shortest, seconds_between(steps[i - 1], steps[i]));
        CHECK(shortest >= 1.0 / max_rate);
        // Pulse width: every high lasts at least pulse_width_us.
        for (std::size_t i = 0; i + 1 < edges.size(); ++i)
            if (edges[i].level) CHECK(seconds_between(edges[i].time, edges[i + 1].time) >= 5e-6);
        // Signed position from the edges and the DIR record, sampled in 80 ms windows.
        const std::vector<gpio::Edge> all = rig.lines.edges();
        const int dir = line == kPanStep ? kPanDir : kTiltDir;
        const TimePoint start = all.front().time;
        constexpr double kWindow = 0.08;
        std::vector<double> positions(1, 0.0);
        double position = 0.0;
        bool forward = false;
        for (const gpio::Edge& edge : all) {
            while (seconds_between(start, edge.time) > kWindow * static_cast<double>(positions.size())) positions.push_back(position);
            if (edge.offset == dir) forward = edge.level;
            if (edge.offset == line && edge.level) position += forward ? 1.0 : -1.0;
        }
        double worst = 0.0;
        for (std::size_t i = 2; i < positions.size(); ++i)
            worst = std::max(worst, std::abs(positions[i] - 2 * positions[i - 1] + positions[i - 2]) / (kWindow * kWindow));
        // Allowed: ±1 step of quantisation per window, and the catch-up step_axis.hpp documents: an axis
        // woken up to kMaxLag late steps faster until it is back on its timeline, which moves up to
        // top speed × kMaxLag steps across a window boundary (counted twice in a second difference).
        const double top_speed = 180.0 * kStepsPerDeg;
        const double catch_up = 2.0 * top_speed * std::chrono::duration<double>(gpio::StepAxis::kMaxLag).count();
        const double allowed = 1.1 * accel + (2.0 + catch_up) / (kWindow * kWindow);
        INFO("largest windowed acceleration " << worst << " steps/s^2, allowed " << allowed << ", max accel " << accel);
        CHECK(worst <= allowed);
        CHECK(worst >= 0.5 * accel);  // it did ramp at about max accel
    }
}

TEST_CASE("gpio-stepper: DIR changes only at rest and stays stable for dir_setup before the next step", "[gpio]") {
    StepperRig rig;
    for (int i = 0; i < 4; ++i) REQUIRE(rig.drive(command(CommandMode::Velocity, deg(i % 2 ? -40.0 : 40.0), 0.0), 0.25));
    REQUIRE(rig.drive(command(CommandMode::Velocity, 0.0, 0.0), 0.2));
    const std::vector<gpio::Edge> all = rig.lines.edges();
    int dir_changes = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (all[i].offset != kPanDir) continue;
        ++dir_changes;
        for (std::size_t j = i + 1; j < all.size(); ++j)
            if (all[j].offset == kPanStep) {
                CHECK(all[j].level);
                CHECK(seconds_between(all[i].time, all[j].time) >= 20e-6);
                break;
            }
        for (std::size_t j = i; j-- > 0;)  // the step before it had ended
            if (all[j].offset == kPanStep) {
                CHECK_FALSE(all[j].level);
                break;
            }
    }
    CHECK(dir_changes == 4);
}

TEST_CASE("gpio-stepper: homing seeks the switch, backs off and sets the offset", "[gpio]") {
    gpio::GpioSettings s = rig_settings();
    s.pan_limit_min_line = kPanMin;
    s.tilt_limit_max_line = kTiltMax;
    s.pan_home_switch = "min";
    s.tilt_home_switch = "max";
    s.homing_speed_deg_s = 20.0;
    s.home_backoff_deg = 2.0;
    s.pan_home_offset_deg = -90.0;
    s.tilt_home_offset_deg = 45.0;
    s.require_homing = true;
    s.limit_active_low = false;
    StepperRig rig(s, true,
                   {{kPanMin, kPanStep, kPanDir, -300, true, true}, {kTiltMax, kTiltStep, kTiltDir, 200, false, true}});
    // require_homing: no motion before homing.
    CHECK_FALSE(rig.drive(command(CommandMode::Velocity, deg(10.0), deg(10.0)), 0.1));
    CHECK(rig.lines.edges_of(kPanStep).empty());
    ptu::PtuState state;
    REQUIRE(rig.driver->home(rig.clock.now()).ok);
    for (int i = 0; i < 300 && !(state.axes[0].homed && state.axes[1].homed); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        rig.driver->read(state, rig.clock.now());
    }
    REQUIRE(state.axes[0].homed);
    REQUIRE(state.axes[1].homed);
    const long backoff = std::lround(2.0 * kStepsPerDeg);
    CHECK(rig.lines.steps(kPanStep) == Approx(-299 + backoff).margin(1));  // released at −299, then the back-off
    CHECK(rig.lines.steps(kTiltStep) == Approx(199 - backoff).margin(1));
    CHECK(state.axes[0].position_rad == Approx(std::lround(-90.0 * kStepsPerDeg) / kStepsPerRad));
    CHECK(state.axes[1].position_rad == Approx(std::lround(45.0 * kStepsPerDeg) / kStepsPerRad));
    // The switch was reached: the motor went at least to it.
    const std::vector<gpio::Edge> pan = rig.lines.edges_of(kPanStep);
    CHECK(rising(pan).size() >= 300 + static_cast<std::size_t>(backoff));
    // Now moves are allowed and counted from the offset.
    REQUIRE(rig.drive(command(CommandMode::Position, deg(-85.0), deg(45.0)), 0.5));
    CHECK(rig.lines.steps(kPanStep) == -299 + backoff + std::lround(-85.0 * kStepsPerDeg) - std::lround(-90.0 * kStepsPerDeg));
}

TEST_CASE("gpio-stepper: a limit switch faults its axis and stops the other", "[gpio]") {
    gpio::GpioSettings s = rig_settings();
    s.pan_limit_max_line = kPanMax;
    StepperRig rig(s, true, {{kPanMax, kPanStep, kPanDir, 500, false, false}});  // active low
    rig.drive(command(CommandMode::Velocity, deg(20.0), deg(20.0)), 1.0);
    ptu::PtuState state;
    const ptu::DriverStatus status = rig.read(state);
    REQUIRE_FALSE(status.ok);
    CHECK(std::strstr(status.what(), "pan max limit switch") != nullptr);
    CHECK(state.axes[0].fault);
    CHECK(rig.lines.steps(kPanStep) >= 500);
    CHECK(rig.lines.steps(kPanStep) <= 501);
    // Both stopped: no edges while commands keep coming.
    const std::size_t edges = rig.lines.edge_count();
    CHECK_FALSE(rig.drive(command(CommandMode::Velocity, deg(20.0), deg(20.0)), 0.3));
    CHECK(rig.lines.edge_count() == edges);
}

TEST_CASE("gpio-stepper: E-stop stops every edge and faults until released", "[gpio]") {
    gpio::GpioSettings s = rig_settings();
    s.estop_line = kEstop;
    s.estop_active_low = false;
    StepperRig rig(s);
    REQUIRE(rig.drive(command(CommandMode::Velocity, deg(60.0), deg(-60.0)), 0.3));
    rig.lines.set_input(kEstop, true);
    const TimePoint asserted = MonoClock::now();
    CHECK_FALSE(rig.drive(command(CommandMode::Velocity, deg(60.0), deg(-60.0)), 0.3));
    ptu::PtuState state;
    const ptu::DriverStatus status = rig.read(state);
    REQUIRE_FALSE(status.ok);
    CHECK(std::strstr(status.what(), "E-stop") != nullptr);
    for (const gpio::Edge& edge : rig.lines.edges())  // one poll period and one pulse at most
        if (edge.offset == kPanStep || edge.offset == kTiltStep)
            CHECK(seconds_between(asserted, edge.time) < 0.002);
    rig.lines.set_input(kEstop, false);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    CHECK(rig.read(state).ok);
    const std::size_t edges = rig.lines.edge_count();
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the old command does not restart motion
    CHECK(rig.lines.edge_count() == edges);
    REQUIRE(rig.drive(command(CommandMode::Velocity, deg(60.0), deg(-60.0)), 0.2));  // a fresh one does
    CHECK(rig.lines.edge_count() > edges);
}

TEST_CASE("gpio-stepper: a stale command stream ramps the axes to a stop", "[gpio]") {
    StepperRig rig;
    REQUIRE(rig.drive(command(CommandMode::Velocity, deg(90.0), deg(90.0)), 0.3));
    const TimePoint last_write = MonoClock::now();
    std::this_thread::sleep_for(std::chrono::milliseconds(900));  // timeout 0.3 s + ramp 0.125 s
    const std::vector<TimePoint> steps = rising(rig.lines.edges_of(kPanStep));
    REQUIRE_FALSE(steps.empty());
    CHECK(seconds_between(last_write, steps.back()) < 0.3 + 0.125 + 0.02);
    CHECK(seconds_between(last_write, steps.back()) > 0.29);
}

TEST_CASE("gpio-stepper: an I/O error stops, faults, reopens with backoff and recovers", "[gpio]") {
    StepperRig rig;
    REQUIRE(rig.drive(command(CommandMode::Velocity, deg(30.0), 0.0), 0.2));
    rig.lines.set_failing(true);
    ptu::PtuState state;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const ptu::DriverStatus status = rig.read(state);
    REQUIRE_FALSE(status.ok);
    CHECK(std::strstr(status.what(), "I/O") != nullptr);
    CHECK_FALSE(state.axes[0].homed);
    rig.lines.set_failing(false);
    std::this_thread::sleep_for(std::chrono::milliseconds(700));  // first retry after 0.5 s
    CHECK(rig.read(state).ok);
    CHECK(rig.lines.open_count() == 2);
    const long before = rig.lines.steps(kPanStep);
    REQUIRE(rig.drive(command(CommandMode::Velocity, deg(30.0), 0.0), 0.2));
    CHECK(rig.lines.steps(kPanStep) > before);
}

TEST_CASE("gpio-stepper: the factory refuses settings that cannot work", "[gpio]") {
    SteadyClock clock;
    gpio::FakeGpioLines lines;
    std::string error;
    gpio::GpioSettings s = rig_settings();
    s.max_velocity_deg_s = 400.0;  // 17778 steps/s > 10000
    CHECK(gpio::make_gpio_stepper_driver(s, clock, lines, error) == nullptr);
    CHECK(error.find("max_step_rate_hz") != std::string::npos);
    s = rig_settings();
    s.max_step_rate_hz = 50000;
    CHECK(gpio::make_gpio_stepper_driver(s, clock, lines, error) == nullptr);
    s = rig_settings();
    s.tilt_dir_line = kPanStep;
    CHECK(gpio::make_gpio_stepper_driver(s, clock, lines, error) == nullptr);
    CHECK(error.find("used twice") != std::string::npos);
    s = rig_settings();
    s.require_homing = true;
    CHECK(gpio::make_gpio_stepper_driver(s, clock, lines, error) == nullptr);
    s = rig_settings();
    s.pan_home_switch = "min";
    CHECK(gpio::make_gpio_stepper_driver(s, clock, lines, error) == nullptr);
    CHECK(error.find("pan_limit_min_line") != std::string::npos);
    CHECK(gpio::make_gpio_stepper_driver(rig_settings(), clock, lines, error) != nullptr);
}

TEST_CASE("gpio-stepper: write before activate moves nothing; the pulse thread reports its scheduling", "[gpio]") {
    StepperRig rig(rig_settings(), false);
    CHECK_FALSE(rig.driver->write(command(CommandMode::Velocity, 1.0, 1.0), rig.clock.now()).ok);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    CHECK(rig.lines.edges_of(kPanStep).empty());
    CHECK(rig.lines.level(kEnable) == true);  // disabled
    CHECK(std::strlen(rig.driver->realtime()) > 0);
}
