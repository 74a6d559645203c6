// SPDX-License-Identifier: Apache-2.0
// [gpio] in raysd.ini: step/dir stepper drivers (A4988, DRV8825, TMC2209 in step/dir mode, or an
// industrial driver's PUL/DIR/ENA inputs) on the lines of one GPIO chip. Offsets are the chip's
// line numbers (gpioinfo lists them); -1 means not wired. Dir high moves an axis the positive way.
#pragma once
#include <string>

namespace rays::gpio {

// The highest step rate the pulse thread is configured for, per axis; faster configs are refused.
// Measured here (test_gpio_step_rate, 2 shared cores, SCHED_FIFO): both axes at 20 kHz at once reached
// only about 18.5 kHz with re-bases, so the configured ceiling is half that; a real chip adds one
// ioctl per edge (a few µs), which this leaves room for.
constexpr int kMaxStepRateHz = 10000;

struct GpioSettings {
    std::string chip = "gpiochip0";
    int pan_step_line = -1;
    int pan_dir_line = -1;
    int pan_enable_line = -1;  // per-axis enable, or -1
    int tilt_step_line = -1;
    int tilt_dir_line = -1;
    int tilt_enable_line = -1;
    int enable_line = -1;            // one enable shared by both drivers, or -1
    bool enable_active_low = true;   // most step/dir drivers enable on a low ENA input

    int pan_steps_per_rev = 200;  // full steps per motor revolution
    int pan_microsteps = 16;
    double pan_gear_ratio = 1.0;  // motor revolutions per axis revolution
    int tilt_steps_per_rev = 200;
    int tilt_microsteps = 16;
    double tilt_gear_ratio = 1.0;

    double max_velocity_deg_s = 90.0;  // the pulse thread's own profile; keep [ptu] limits within it
    double max_accel_deg_s2 = 360.0;
    int max_step_rate_hz = kMaxStepRateHz;  // per axis; max_velocity must fit under it
    double pulse_width_us = 5.0;  // shortest step high time (and low time)
    double dir_setup_us = 5.0;    // dir stable this long before the next step edge

    int pan_limit_min_line = -1;  // limit switch inputs at the ends of travel, or -1
    int pan_limit_max_line = -1;
    int tilt_limit_min_line = -1;
    int tilt_limit_max_line = -1;
    bool limit_active_low = true;  // a normally-open switch to ground with a pull-up reads low when hit
    std::string pan_home_switch = "none";  // none|min|max: the limit switch home() seeks
    std::string tilt_home_switch = "none";
    double homing_speed_deg_s = 10.0;
    double home_backoff_deg = 2.0;  // moved off the switch after it releases
    double pan_home_offset_deg = 0.0;  // the position reported where homing ends
    double tilt_home_offset_deg = 0.0;
    double homing_timeout_s = 60.0;
    bool require_homing = false;  // refuse motion until home() has finished

    int estop_line = -1;  // enable/E-stop input: while asserted nothing moves and a fault is reported
    bool estop_active_low = true;

    double command_timeout_s = 0.5;  // no write() for this long: the axes ramp to a stop
    int rt_priority = 80;            // SCHED_FIFO priority of the pulse thread, 0: normal scheduling
};

}  // namespace rays::gpio
