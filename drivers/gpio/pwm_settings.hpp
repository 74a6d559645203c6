// SPDX-License-Identifier: Apache-2.0
// [pwm] in raysd.ini: RC hobby servos on hardware PWM channels (sysfs), driver "pwm-servo". A hobby
// servo reports nothing back, so the position read() gives is an estimate: the servo moving toward
// its commanded angle at its rated speed.
#pragma once
#include <string>

namespace rays::gpio {

struct PwmSettings {
    std::string sysfs_root = "/sys/class/pwm";
    int pan_chip = 0;  // /sys/class/pwm/pwmchipN
    int pan_channel = 0;  // its pwmM
    int tilt_chip = 0;
    int tilt_channel = 1;
    double period_ms = 20.0;

    double pan_min_pulse_us = 1000.0;  // pulse width at pan_min_angle_deg
    double pan_max_pulse_us = 2000.0;  // pulse width at pan_max_angle_deg
    double pan_min_angle_deg = -90.0;
    double pan_max_angle_deg = 90.0;
    double pan_speed_deg_s = 300.0;  // the servo's rated speed (0.2 s/60°)
    double tilt_min_pulse_us = 1000.0;
    double tilt_max_pulse_us = 2000.0;
    double tilt_min_angle_deg = -90.0;
    double tilt_max_angle_deg = 90.0;
    double tilt_speed_deg_s = 300.0;
    double move_speed_deg_s = 90.0;  // a position command's angle slews at this (raysd: within [ptu] max_velocity_deg_s)
    double pan_start_deg = 0.0;  // commanded at activate, and the estimate's start
    double tilt_start_deg = 0.0;

    bool disable_on_deactivate = false;  // true: output off at deactivate (most servos go limp)
    double command_timeout_s = 0.5;      // no write() for this long: hold the estimated position
};

}  // namespace rays::gpio
