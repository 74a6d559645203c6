// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/gpio_stepper.hpp"

#include <chrono>
#include <thread>

#include "drivers/gpio/gpiod_lines.hpp"

namespace rays::gpio {

GpioStepper::GpioStepper(const StepperConfig& config, GpioLines& lines, const Clock& clock,
                         std::unique_ptr<GpioLines> owned)
    : config_(config), owned_(std::move(owned)), lines_(lines), engine_(config, lines, clock) {}

GpioStepper::~GpioStepper() {
    if (active_) deactivate();
    engine_.stop();
    lines_.close();
}

double GpioStepper::command_latency_s() const {
    return std::chrono::duration<double>(PulseEngine::kInputPeriod).count();
}

ptu::DriverStatus GpioStepper::configure() {
    if (active_) return ptu::DriverStatus::failure("gpio: configure while active");
    if (configured_) return ptu::DriverStatus::success();
    if (ptu::DriverStatus status = lines_.open(config_.request); !status.ok) return status;
    configured_ = true;
    engine_.start();
    last_ = report();  // read() keeps this until it takes a newer one
    return ptu::DriverStatus::success();
}

bool GpioStepper::wait_for(bool (*done)(const EngineReport&), double timeout_s) const {
    const auto deadline = MonoClock::now() + std::chrono::duration_cast<TimePoint::duration>(
                                                 std::chrono::duration<double>(timeout_s));
    while (MonoClock::now() < deadline) {
        if (done(report())) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
}

ptu::DriverStatus GpioStepper::activate() {
    if (!configured_) return ptu::DriverStatus::failure("gpio: activate before configure");
    engine_.set_active(true);
    active_ = true;
    const bool has_enable = config_.enables[0] != kNone;
    if (has_enable && !wait_for([](const EngineReport& r) { return r.enabled || !r.status.ok; }, 1.0))
        return ptu::DriverStatus::failure("gpio: the pulse thread did not enable the drivers");
    const EngineReport now = report();
    return now.status;
}

void GpioStepper::deactivate() {
    engine_.set_active(false);
    active_ = false;
    if (!configured_) return;
    // Ramp down from the fastest speed takes max_speed / accel; the thread disables once at rest.
    double ramp_s = 0.0;
    for (const AxisKinematics& axis : config_.axes) ramp_s = std::max(ramp_s, axis.max_speed / axis.accel);
    wait_for([](const EngineReport& r) { return r.at_rest && !r.enabled; }, ramp_s + 1.0);
}

ptu::DriverStatus GpioStepper::home(TimePoint now) {
    (void)now;
    if (!active_) return ptu::DriverStatus::failure("gpio: home while not active");
    if (config_.wiring[0].home_side == 0 || config_.wiring[1].home_side == 0)
        return ptu::DriverStatus::failure("gpio: homing needs pan_home_switch and tilt_home_switch");
    engine_.request_home();
    return ptu::DriverStatus::success();
}

ptu::DriverStatus GpioStepper::write(const ptu::PtuCommand& command, TimePoint now) {
    if (!active_) return ptu::DriverStatus::failure("gpio: write while not active");
    // Skipped only while the pulse thread copies the slot; the next frame's command follows.
    engine_.commands().try_publish([&](CommandSlot& slot) {
        slot.command = command;
        slot.written = now;
        slot.valid = true;
    });
    engine_.reports().try_read([this](const EngineReport& report) { last_ = report; });
    if (!last_.status.ok) return last_.status;
    if (config_.require_homing && !(last_.state.axes[0].homed && last_.state.axes[1].homed))
        return ptu::DriverStatus::failure("gpio: not homed (require_homing): no motion before home");
    return ptu::DriverStatus::success();
}

ptu::DriverStatus GpioStepper::read(ptu::PtuState& state, TimePoint now) {
    (void)now;
    if (!configured_) return ptu::DriverStatus::failure("gpio: read before configure");
    engine_.reports().try_read([this](const EngineReport& report) { last_ = report; });
    state = last_.state;
    return last_.status;
}

EngineReport GpioStepper::report() const {
    EngineReport copy;
    engine_.reports().read([&](const EngineReport& report) { copy = report; });
    return copy;
}

std::unique_ptr<GpioStepper> make_gpio_stepper_driver(const GpioSettings& settings, const Clock& clock,
                                                      GpioLines& lines, std::string& error) {
    StepperConfig config;
    if (!make_stepper_config(settings, config, error)) return nullptr;
    return std::make_unique<GpioStepper>(config, lines, clock);
}

std::unique_ptr<ptu::PtuDriver> make_gpio_stepper_driver(const GpioSettings& settings, const Clock& clock,
                                                         std::string& error) {
    StepperConfig config;
    if (!make_stepper_config(settings, config, error)) return nullptr;
    auto lines = std::make_unique<GpiodLines>();
    GpioLines& ref = *lines;
    return std::make_unique<GpioStepper>(config, ref, clock, std::move(lines));
}

}  // namespace rays::gpio
