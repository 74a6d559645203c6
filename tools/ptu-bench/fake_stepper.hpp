// The gpio-stepper both GPIO benches drive: two axes on FakeGpioLines, pan STEP 0 / DIR 1, tilt STEP 2 /
// DIR 3, the rest at the driver's defaults.
#pragma once
#include "drivers/gpio/gpio_settings.hpp"

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

}  // namespace rays::bench
