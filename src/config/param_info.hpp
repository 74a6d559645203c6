// SPDX-License-Identifier: Apache-2.0
// What a configuration parameter is, independent of the struct that holds it: the description
// that parsing, validation, listing and the sample file all read.
#pragma once
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

namespace rays::config {

// Text holds any one-line string (a path); Choice one of a fixed list of words. Both are strings in
// ParamValue, which lists its alternatives in the order of ParamType's first four.
enum class ParamType { Int, Double, Bool, Text, Choice };
enum class ParamKind {
    Capacity,  // sizes buffers: fixed when the daemon starts
    Tunable,   // may change at run time, within the capacities
};

using ParamValue = std::variant<int, double, bool, std::string>;

template <class T>
constexpr ParamType param_type_of() {
    static_assert(std::is_same_v<T, int> || std::is_same_v<T, double> || std::is_same_v<T, bool> ||
                      std::is_same_v<T, std::string>,
                  "a parameter is an int, a double, a bool or a string");
    if constexpr (std::is_same_v<T, int>) return ParamType::Int;
    else if constexpr (std::is_same_v<T, double>) return ParamType::Double;
    else if constexpr (std::is_same_v<T, bool>) return ParamType::Bool;
    else return ParamType::Text;
}

struct ParamInfo {
    std::string name;  // "section.key", e.g. "rays.alpha" is key alpha under [rays]
    ParamType type = ParamType::Double;
    ParamKind kind = ParamKind::Tunable;
    std::string_view unit;  // "px", "grey/px", ... or "" for a plain number (unit and choices: literals)
    double min = 0.0;       // inclusive range; numbers only
    double max = 0.0;
    ParamValue default_value;  // read from the settings struct's default member initialiser
    std::string doc;           // one line (owned: tables may build it, e.g. per axis)
    std::string_view choices;  // Choice only: the accepted words, separated by '|' ("v4l2|replay")

    std::string_view section() const { return std::string_view(name).substr(0, name.find('.')); }
    std::string_view key() const { return std::string_view(name).substr(name.find('.') + 1); }
};

}  // namespace rays::config
