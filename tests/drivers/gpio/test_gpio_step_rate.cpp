// What the pulse thread sustains here: both axes at the configured maximum, kMaxStepRateHz (10 kHz),
// at once, against the fake lines. Prints the measured rate and lateness (quoted in the README).
#include <catch2/catch.hpp>

#include <cstdio>

#include "gpio_rig.hpp"

using namespace rays;
using namespace rays::test;

TEST_CASE("gpio-stepper: both axes sustain kMaxStepRateHz at once", "[gpio][rate]") {
    gpio::GpioSettings s = rig_settings();
    s.max_step_rate_hz = gpio::kMaxStepRateHz;
    s.max_velocity_deg_s = gpio::kMaxStepRateHz / kStepsPerDeg;
    s.max_accel_deg_s2 = 20000.0;  // reaches top speed in 0.02 s
    s.pulse_width_us = 2.0;
    s.rt_priority = 80;  // if allowed
    StepperRig rig(s);
    REQUIRE(rig.drive(command(ptu::CommandMode::Velocity, 100.0, 100.0), 1.0));  // far above: held at max
    for (int line : {kPanStep, kTiltStep}) {
        const std::vector<TimePoint> steps = rising(rig.lines.edges_of(line));
        REQUIRE(steps.size() > 5000);
        double shortest = 1.0;
        for (std::size_t i = 1; i < steps.size(); ++i) shortest = std::min(shortest, seconds_between(steps[i - 1], steps[i]));
        // Cruise: the last 0.5 s of edges.
        std::size_t first = steps.size() - 1;
        while (first > 0 && seconds_between(steps[first], steps.back()) < 0.5) --first;
        const double rate = static_cast<double>(steps.size() - 1 - first) / seconds_between(steps[first], steps.back());
        const gpio::EngineReport report = rig.driver->report();
        std::printf("gpio step rate: %s line %d: %.0f steps/s sustained (configured %d), shortest interval %.1f us, "
                    "latest edge %.0f us after due, %ld re-bases; pulse thread %s\n",
                    line == kPanStep ? "pan" : "tilt", line, rate, gpio::kMaxStepRateHz, shortest * 1e6,
                    report.max_late_us, report.rebases, rig.driver->realtime());
        CHECK(shortest >= 1.0 / gpio::kMaxStepRateHz);
        CHECK(rate > 0.95 * gpio::kMaxStepRateHz);
    }
}
