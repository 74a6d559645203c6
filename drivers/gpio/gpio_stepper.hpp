// SPDX-License-Identifier: Apache-2.0
// Driver "gpio-stepper": two step/dir stepper axes on GPIO lines ([gpio] in raysd.ini). write() and
// read() only exchange mailboxes with the PulseEngine thread, which alone touches the lines.
// Lifecycle: configure() opens the chip (outputs low, drivers disabled) and starts the pulse thread;
// activate() enables the drivers; deactivate() ramps both axes to rest, then disables them.
// Positions are counted steps (homing sets them); velocity is the step rate's.
#pragma once
#include <memory>
#include <string>

#include "drivers/gpio/gpio_lines.hpp"
#include "drivers/gpio/gpio_settings.hpp"
#include "drivers/gpio/pulse_engine.hpp"
#include "drivers/gpio/stepper_config.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::gpio {

class GpioStepper final : public ptu::PtuDriver {
public:
    // `lines` must outlive the driver (tests pass a FakeGpioLines); `owned` may hold it.
    GpioStepper(const StepperConfig& config, GpioLines& lines, const Clock& clock,
                std::unique_ptr<GpioLines> owned = nullptr);
    ~GpioStepper() override;

    const char* name() const override { return "gpio-stepper"; }
    double command_latency_s() const override;  // the pulse thread's poll period
    ptu::DriverStatus configure() override;
    ptu::DriverStatus activate() override;
    void deactivate() override;
    ptu::DriverStatus home(TimePoint now) override;
    ptu::DriverStatus write(const ptu::PtuCommand& command, TimePoint now) override;
    ptu::DriverStatus read(ptu::PtuState& state, TimePoint now) override;

    // The pulse thread's scheduling: "SCHED_FIFO 80", "normal scheduling" or "refused: …".
    const char* realtime() const { return engine_.realtime(); }
    EngineReport report() const;  // the newest report (waits for the lock: not for the frame loop)

private:
    bool wait_for(bool (*done)(const EngineReport&), double timeout_s) const;

    StepperConfig config_;
    std::unique_ptr<GpioLines> owned_;
    GpioLines& lines_;
    PulseEngine engine_;
    EngineReport last_;  // the newest report read() saw
    bool configured_ = false;
    bool active_ = false;
};

// The factory the daemon calls for driver = gpio-stepper: null with `error` set for invalid settings.
std::unique_ptr<ptu::PtuDriver> make_gpio_stepper_driver(const GpioSettings& settings, const Clock& clock,
                                                         std::string& error);
// The same over other lines (tests, benches, a simulation).
std::unique_ptr<GpioStepper> make_gpio_stepper_driver(const GpioSettings& settings, const Clock& clock,
                                                      GpioLines& lines, std::string& error);

}  // namespace rays::gpio
