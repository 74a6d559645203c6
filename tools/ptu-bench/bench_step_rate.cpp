// SPDX-License-Identifier: Apache-2.0
// "gpio-step-rate": what the stepper's pulse thread sustains on this machine. Both axes are held at
// kMaxStepRateHz against FakeGpioLines (`commands` velocity commands 2 ms apart, far above the top
// speed); the samples are every STEP edge's time after its due time, as the engine's histogram keeps
// it (a power-of-two µs bucket's upper bound), and the note gives each axis's sustained rate over the
// run's second half and what lateness cost: late edges and the plan's steps dropped (step_axis.hpp).
#include <chrono>
#include <cstdio>
#include <thread>

#include "drivers/gpio/fake_gpio_lines.hpp"
#include "drivers/gpio/gpio_stepper.hpp"
#include "fake_stepper.hpp"
#include "latency_bench.hpp"

namespace rays::bench {
namespace {

std::string note;

double seconds_between(TimePoint a, TimePoint b) { return std::chrono::duration<double>(b - a).count(); }

// Steps per second over the second half of a STEP line's rising edges.
double sustained_rate(const std::vector<gpio::Edge>& edges) {
    std::vector<TimePoint> steps;
    for (const gpio::Edge& edge : edges)
        if (edge.level) steps.push_back(edge.time);
    if (steps.size() < 4) return 0.0;
    const std::size_t first = steps.size() / 2;
    return static_cast<double>(steps.size() - 1 - first) / seconds_between(steps[first], steps.back());
}

std::vector<double> run_step_rate(int commands, std::string& error) {
    gpio::GpioSettings settings = fake_stepper_settings();
    const double steps_per_deg = settings.pan_steps_per_rev * settings.pan_microsteps * settings.pan_gear_ratio / 360.0;
    settings.max_velocity_deg_s = gpio::kMaxStepRateHz / steps_per_deg;
    settings.max_accel_deg_s2 = 20000.0;  // top speed within about 0.03 s
    settings.pulse_width_us = 2.0;
    const auto rig = FakeStepper::start(settings, error);
    if (!rig) return {};
    auto& [clock, lines, driver] = *rig;
    ptu::PtuCommand command;
    command.axes[0] = command.axes[1] = {ptu::CommandMode::Velocity, 100.0};  // rad/s: held at the top speed
    for (int i = 0; i < commands; ++i) {
        driver->write(command, clock.now());
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    const gpio::EngineReport report = driver->report();
    driver->deactivate();
    const double pan = sustained_rate(lines.edges_of(0)), tilt = sustained_rate(lines.edges_of(2));
    char text[300];
    std::snprintf(text, sizeof text,
                  "sustained %.0f (pan) and %.0f (tilt) steps/s of %d configured; %ld of %ld edges late, %ld steps "
                  "dropped; latest %.0f us; pulse thread %s",
                  pan, tilt, gpio::kMaxStepRateHz, report.late_edges, report.lateness.total(), report.lost_steps,
                  report.max_late_us, driver->realtime());
    note = text;
    std::vector<double> lateness;
    for (std::size_t b = 0; b < gpio::LatenessHistogram::kBuckets; ++b)
        lateness.insert(lateness.end(), static_cast<std::size_t>(report.lateness.counts[b]),
                        gpio::LatenessHistogram::upper_us(b));
    if (lateness.empty()) error = "no STEP edge";
    return lateness;
}

const bool registered = register_bench({"gpio-step-rate",
                                        "both axes at kMaxStepRateHz on FakeGpioLines: each STEP edge's lateness "
                                        "(power-of-two us bucket), sustained rates in the note",
                                        run_step_rate, [] { return note; }});

}  // namespace
}  // namespace rays::bench
