// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/stepper_config.hpp"
#include "common/angles.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace rays::gpio {
namespace {


struct AxisLines {
    const char* name;
    int step, dir, enable, limit_min, limit_max;
    const std::string& home;
    int steps_per_rev, microsteps;
    double gear_ratio, home_offset_deg;
};

class Builder {
public:
    Builder(StepperConfig& config, std::string& error) : config_(config), error_(error) {}

    bool used(int offset, const char* what) {
        for (int known : offsets_)
            if (known == offset) return fail(std::string("gpio: line ") + std::to_string(offset) + " is used twice (" + what + ")");
        offsets_.push_back(offset);
        return true;
    }

    std::size_t output(int offset, bool initial) {
        config_.request.outputs.push_back({offset, initial});
        return config_.request.outputs.size() - 1;
    }

    int input(int offset, const char* what) {
        if (offset < 0) return kNone;
        if (!used(offset, what)) return kNone;
        config_.request.inputs.push_back(offset);
        return static_cast<int>(config_.request.inputs.size() - 1);
    }

    bool fail(std::string message) {
        if (error_.empty()) error_ = std::move(message);
        return false;
    }

    bool ok() const { return error_.empty(); }

private:
    StepperConfig& config_;
    std::string& error_;
    std::vector<int> offsets_;
};

bool add_axis(const GpioSettings& s, const AxisLines& lines, std::size_t index, Builder& builder,
              StepperConfig& config) {
    const std::string name = lines.name;
    if (lines.step < 0 || lines.dir < 0) return builder.fail("gpio: " + name + "_step_line and " + name + "_dir_line are required");
    if (!builder.used(lines.step, "step") || !builder.used(lines.dir, "dir")) return false;
    AxisWiring& wiring = config.wiring[index];
    wiring.step = builder.output(lines.step, false);
    wiring.dir = builder.output(lines.dir, false);
    wiring.limit_min = builder.input(lines.limit_min, "limit switch");
    wiring.limit_max = builder.input(lines.limit_max, "limit switch");
    wiring.home_side = lines.home == "min" ? -1 : lines.home == "max" ? 1 : 0;
    if ((wiring.home_side < 0 && wiring.limit_min == kNone) || (wiring.home_side > 0 && wiring.limit_max == kNone))
        return builder.fail("gpio: " + name + "_home_switch = " + lines.home + " needs " + name + "_limit_" + lines.home + "_line");

    AxisKinematics& axis = config.axes[index];
    axis.steps_per_rad = lines.steps_per_rev * lines.microsteps * lines.gear_ratio / (2.0 * std::numbers::pi);
    axis.max_speed = s.max_velocity_deg_s * kRadPerDeg * axis.steps_per_rad;
    axis.accel = s.max_accel_deg_s2 * kRadPerDeg * axis.steps_per_rad;
    axis.homing_speed = s.homing_speed_deg_s * kRadPerDeg * axis.steps_per_rad;
    axis.backoff_steps = std::lround(s.home_backoff_deg * kRadPerDeg * axis.steps_per_rad);
    axis.home_offset_steps = std::lround(lines.home_offset_deg * kRadPerDeg * axis.steps_per_rad);
    if (axis.max_speed > s.max_step_rate_hz)
        return builder.fail("gpio: " + name + ": max_velocity_deg_s needs " + std::to_string(std::lround(axis.max_speed)) +
                            " steps/s, above max_step_rate_hz = " + std::to_string(s.max_step_rate_hz));
    return true;
}

}  // namespace

bool make_stepper_config(const GpioSettings& s, StepperConfig& config, std::string& error) {
    config = StepperConfig{};
    error.clear();
    Builder builder(config, error);
    if (s.chip.empty()) return builder.fail("gpio: chip is empty");
    if (s.max_step_rate_hz < 1 || s.max_step_rate_hz > kMaxStepRateHz)
        return builder.fail("gpio: max_step_rate_hz must lie in 1.." + std::to_string(kMaxStepRateHz) +
                            " (the rate the pulse thread is measured to sustain)");
    if (2.0 * s.pulse_width_us * 1e-6 * s.max_step_rate_hz > 1.0)
        return builder.fail("gpio: two pulse_width_us do not fit in one period of max_step_rate_hz");
    if (s.homing_speed_deg_s > s.max_velocity_deg_s) return builder.fail("gpio: homing_speed_deg_s exceeds max_velocity_deg_s");
    config.request.chip = s.chip;
    const AxisLines pan{"pan", s.pan_step_line, s.pan_dir_line, s.pan_enable_line, s.pan_limit_min_line,
                        s.pan_limit_max_line, s.pan_home_switch, s.pan_steps_per_rev, s.pan_microsteps,
                        s.pan_gear_ratio, s.pan_home_offset_deg};
    const AxisLines tilt{"tilt", s.tilt_step_line, s.tilt_dir_line, s.tilt_enable_line, s.tilt_limit_min_line,
                         s.tilt_limit_max_line, s.tilt_home_switch, s.tilt_steps_per_rev, s.tilt_microsteps,
                         s.tilt_gear_ratio, s.tilt_home_offset_deg};
    if (!add_axis(s, pan, 0, builder, config) || !add_axis(s, tilt, 1, builder, config)) return false;

    const bool disabled_level = s.enable_active_low;  // outputs start with the drivers disabled
    std::size_t enables = 0;
    for (int offset : {s.enable_line, s.pan_enable_line, s.tilt_enable_line}) {
        if (offset < 0) continue;
        if (!builder.used(offset, "enable")) return false;
        config.enables[enables++] = static_cast<int>(builder.output(offset, disabled_level));
    }
    config.estop = builder.input(s.estop_line, "E-stop");
    if (!builder.ok()) return false;
    if (s.require_homing && (config.wiring[0].home_side == 0 || config.wiring[1].home_side == 0))
        return builder.fail("gpio: require_homing needs pan_home_switch and tilt_home_switch");

    config.enable_active_low = s.enable_active_low;
    config.limit_active_low = s.limit_active_low;
    config.estop_active_low = s.estop_active_low;
    config.max_step_rate_hz = s.max_step_rate_hz;
    config.pulse_width_s = s.pulse_width_us * 1e-6;
    config.dir_setup_s = s.dir_setup_us * 1e-6;
    config.command_timeout_s = s.command_timeout_s;
    config.homing_timeout_s = s.homing_timeout_s;
    config.require_homing = s.require_homing;
    config.rt_priority = s.rt_priority;
    return true;
}

}  // namespace rays::gpio
