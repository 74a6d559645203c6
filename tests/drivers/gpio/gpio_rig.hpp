// SPDX-License-Identifier: Apache-2.0
// A GpioStepper over FakeGpioLines on the steady clock, with the lines of a small rig: pan STEP 0,
// DIR 1, tilt STEP 2, DIR 3, shared ENABLE 4; limit switches pan 10/11, tilt 12/13; E-stop 14.
// 44.4 steps/deg (200 × 16 microsteps, 5:1 gear), 8000 steps/s top speed, 32000 steps/s².
#pragma once
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <initializer_list>
#include <memory>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "drivers/gpio/fake_gpio_lines.hpp"
#include "drivers/gpio/gpio_stepper.hpp"
#include "support/eventually.hpp"

namespace rays::test {

constexpr int kPanStep = 0, kPanDir = 1, kTiltStep = 2, kTiltDir = 3, kEnable = 4;
constexpr int kPanMin = 10, kPanMax = 11, kTiltMin = 12, kTiltMax = 13, kEstop = 14;
constexpr double kStepsPerDeg = 200.0 * 16.0 * 5.0 / 360.0;
constexpr double kStepsPerRad = kStepsPerDeg * 180.0 / std::numbers::pi;

inline gpio::GpioSettings rig_settings() {
    gpio::GpioSettings s;
    s.chip = "fake";
    s.pan_step_line = kPanStep;
    s.pan_dir_line = kPanDir;
    s.tilt_step_line = kTiltStep;
    s.tilt_dir_line = kTiltDir;
    s.enable_line = kEnable;
    s.pan_gear_ratio = 5.0;
    s.tilt_gear_ratio = 5.0;
    s.max_velocity_deg_s = 180.0;
    s.max_accel_deg_s2 = 720.0;
    s.max_step_rate_hz = 10000;
    s.dir_setup_us = 20.0;
    s.pulse_width_us = 5.0;
    s.command_timeout_s = 0.3;
    s.rt_priority = 80;  // SCHED_FIFO where allowed, as on a rig
    return s;
}

inline double seconds_between(TimePoint a, TimePoint b) { return std::chrono::duration<double>(b - a).count(); }

struct StepperRig {
    // `switches` are wired before the driver starts reading its inputs (a switch added later could be
    // read as pressed in between).
    explicit StepperRig(const gpio::GpioSettings& settings = rig_settings(), bool activate = true,
                        std::initializer_list<gpio::SimulatedSwitch> switches = {}) {
        lines.add_motor(kPanStep, kPanDir);
        lines.add_motor(kTiltStep, kTiltDir);
        for (const gpio::SimulatedSwitch& simulated : switches) lines.add_switch(simulated);
        std::string error;
        driver = gpio::make_gpio_stepper_driver(settings, clock, lines, error);
        REQUIRE(driver != nullptr);
        REQUIRE(driver->configure().ok);
        if (activate) REQUIRE(driver->activate().ok);
    }

    // Writes `command` at 100 Hz for `seconds`, as the frame loop would; false if any write failed.
    bool drive(const ptu::PtuCommand& command, double seconds) {
        bool ok = true;
        const auto end = MonoClock::now() + std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(seconds));
        while (MonoClock::now() < end) {
            ok = driver->write(command, clock.now()).ok && ok;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return ok;
    }

    // Writes `command` about every 10 ms until `done` holds (test::eventually's generous bound); whether it held.
    template <class Predicate>
    bool drive_until(const ptu::PtuCommand& command, Predicate done) {
        return eventually([&] {
            driver->write(command, clock.now());
            return done();
        });
    }

    // The driver's state from a report the pulse thread published after this call began. read()
    // takes the newest report without waiting and keeps the last one it took while the pulse
    // thread is publishing, so it is asked again until what it gives is that new.
    ptu::DriverStatus read(ptu::PtuState& state) {
        const TimePoint asked = clock.now();
        ptu::DriverStatus status;
        eventually([&] {
            status = driver->read(state, clock.now());
            return state.stamp > asked;
        });
        return status;
    }

    SteadyClock clock;
    gpio::FakeGpioLines lines;
    std::unique_ptr<gpio::GpioStepper> driver;
};

inline ptu::PtuCommand command(ptu::CommandMode mode, double pan, double tilt) {
    ptu::PtuCommand c;
    c.axes[0] = {mode, pan};
    c.axes[1] = {mode, tilt};
    return c;
}

inline double deg(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Rising edges of a STEP line.
inline std::vector<TimePoint> rising(const std::vector<gpio::Edge>& edges) {
    std::vector<TimePoint> times;
    for (const gpio::Edge& edge : edges)
        if (edge.level) times.push_back(edge.time);
    return times;
}

}  // namespace rays::test
