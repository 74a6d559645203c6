// SPDX-License-Identifier: Apache-2.0
// GpioSettings turned into what the pulse thread works with: line indices into one LineRequest and
// per-axis kinematics in steps, after checking the combination (the factory's errors come from here).
#pragma once
#include <array>
#include <cstddef>
#include <string>

#include "drivers/gpio/gpio_lines.hpp"
#include "drivers/gpio/gpio_settings.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::gpio {

constexpr int kNone = -1;  // no line index

struct AxisWiring {
    std::size_t step = 0;  // output indices
    std::size_t dir = 0;
    int limit_min = kNone;  // input indices
    int limit_max = kNone;
    int home_side = 0;  // -1: home at the min switch, +1: at the max switch, 0: cannot home
};

struct AxisKinematics {
    double steps_per_rad = 1.0;
    double max_speed = 1.0;     // steps/s
    double accel = 1.0;         // steps/s²
    double homing_speed = 1.0;  // steps/s
    long backoff_steps = 0;
    long home_offset_steps = 0;  // position where homing ends
};

struct StepperConfig {
    LineRequest request;
    std::array<AxisWiring, ptu::kAxes> wiring{};
    std::array<AxisKinematics, ptu::kAxes> axes{};
    std::array<int, 3> enables{kNone, kNone, kNone};  // output indices of the enable lines
    int estop = kNone;                                 // input index
    bool enable_active_low = true;
    bool limit_active_low = true;
    bool estop_active_low = true;
    double max_step_rate_hz = kMaxStepRateHz;
    double pulse_width_s = 5e-6;
    double dir_setup_s = 5e-6;
    double command_timeout_s = 0.5;
    double homing_timeout_s = 60.0;
    bool require_homing = false;
    int rt_priority = 0;
};

// False with `error` set when the settings cannot work (a line missing or used twice, a speed the
// step rate cannot reach, homing without a switch, ...).
bool make_stepper_config(const GpioSettings& settings, StepperConfig& config, std::string& error);

}  // namespace rays::gpio
