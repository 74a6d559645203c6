// SPDX-License-Identifier: Apache-2.0
// Latency benches of the GPIO drivers against their recording fakes: "gpio-stepper" from write() to
// the first STEP edge of the new command (the fake lines' own timestamp; the axis starts from rest, so
// this is the pulse thread's poll delay plus wake-up), "pwm-servo" from write() to the duty_cycle write.
#include <chrono>
#include <thread>

#include "drivers/gpio/fake_gpio_lines.hpp"
#include "drivers/gpio/fake_pwm_channel.hpp"
#include "drivers/gpio/gpio_stepper.hpp"
#include "drivers/gpio/pwm_servo.hpp"
#include "fake_stepper.hpp"
#include "latency_bench.hpp"

namespace rays::bench {
namespace {

ptu::PtuCommand both(ptu::CommandMode mode, double value) {
    ptu::PtuCommand command;
    command.axes[0] = {mode, value};
    command.axes[1] = {mode, value};
    return command;
}

double micros(TimePoint from, TimePoint to) { return std::chrono::duration<double, std::micro>(to - from).count(); }

std::vector<double> run_stepper(int commands, std::string& error) {
    gpio::GpioSettings settings = fake_stepper_settings();
    settings.max_accel_deg_s2 = 100000.0;  // stops within a few steps between commands
    const auto rig = FakeStepper::start(settings, error);
    if (!rig) return {};
    auto& [clock, lines, driver] = *rig;
    std::vector<double> latencies;
    for (int i = 0; i < commands; ++i) {
        const std::size_t before = lines.edge_count();
        const TimePoint written = MonoClock::now();
        driver->write(both(ptu::CommandMode::Velocity, 0.5), clock.now());
        while (lines.edge_count() == before && MonoClock::now() - written < std::chrono::seconds(1))
            std::this_thread::yield();
        const std::vector<gpio::Edge> edges = lines.edges();
        for (std::size_t e = before; e < edges.size(); ++e)
            if (edges[e].offset == 0 && edges[e].level) {
                latencies.push_back(micros(written, edges[e].time));
                break;
            }
        driver->write(ptu::PtuCommand::stop(), clock.now());
        std::this_thread::sleep_for(std::chrono::milliseconds(3));
    }
    driver->deactivate();
    if (latencies.size() != static_cast<std::size_t>(commands)) error = "a command produced no step edge";
    return latencies;
}

std::vector<double> run_servo(int commands, std::string& error) {
    SteadyClock clock;
    gpio::FakePwmChannel pan, tilt;
    auto driver = gpio::make_pwm_servo_driver(gpio::PwmSettings{}, clock, pan, tilt, error);
    if (!driver) return {};
    if (ptu::DriverStatus s = driver->configure(); !s.ok) return error = s.what(), std::vector<double>{};
    if (ptu::DriverStatus s = driver->activate(); !s.ok) return error = s.what(), std::vector<double>{};
    std::vector<double> latencies;
    for (int i = 0; i < commands; ++i) {
        const std::size_t before = pan.writes().size();
        const TimePoint written = MonoClock::now();
        driver->write(both(ptu::CommandMode::Position, i % 2 == 0 ? 0.3 : -0.3), clock.now());
        while (pan.writes().size() == before && MonoClock::now() - written < std::chrono::seconds(1))
            std::this_thread::yield();
        const std::vector<gpio::PwmWrite> writes = pan.writes();
        if (writes.size() > before) latencies.push_back(micros(written, writes[before].time));
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    driver->deactivate();
    if (latencies.size() != static_cast<std::size_t>(commands)) error = "a command produced no duty_cycle write";
    return latencies;
}

const bool registered_stepper = register_bench(
    {"gpio-stepper", "write() to the first STEP edge on FakeGpioLines (axis from rest)", run_stepper});
const bool registered_servo =
    register_bench({"pwm-servo", "write() to the duty_cycle write on FakePwmChannel", run_servo});

}  // namespace
}  // namespace rays::bench
