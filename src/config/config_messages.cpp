// SPDX-License-Identifier: Apache-2.0
#include "config/config_messages.hpp"

#include <optional>

#include "config/name_suggestion.hpp"

namespace rays::config {
namespace {

std::string suggestion(std::optional<std::string_view> closest, std::string_view before, std::string_view after) {
    if (!closest) return {};
    return " (did you mean " + std::string(before) + std::string(*closest) + std::string(after) + "?)";
}

}  // namespace

std::string unknown_parameter_message(std::string_view name, const std::vector<std::string_view>& names) {
    return "unknown parameter " + std::string(name) + suggestion(closest_name(name, names), "", "");
}

std::string unknown_section_message(std::string_view section, const std::vector<std::string_view>& sections) {
    return "unknown section [" + std::string(section) + "]" + suggestion(closest_name(section, sections), "[", "]");
}

std::string key_outside_section_message(std::string_view key, const std::vector<std::string_view>& names) {
    std::string message = "key " + std::string(key) + " comes before any [section] header";
    for (std::string_view name : names) {
        std::size_t dot = name.find('.');
        if (name.substr(dot + 1) == key)
            return message + " (" + std::string(name) + " belongs under [" + std::string(name.substr(0, dot)) + "])";
    }
    return message;
}

std::string capacity_is_fixed_message(std::string_view name) {
    return std::string(name) + " is a capacity, fixed at start: change it in the configuration file and restart";
}

}  // namespace rays::config
