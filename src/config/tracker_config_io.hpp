// SPDX-License-Identifier: Apache-2.0
// The tracking core's configuration file and run-time parameters, all driven by tracker_params().
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config/config_error.hpp"
#include "config/param_info.hpp"
#include "core/tracker_config.hpp"

namespace rays::config {

// Reads an INI file over TrackerConfig{}; on error `out` is unchanged and the error names the line.
std::optional<ConfigError> load_ini(const std::string& path, TrackerConfig& out);

// Sets one parameter by name ("rays.alpha") from text; validated as in the file, cross-field rules
// included. Capacities are refused unless `allow_capacity`. On error `config` is unchanged.
std::optional<std::string> set_param(TrackerConfig& config, std::string_view name, std::string_view value,
                                     bool allow_capacity);

// The parameter's value as text the file and set_param accept.
std::optional<std::string> get_param(const TrackerConfig& config, std::string_view name, std::string& value_out);

// Flat object of every setting: {"rays.alpha": 0.02, ...}.
nlohmann::json to_json(const TrackerConfig& config);

// A documented INI file setting every key to its value in `values`.
std::string sample_ini(const TrackerConfig& values);

// Every parameter in table order, for listings such as "raysctl get".
std::vector<const ParamInfo*> list_params();

}  // namespace rays::config
