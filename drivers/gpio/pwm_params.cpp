// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/pwm_params.hpp"

namespace rays::gpio {
namespace {

using config::ParamKind;
using config::ParamTable;
using S = PwmSettings;

ParamTable<S> build() {
    ParamTable<S> table;
    table.section("pwm", ParamKind::Capacity, [](S& s) -> S& { return s; })
        .add("sysfs_root", &S::sysfs_root, "the PWM class directory (pwmchipN folders)")
        .add("pan_chip", &S::pan_chip, "", 0, 1023, "pan servo: N of pwmchipN")
        .add("pan_channel", &S::pan_channel, "", 0, 1023, "pan servo: M of pwmM on that chip")
        .add("tilt_chip", &S::tilt_chip, "", 0, 1023, "tilt servo: N of pwmchipN")
        .add("tilt_channel", &S::tilt_channel, "", 0, 1023, "tilt servo: M of pwmM on that chip")
        .add("period_ms", &S::period_ms, "ms", 2, 50, "PWM period (20 ms: 50 Hz, the RC standard)")
        .add("pan_min_pulse_us", &S::pan_min_pulse_us, "us", 100, 5000, "pan pulse width at pan_min_angle_deg")
        .add("pan_max_pulse_us", &S::pan_max_pulse_us, "us", 100, 5000, "pan pulse width at pan_max_angle_deg")
        .add("pan_min_angle_deg", &S::pan_min_angle_deg, "deg", -360, 360, "pan angle at the shortest pulse")
        .add("pan_max_angle_deg", &S::pan_max_angle_deg, "deg", -360, 360, "pan angle at the longest pulse")
        .add("pan_speed_deg_s", &S::pan_speed_deg_s, "deg/s", 1, 10000, "pan servo's rated speed, for the position estimate")
        .add("tilt_min_pulse_us", &S::tilt_min_pulse_us, "us", 100, 5000, "tilt pulse width at tilt_min_angle_deg")
        .add("tilt_max_pulse_us", &S::tilt_max_pulse_us, "us", 100, 5000, "tilt pulse width at tilt_max_angle_deg")
        .add("tilt_min_angle_deg", &S::tilt_min_angle_deg, "deg", -360, 360, "tilt angle at the shortest pulse")
        .add("tilt_max_angle_deg", &S::tilt_max_angle_deg, "deg", -360, 360, "tilt angle at the longest pulse")
        .add("tilt_speed_deg_s", &S::tilt_speed_deg_s, "deg/s", 1, 10000, "tilt servo's rated speed, for the position estimate")
        .add("move_speed_deg_s", &S::move_speed_deg_s, "deg/s", 1, 10000,
             "position moves (search, home, park, goto): the commanded angle slews at this, at most at [ptu] max_velocity_deg_s")
        .add("pan_start_deg", &S::pan_start_deg, "deg", -360, 360, "pan angle commanded at activate")
        .add("tilt_start_deg", &S::tilt_start_deg, "deg", -360, 360, "tilt angle commanded at activate")
        .add("disable_on_deactivate", &S::disable_on_deactivate,
             "switch the PWM output off at deactivate (most servos then go limp; off: they hold)")
        .add("command_timeout_s", &S::command_timeout_s, "s", 0.02, 10,
             "no new command for this long: the servos hold their estimated position");
    table.add_rule(config::less_than("pwm.pan_min_pulse_us", "pwm.pan_max_pulse_us"));
    table.add_rule(config::less_than("pwm.tilt_min_pulse_us", "pwm.tilt_max_pulse_us"));
    table.add_rule(config::less_than("pwm.pan_min_angle_deg", "pwm.pan_max_angle_deg"));
    table.add_rule(config::less_than("pwm.tilt_min_angle_deg", "pwm.tilt_max_angle_deg"));
    return table;
}

}  // namespace

const config::ParamTable<PwmSettings>& pwm_params() {
    static const config::ParamTable<PwmSettings> table = build();
    return table;
}

}  // namespace rays::gpio
