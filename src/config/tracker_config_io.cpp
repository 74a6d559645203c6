// SPDX-License-Identifier: Apache-2.0
#include "config/tracker_config_io.hpp"

#include "config/config_engine.hpp"
#include "config/config_table.hpp"

namespace rays::config {

std::optional<ConfigError> load_ini(const std::string& path, TrackerConfig& out) {
    return load_ini(path, tracker_params(), out);
}

std::optional<std::string> set_param(TrackerConfig& config, std::string_view name, std::string_view value,
                                     bool allow_capacity) {
    return set_param(tracker_params(), config, name, value, allow_capacity);
}

std::optional<std::string> get_param(const TrackerConfig& config, std::string_view name, std::string& value_out) {
    return get_param(tracker_params(), config, name, value_out);
}

nlohmann::json to_json(const TrackerConfig& config) { return to_json(tracker_params(), config); }

std::string sample_ini(const TrackerConfig& values) { return sample_ini(tracker_params(), values); }

std::vector<const ParamInfo*> list_params() { return list_params(tracker_params()); }

}  // namespace rays::config
