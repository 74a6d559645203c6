// SPDX-License-Identifier: Apache-2.0
#include "daemon/ptu_factory.hpp"

#include <algorithm>

#include "common/angles.hpp"

#include "drivers/can/canopen/canopen_driver.hpp"
#include "drivers/can/odrive/odrive_driver.hpp"
#include "drivers/gpio/gpio_stepper.hpp"
#include "drivers/gpio/pwm_servo.hpp"
#include "drivers/mock/mock_ptu.hpp"
#include "drivers/modbus/modbus_ptu.hpp"

namespace rays::daemon {
namespace {

ptu::MockPtuConfig mock_ptu_config(const MockPtuSettings& mock, const PtuMotion& motion) {
    ptu::MockPtuConfig config;
    config.max_velocity_rad_s = mock.max_velocity_deg_s * kRadPerDeg;
    // The simulated unit follows PtuLimiter's position targets (search, home, park, goto) at the soft
    // velocity limit, as with_moves_within_soft_limits sets a real drive's profile velocity.
    config.profile_velocity_rad_s = std::min(mock.max_velocity_deg_s, motion.max_velocity_deg_s) * kRadPerDeg;
    config.max_accel_rad_s2 = mock.max_accel_deg_s2 * kRadPerDeg;
    config.latency_s = mock.latency_ms / 1000.0;
    config.record_capacity = mock.record_path.empty() ? 16 : 262'144;
    return config;
}

void hold_within(double& value, double limit) { value = std::min(value, limit); }

}  // namespace

DaemonConfig with_moves_within_soft_limits(DaemonConfig config) {
    const double velocity = config.ptu.motion.max_velocity_deg_s;
    hold_within(config.canopen.max_velocity_deg_s, velocity);  // 0x607F, 0x6081
    hold_within(config.odrive.max_velocity_deg_s, velocity);   // Set_Traj_Vel_Limit
    hold_within(config.gpio.max_velocity_deg_s, velocity);     // the pulse thread's profile
    hold_within(config.gpio.homing_speed_deg_s, velocity);
    hold_within(config.pwm.move_speed_deg_s, velocity);        // the commanded angle's slew
    return config;
}

std::unique_ptr<ptu::PtuDriver> make_ptu_driver(const DaemonConfig& given, const Clock& clock, std::string& error) {
    const DaemonConfig config = with_moves_within_soft_limits(given);
    const std::string& driver = config.ptu.driver;
    if (driver == "modbus") return ptu::make_modbus_driver(config.modbus, clock, error);
    if (driver == "canopen") return canopen::make_canopen_driver(config.canopen, clock, error);
    if (driver == "odrive") return odrive::make_odrive_driver(config.odrive, clock, error);
    if (driver == "gpio-stepper") return gpio::make_gpio_stepper_driver(config.gpio, clock, error);
    if (driver == "pwm-servo") return gpio::make_pwm_servo_driver(config.pwm, clock, error);
    return std::make_unique<ptu::MockPtu>(mock_ptu_config(config.mock, config.ptu.motion), clock);
}

}  // namespace rays::daemon
