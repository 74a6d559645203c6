// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/gpio_params.hpp"

namespace rays::gpio {
namespace {

using config::ParamKind;
using config::ParamTable;
using S = GpioSettings;

constexpr double kMaxOffset = 1023;  // line offsets; -1: not wired

void add_lines(ParamTable<S>& table) {
    table.section("gpio", ParamKind::Capacity, [](S& s) -> S& { return s; })
        .add("chip", &S::chip, "GPIO chip: gpiochip0, /dev/gpiochip0, its number or its label")
        .add("pan_step_line", &S::pan_step_line, "", -1, kMaxOffset, "pan STEP output line offset")
        .add("pan_dir_line", &S::pan_dir_line, "", -1, kMaxOffset, "pan DIR output line (high: positive way)")
        .add("pan_enable_line", &S::pan_enable_line, "", -1, kMaxOffset, "pan ENABLE output line, -1: none")
        .add("tilt_step_line", &S::tilt_step_line, "", -1, kMaxOffset, "tilt STEP output line offset")
        .add("tilt_dir_line", &S::tilt_dir_line, "", -1, kMaxOffset, "tilt DIR output line (high: positive way)")
        .add("tilt_enable_line", &S::tilt_enable_line, "", -1, kMaxOffset, "tilt ENABLE output line, -1: none")
        .add("enable_line", &S::enable_line, "", -1, kMaxOffset, "ENABLE output shared by both drivers, -1: none")
        .add("enable_active_low", &S::enable_active_low, "the drivers are enabled by a low ENABLE level");
}

void add_mechanics(ParamTable<S>& table) {
    table.section("gpio", ParamKind::Capacity, [](S& s) -> S& { return s; })
        .add("pan_steps_per_rev", &S::pan_steps_per_rev, "steps", 1, 100000, "pan motor full steps per revolution")
        .add("pan_microsteps", &S::pan_microsteps, "", 1, 256, "pan driver microsteps per full step")
        .add("pan_gear_ratio", &S::pan_gear_ratio, "", 0.001, 10000, "pan motor revolutions per axis revolution")
        .add("tilt_steps_per_rev", &S::tilt_steps_per_rev, "steps", 1, 100000, "tilt motor full steps per revolution")
        .add("tilt_microsteps", &S::tilt_microsteps, "", 1, 256, "tilt driver microsteps per full step")
        .add("tilt_gear_ratio", &S::tilt_gear_ratio, "", 0.001, 10000, "tilt motor revolutions per axis revolution")
        .add("max_velocity_deg_s", &S::max_velocity_deg_s, "deg/s", 0.01, 10000,
             "fastest axis speed of the step generator (keep ptu.max_velocity_deg_s within it); raysd uses at most ptu.max_velocity_deg_s")
        .add("max_accel_deg_s2", &S::max_accel_deg_s2, "deg/s^2", 0.01, 1000000,
             "acceleration of the step generator's ramps (keep ptu.max_accel_deg_s2 within it)")
        .add("max_step_rate_hz", &S::max_step_rate_hz, "Hz", 1, kMaxStepRateHz,
             "highest step rate per axis; max_velocity_deg_s must fit under it")
        .add("pulse_width_us", &S::pulse_width_us, "us", 1, 1000, "shortest STEP high (and low) time")
        .add("dir_setup_us", &S::dir_setup_us, "us", 0, 10000, "DIR stable this long before a STEP edge");
}

void add_switches(ParamTable<S>& table) {
    table.section("gpio", ParamKind::Capacity, [](S& s) -> S& { return s; })
        .add("pan_limit_min_line", &S::pan_limit_min_line, "", -1, kMaxOffset, "pan limit switch input at the negative end, -1: none")
        .add("pan_limit_max_line", &S::pan_limit_max_line, "", -1, kMaxOffset, "pan limit switch input at the positive end, -1: none")
        .add("tilt_limit_min_line", &S::tilt_limit_min_line, "", -1, kMaxOffset, "tilt limit switch input at the negative end, -1: none")
        .add("tilt_limit_max_line", &S::tilt_limit_max_line, "", -1, kMaxOffset, "tilt limit switch input at the positive end, -1: none")
        .add("limit_active_low", &S::limit_active_low, "a limit switch reads low when hit")
        .add_choice("pan_home_switch", &S::pan_home_switch, "none|min|max", "the pan limit switch homing seeks")
        .add_choice("tilt_home_switch", &S::tilt_home_switch, "none|min|max", "the tilt limit switch homing seeks")
        .add("homing_speed_deg_s", &S::homing_speed_deg_s, "deg/s", 0.01, 1000,
             "speed toward and off the home switch; raysd uses at most ptu.max_velocity_deg_s")
        .add("home_backoff_deg", &S::home_backoff_deg, "deg", 0, 90, "moved on past the point where the switch releases")
        .add("pan_home_offset_deg", &S::pan_home_offset_deg, "deg", -360, 360, "pan position reported where homing ends")
        .add("tilt_home_offset_deg", &S::tilt_home_offset_deg, "deg", -180, 180, "tilt position reported where homing ends")
        .add("homing_timeout_s", &S::homing_timeout_s, "s", 1, 3600, "homing that has not finished by then faults")
        .add("require_homing", &S::require_homing, "refuse motion until homing has finished")
        .add("estop_line", &S::estop_line, "", -1, kMaxOffset, "enable/E-stop input: asserted stops everything, -1: none")
        .add("estop_active_low", &S::estop_active_low, "the E-stop input reads low when asserted");
}

void add_timing(ParamTable<S>& table) {
    table.section("gpio", ParamKind::Capacity, [](S& s) -> S& { return s; })
        .add("command_timeout_s", &S::command_timeout_s, "s", 0.02, 10,
             "no new command for this long: the pulse thread ramps the axes to a stop")
        .add("rt_priority", &S::rt_priority, "", 0, 99, "SCHED_FIFO priority of the pulse thread, 0: normal scheduling");
}

ParamTable<S> build() {
    ParamTable<S> table;
    add_lines(table);
    add_mechanics(table);
    add_switches(table);
    add_timing(table);
    return table;
}

}  // namespace

const config::ParamTable<GpioSettings>& gpio_params() {
    static const config::ParamTable<GpioSettings> table = build();
    return table;
}

}  // namespace rays::gpio
