// SPDX-License-Identifier: Apache-2.0
// Rules between parameters (a count within its capacity, a minimum below its maximum), checked
// after every key is read and on every run-time change. Rules name parameters rather than struct
// fields, so they work on any settings struct whose table holds those names.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rays::config {

// Reads a parameter's current value by name (bools read as 0 or 1).
using ParamLookup = std::function<double(std::string_view name)>;

struct CrossRule {
    std::vector<std::string> keys;  // the parameters it relates; a file error names the last of them set
    std::function<std::optional<std::string>(const ParamLookup&)> check;  // error message or nullopt
};

// lower <= upper, e.g. at_most("rays.count", "rays.max_rays").
CrossRule at_most(std::string lower, std::string upper);

// lower < upper.
CrossRule less_than(std::string lower, std::string upper);

}  // namespace rays::config
