// SPDX-License-Identifier: Apache-2.0
// Error messages shared by the INI loader and run-time set, with "did you mean" suggestions.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace rays::config {

// "unknown parameter rays.alpah (did you mean rays.alpha?)"
std::string unknown_parameter_message(std::string_view name, const std::vector<std::string_view>& names);

// "unknown section [detcet] (did you mean [detect]?)"
std::string unknown_section_message(std::string_view section, const std::vector<std::string_view>& sections);

// "key alpha comes before any [section] header (rays.alpha belongs under [rays])"
std::string key_outside_section_message(std::string_view key, const std::vector<std::string_view>& names);

// "rays.max_rays is a capacity, fixed at start: ..."
std::string capacity_is_fixed_message(std::string_view name);

}  // namespace rays::config
