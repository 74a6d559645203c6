// SPDX-License-Identifier: Apache-2.0
// The PTU driver [ptu] driver names, built from its own section ([mock], [modbus], [canopen],
// [odrive], [gpio], [pwm]), not yet configured.
#pragma once
#include <memory>
#include <string>

#include "core/clock.hpp"
#include "daemon/daemon_config.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::daemon {

// The configuration with each drive's own position-move speed (profile velocity, homing speed) held
// within [ptu] max_velocity_deg_s as configured at start. PtuLimiter advances a position move's target
// (search, home, park, goto) at most at the soft velocity, but the drive's profile moves to each
// target, at its own speed between them. Accelerations stay as configured: a drive's deceleration
// also stops it. make_ptu_driver builds from this.
DaemonConfig with_moves_within_soft_limits(DaemonConfig config);

// Null with `error` when the section's settings cannot work together.
std::unique_ptr<ptu::PtuDriver> make_ptu_driver(const DaemonConfig& config, const Clock& clock, std::string& error);

}  // namespace rays::daemon
