// SPDX-License-Identifier: Apache-2.0
// The gpio-stepper both GPIO benches drive: two axes on FakeGpioLines, pan STEP 0 / DIR 1, tilt STEP 2 /
// DIR 3, the rest at the driver's defaults unless a bench changes them; configured and activated.
#pragma once
#include <memory>
#include <string>

#include "core/clock.hpp"
#include "drivers/gpio/fake_gpio_lines.hpp"
#include "drivers/gpio/gpio_settings.hpp"
#include "drivers/gpio/gpio_stepper.hpp"

namespace rays::bench {

inline gpio::GpioSettings fake_stepper_settings() {
    gpio::GpioSettings settings;
    settings.chip = "fake";
    settings.pan_step_line = 0;
    settings.pan_dir_line = 1;
    settings.tilt_step_line = 2;
    settings.tilt_dir_line = 3;
    return settings;
}

struct FakeStepper {
    SteadyClock clock;
    gpio::FakeGpioLines lines;
    std::unique_ptr<gpio::GpioStepper> driver;

    // Null with `error` set when the driver refuses the settings or does not come up.
    static std::unique_ptr<FakeStepper> start(const gpio::GpioSettings& settings, std::string& error) {
        auto rig = std::make_unique<FakeStepper>();
        rig->driver = gpio::make_gpio_stepper_driver(settings, rig->clock, rig->lines, error);
        if (!rig->driver) return nullptr;
        if (ptu::DriverStatus s = rig->driver->configure(); !s.ok) return error = s.what(), nullptr;
        if (ptu::DriverStatus s = rig->driver->activate(); !s.ok) return error = s.what(), nullptr;
        return rig;
    }
};

}  // namespace rays::bench
