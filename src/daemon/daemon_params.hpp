// SPDX-License-Identifier: Apache-2.0
// The parameter table of raysd's INI file: the tracking core's keys and one section per subsystem.
#pragma once
#include <optional>
#include <string>

#include "config/config_error.hpp"
#include "config/param_table.hpp"
#include "daemon/daemon_config.hpp"

namespace rays::daemon {

// Built once, on first use.
const config::ParamTable<DaemonConfig>& daemon_params();

// Reads `path` over DaemonConfig{}; `out` changes only when the whole file is valid.
std::optional<config::ConfigError> load_daemon_config(const std::string& path, DaemonConfig& out);

// The names of the capacities (fixed-at-start keys) whose values differ between `a` and `b`,
// comma-separated; empty when none do. A reload applies tunables only and reports these.
std::string changed_capacities(const DaemonConfig& a, const DaemonConfig& b);

// What config/raysd.ini holds for a real rig: the built-in defaults (a V4L2 camera) with a real PTU
// driver (a Modbus dual-axis drive on an RS-485 adapter) in place of the mock, so an installed
// raysd never drives a simulation by default.
DaemonConfig rig_template();

// Copies every tunable of `from` into `to`, leaving the capacities of `to` as they are.
void copy_tunables(const DaemonConfig& from, DaemonConfig& to);

}  // namespace rays::daemon
