// SPDX-License-Identifier: Apache-2.0
// Parameter values as text: the one place where "0.02", "yes" or "360" become typed values and
// back, with the range check, so the INI file and run-time set accept exactly the same input.
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "config/param_info.hpp"

namespace rays::config {

// Parses `text` as a value of `param` (type, then range). Returns an error message naming the
// parameter, e.g. "rays.alpha = -1 is out of range [0, 10]"; `out` is untouched on error.
std::optional<std::string> parse_value(const ParamInfo& param, std::string_view text, ParamValue& out);

// Shortest text that parses back to the same value: "360", "0.02", "true".
std::string format_value(const ParamValue& value);

// Shortest fixed-point text that parses back to `number`: "720", "0.002".
std::string format_number(double number);

// The value as a number for cross-field rules (bools read as 0 or 1, text as NaN).
double value_as_number(const ParamValue& value);

// "int, range [4, 4096] rays", "real, range [0, 10]", "bool (true/false)", "text" or "one of a|b".
std::string describe_type_and_range(const ParamInfo& param);

}  // namespace rays::config
