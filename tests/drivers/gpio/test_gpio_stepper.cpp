// SPDX-License-Identifier: Apache-2.0
// gpio-stepper against FakeGpioLines: what the lines received (edges with their times, the steps a
// motor would have made), not the driver's own account. The pulse thread runs in real time, so these
// tests assert only what holds however late it wakes on a loaded machine (counts, order, no interval
// shorter than the limits allow) and wait for events with generous bounds; how fast it steps here is
// ptu-bench's gpio-step-rate.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
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
    const auto at = [&rig](long pan, long tilt) {
        return [&rig, pan, tilt] { return rig.lines.steps(kPanStep) == pan && rig.lines.steps(kTiltStep) == tilt; };
    };
    REQUIRE(rig.drive_until(command(CommandMode::Position, deg(10.0), deg(-5.0)),
                            at(std::lround(10.0 * kStepsPerDeg), -std::lround(5.0 * kStepsPerDeg))));
    REQUIRE(rig.drive(command(CommandMode::Position, deg(10.0), deg(-5.0)), 0.1));  // at rest there: nothing more
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
    REQUIRE(rig.drive_until(command(CommandMode::Position, deg(-3.0), 0.0), at(std::lround(-3.0 * kStepsPerDeg), 0)));
    CHECK(rig.lines.steps(kPanStep) == std::lround(-3.0 * kStepsPerDeg));
    CHECK(rig.lines.steps(kTiltStep) == 0);
    rig.driver->deactivate();
    CHECK(rig.lines.level(kEnable) == true);  // disabled after deactivate
}

TEST_CASE("gpio-stepper: no step interval beats the maximum rate or the ramp, however late the thread wakes", "[gpio]") {
    StepperRig rig;
    REQUIRE(rig.drive(command(CommandMode::Velocity, deg(180.0), deg(90.0)), 0.6));
    REQUIRE(rig.drive(command(CommandMode::Velocity, deg(-180.0), deg(-90.0)), 0.8));
    REQUIRE(rig.drive(command(CommandMode::Velocity, 0.0, 0.0), 0.4));
    const double max_rate = rig_settings().max_step_rate_hz;
    const double accel = 720.0 * kStepsPerDeg;
    for (int line : {kPanStep, kTiltStep}) {
        const std::vector<gpio::Edge> edges = rig.lines.edges_of(line);
        const std::vector<TimePoint> steps = rising(edges);
        REQUIRE(steps.size() > 100);  // it moved; how far depends on the machine's load
        // Pulse width: every high lasts at least pulse_width_us.
        for (std::size_t i = 0; i + 1 < edges.size(); ++i)
            if (edges[i].level) CHECK(seconds_between(edges[i].time, edges[i + 1].time) >= 5e-6);
        // Each interval's rate r: never above the maximum, and (r_next² − r'²) / 2 ≤ kRampRise · accel against
        // the interval before, r' = 1/(Δt − kJitter) (step_axis.hpp): a late edge lengthens its own interval,
        // and none after it is shortened to catch up.
        double shortest = 1.0, rise = 0.0;
        for (std::size_t i = 1; i < steps.size(); ++i) {
            const double interval = seconds_between(steps[i - 1], steps[i]);
            shortest = std::min(shortest, interval);
            const double jitter = std::chrono::duration<double>(gpio::StepAxis::kJitter).count();
            if (i >= 2 && seconds_between(steps[i - 2], steps[i - 1]) > 2.0 * jitter) {
                const double before = 1.0 / (seconds_between(steps[i - 2], steps[i - 1]) - jitter), now = 1.0 / interval;
                rise = std::max(rise, 0.5 * (now * now - before * before) / (1.0 + 1e-4));  // 1e-4: ns rounding
            }
        }
        const gpio::EngineReport report = rig.driver->report();
        INFO("shortest interval " << shortest * 1e6 << " us; largest rise " << rise << " steps/s^2, max accel " << accel
                                  << "; " << report.late_edges << " late edges, " << report.lost_steps << " steps lost");
        CHECK(shortest >= 1.0 / max_rate);
        CHECK(rise <= 1.001 * gpio::kRampRise * accel);
    }
}

TEST_CASE("gpio-stepper: DIR changes only at rest and stays stable for dir_setup before the next step", "[gpio]") {
    StepperRig rig;
    for (std::size_t i = 0; i < 4; ++i)  // each way until DIR has changed and a step has followed
        REQUIRE(rig.drive_until(command(CommandMode::Velocity, deg(i % 2 ? -40.0 : 40.0), 0.0), [&] {
            const std::vector<gpio::Edge> all = rig.lines.edges();
            return rig.lines.edges_of(kPanDir).size() == i + 1 && all.back().offset == kPanStep;
        }));
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
    eventually([&] {
        rig.driver->read(state, rig.clock.now());
        return state.axes[0].homed && state.axes[1].homed;
    });
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
    const long pan_target = -299 + backoff + std::lround(-85.0 * kStepsPerDeg) - std::lround(-90.0 * kStepsPerDeg);
    CHECK(rig.drive_until(command(CommandMode::Position, deg(-85.0), deg(45.0)),
                          [&] { return rig.lines.steps(kPanStep) == pan_target; }));
}

TEST_CASE("gpio-stepper: a limit switch faults its axis and stops the other", "[gpio]") {
    gpio::GpioSettings s = rig_settings();
    s.pan_limit_max_line = kPanMax;
    StepperRig rig(s, true, {{kPanMax, kPanStep, kPanDir, 500, false, false}});  // active low
    REQUIRE(rig.drive_until(command(CommandMode::Velocity, deg(20.0), deg(20.0)),
                            [&rig] { return !rig.driver->report().status.ok && rig.driver->report().at_rest; }));
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
    // The thread reads its inputs at least every kInputPeriod of its own time and steps each axis at
    // most once per wake-up, so at most one step per axis starts after the switch closed, however late.
    int after = 0;
    for (const gpio::Edge& edge : rig.lines.edges())
        if ((edge.offset == kPanStep || edge.offset == kTiltStep) && edge.level && edge.time > asserted) ++after;
    CHECK(after <= 2);
    rig.lines.set_input(kEstop, false);
    CHECK(eventually([&] { return rig.read(state).ok; }));
    const std::size_t edges = rig.lines.edge_count();
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the old command does not restart motion
    CHECK(rig.lines.edge_count() == edges);
    CHECK(rig.drive_until(command(CommandMode::Velocity, deg(60.0), deg(-60.0)),  // a fresh one does
                          [&] { return rig.lines.edge_count() > edges; }));
}

// The driver's clock, moved by the test while the pulse thread reads it.
class HandClock final : public Clock {
public:
    TimePoint now() const override { return TimePoint{TimePoint::duration{ticks_.load()}}; }
    void set_seconds(double seconds) {
        ticks_.store(std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(seconds)).count());
    }

private:
    std::atomic<TimePoint::duration::rep> ticks_{0};
};

// Staleness is judged on the driver's clock, here moved by hand, so what is asserted does not hang on
// when the pulse thread happens to wake.
TEST_CASE("gpio-stepper: a stale command stream ramps the axes to rest, and the next write moves them", "[gpio]") {
    HandClock clock;
    clock.set_seconds(10.0);
    gpio::FakeGpioLines lines;
    lines.add_motor(kPanStep, kPanDir);
    lines.add_motor(kTiltStep, kTiltDir);
    std::string error;
    const std::unique_ptr<gpio::GpioStepper> driver = gpio::make_gpio_stepper_driver(rig_settings(), clock, lines, error);
    REQUIRE(driver != nullptr);
    REQUIRE(driver->configure().ok);
    REQUIRE(driver->activate().ok);
    REQUIRE(driver->write(command(CommandMode::Velocity, deg(90.0), deg(90.0)), clock.now()).ok);
    // 0.29 s after the write on the driver's clock (timeout 0.3 s): still fresh, the axes keep stepping.
    clock.set_seconds(10.29);
    REQUIRE(eventually([&] { return lines.steps(kPanStep) > 200 && lines.steps(kTiltStep) > 200; }));
    CHECK_FALSE(driver->report().at_rest);
    // 0.31 s: stale. They come to rest and stay there with no further write, after no more steps than
    // the ramp down from 90 deg/s allows (v^2 / 2a; lateness only drops steps) and the one a wake-up
    // that read the clock just before it moved may still make.
    clock.set_seconds(10.31);
    const TimePoint stale = MonoClock::now();
    REQUIRE(eventually([&] { return driver->report().at_rest; }));
    const std::size_t edges = lines.edge_count();
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    CHECK(lines.edge_count() == edges);
    const double speed = 90.0 * kStepsPerDeg, accel = 720.0 * kStepsPerDeg;
    for (int line : {kPanStep, kTiltStep}) {
        const std::vector<TimePoint> steps = rising(lines.edges_of(line));
        const auto after = std::count_if(steps.begin(), steps.end(), [&](TimePoint t) { return t > stale; });
        CHECK(after <= std::lround(speed * speed / (2.0 * accel)) + 1);
    }
    CHECK(driver->report().status.ok);  // a stale stream is no fault: the next write moves them again
    REQUIRE(driver->write(command(CommandMode::Velocity, deg(30.0), 0.0), clock.now()).ok);
    CHECK(eventually([&] { return lines.edge_count() > edges; }));
}

TEST_CASE("gpio-stepper: from configure on, read gives a state the pulse thread published", "[gpio]") {
    // Asked at once, before the pulse thread may have run: the axes as they start, stamped on the
    // driver's clock, never the empty state of a report not yet published.
    HandClock clock;
    clock.set_seconds(10.0);
    gpio::FakeGpioLines lines;
    lines.add_motor(kPanStep, kPanDir);
    lines.add_motor(kTiltStep, kTiltDir);
    std::string error;
    const std::unique_ptr<gpio::GpioStepper> driver = gpio::make_gpio_stepper_driver(rig_settings(), clock, lines, error);
    REQUIRE(driver != nullptr);
    REQUIRE(driver->configure().ok);
    CHECK(driver->report().state.stamp == clock.now());
    ptu::PtuState state;
    state.axes[0].position_rad = 1.0;
    CHECK(driver->read(state, clock.now()).ok);
    CHECK(state.stamp == clock.now());
    CHECK(state.axes[0].position_rad == 0.0);
}

TEST_CASE("gpio-stepper: an I/O error stops, faults, reopens with backoff and recovers", "[gpio]") {
    StepperRig rig;
    REQUIRE(rig.drive(command(CommandMode::Velocity, deg(30.0), 0.0), 0.2));
    const TimePoint failing_from = MonoClock::now();  // the pulse thread meets the error no earlier
    rig.lines.set_failing(true);
    ptu::PtuState state;
    REQUIRE(eventually([&] { return !rig.driver->report().status.ok; }));
    const ptu::DriverStatus status = rig.read(state);
    REQUIRE_FALSE(status.ok);
    CHECK(std::strstr(status.what(), "I/O") != nullptr);
    CHECK_FALSE(state.axes[0].homed);
    rig.lines.set_failing(false);
    REQUIRE(eventually([&] { return rig.read(state).ok; }));
    // The first reopen waits out kFirstBackoff from the error, however late this thread saw it.
    CHECK(MonoClock::now() - failing_from >= gpio::PulseEngine::kFirstBackoff);
    CHECK(rig.lines.open_count() == 2);
    const long before = rig.lines.steps(kPanStep);
    CHECK(rig.drive_until(command(CommandMode::Velocity, deg(30.0), 0.0), [&] { return rig.lines.steps(kPanStep) > before; }));
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

TEST_CASE("gpio-stepper: write before activate moves nothing, the pulse thread reports its scheduling", "[gpio]") {
    StepperRig rig(rig_settings(), false);
    CHECK_FALSE(rig.driver->write(command(CommandMode::Velocity, 1.0, 1.0), rig.clock.now()).ok);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    CHECK(rig.lines.edges_of(kPanStep).empty());
    CHECK(rig.lines.level(kEnable) == true);  // disabled
    CHECK(eventually([&] { return std::strlen(rig.driver->realtime()) > 0; }));
}
