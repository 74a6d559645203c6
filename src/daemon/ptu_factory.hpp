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

// Null with `error` when the section's settings cannot work together.
std::unique_ptr<ptu::PtuDriver> make_ptu_driver(const DaemonConfig& config, const Clock& clock, std::string& error);

}  // namespace rays::daemon
