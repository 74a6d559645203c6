// SPDX-License-Identifier: Apache-2.0
#include "config/param_text.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <system_error>
#include <type_traits>

namespace rays::config {
namespace {

bool equals_ignoring_case(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        char x = a[i] >= 'A' && a[i] <= 'Z' ? static_cast<char>(a[i] - 'A' + 'a') : a[i];
        if (x != b[i]) return false;
    }
    return true;
}

std::string_view trim(std::string_view text) {
    const std::string_view blanks = " \t\r\n";
    std::size_t first = text.find_first_not_of(blanks);
    if (first == std::string_view::npos) return {};
    return text.substr(first, text.find_last_not_of(blanks) - first + 1);
}

std::string prefix(const ParamInfo& param, std::string_view text) {
    return param.name + " = " + std::string(text);
}

// inih strips an inline comment only after whitespace and ';', so "0.5 # note" reaches us whole.
std::string trailing_text_note(std::string_view rest) {
    std::string note = " (unexpected '" + std::string(rest) + "'";
    if (rest.find_first_of("#;") != std::string_view::npos) note += "; an inline comment starts with ' ;'";
    return note + ")";
}

std::string range_text(const ParamInfo& param) {
    // Appended piece by piece: '"[" + std::string' trips g++ 12's false -Wrestrict (GCC bug 105329).
    std::string text = "[";
    text += format_number(param.min);
    text += ", ";
    text += format_number(param.max);
    text += "]";
    if (!param.unit.empty()) {
        text += " ";
        text += param.unit;
    }
    return text;
}

std::optional<std::string> check_range(const ParamInfo& param, std::string_view text, double number) {
    if (number >= param.min && number <= param.max) return std::nullopt;
    return prefix(param, text) + " is out of range " + range_text(param);
}

std::optional<std::string> parse_int(const ParamInfo& param, std::string_view text, ParamValue& out) {
    long long number = 0;
    const char* end = text.data() + text.size();
    auto [stop, status] = std::from_chars(text.data(), end, number);
    if (status == std::errc::result_out_of_range) return prefix(param, text) + " is out of range " + range_text(param);
    if (status != std::errc{}) return prefix(param, text) + " is not an integer";
    if (stop != end) return prefix(param, text) + " is not an integer" + trailing_text_note({stop, end});
    if (auto error = check_range(param, text, static_cast<double>(number))) return error;
    out = static_cast<int>(number);
    return std::nullopt;
}

std::optional<std::string> parse_double(const ParamInfo& param, std::string_view text, ParamValue& out) {
    double number = 0.0;
    const char* end = text.data() + text.size();
    auto [stop, status] = std::from_chars(text.data(), end, number);
    if (status == std::errc::result_out_of_range) return prefix(param, text) + " is out of range " + range_text(param);
    if (status != std::errc{}) return prefix(param, text) + " is not a number";
    if (stop != end) return prefix(param, text) + " is not a number" + trailing_text_note({stop, end});
    if (!std::isfinite(number)) return prefix(param, text) + " is not a finite number";
    if (auto error = check_range(param, text, number)) return error;
    out = number;
    return std::nullopt;
}

std::optional<std::string> parse_bool(const ParamInfo& param, std::string_view text, ParamValue& out) {
    constexpr std::array<std::string_view, 4> yes = {"true", "yes", "on", "1"};
    constexpr std::array<std::string_view, 4> no = {"false", "no", "off", "0"};
    for (std::string_view word : yes) {
        if (equals_ignoring_case(text, word)) {
            out = true;
            return std::nullopt;
        }
    }
    for (std::string_view word : no) {
        if (equals_ignoring_case(text, word)) {
            out = false;
            return std::nullopt;
        }
    }
    return prefix(param, text) + " is not a boolean (use true/false, yes/no, on/off or 1/0)";
}

constexpr std::size_t kMaxTextLength = 1024;

std::optional<std::string> parse_text(const ParamInfo& param, std::string_view text, ParamValue& out) {
    if (text.size() > kMaxTextLength)
        return param.name + " is longer than " + std::to_string(kMaxTextLength) + " characters";
    for (char c : text)
        if (static_cast<unsigned char>(c) < 0x20) return param.name + " contains a control character";
    // An INI file reads " ;x" as a comment but "key =;x" as ";x": refused everywhere, so that set
    // accepts what a file does and every value reads back from the file sample_ini writes.
    if (text.starts_with(';') || text.find(" ;") != std::string_view::npos)
        return prefix(param, text) + " has a ';' at its start or after a blank, where an INI file starts a comment";
    out = std::string(text);
    return std::nullopt;
}

std::optional<std::string> parse_choice(const ParamInfo& param, std::string_view text, ParamValue& out) {
    std::string_view rest = param.choices;
    while (!rest.empty()) {
        std::size_t bar = rest.find('|');
        if (rest.substr(0, bar) == text) {
            out = std::string(text);
            return std::nullopt;
        }
        rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
    }
    return prefix(param, text) + " is not one of " + std::string(param.choices);
}

}  // namespace

std::optional<std::string> parse_value(const ParamInfo& param, std::string_view text, ParamValue& out) {
    text = trim(text);
    if (text.empty() && param.type != ParamType::Text) return param.name + " has no value";
    switch (param.type) {
    case ParamType::Int: return parse_int(param, text, out);
    case ParamType::Double: return parse_double(param, text, out);
    case ParamType::Bool: return parse_bool(param, text, out);
    case ParamType::Text: return parse_text(param, text, out);
    case ParamType::Choice: return parse_choice(param, text, out);
    }
    return param.name + " has an unknown type";
}

std::string format_number(double number) {
    std::array<char, 64> buffer{};
    auto [end, status] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), number, std::chars_format::fixed);
    if (status != std::errc{})  // wider than the buffer in fixed notation: let to_chars pick
        end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), number).ptr;
    return std::string(buffer.data(), end);
}

std::string format_value(const ParamValue& value) {
    if (const int* number = std::get_if<int>(&value)) return std::to_string(*number);
    if (const bool* flag = std::get_if<bool>(&value)) return *flag ? "true" : "false";
    if (const std::string* text = std::get_if<std::string>(&value)) return *text;
    return format_number(std::get<double>(value));
}

double value_as_number(const ParamValue& value) {
    return std::visit(
        [](const auto& v) {
            if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::string>) return std::nan("");
            else return static_cast<double>(v);
        },
        value);
}

std::string describe_type_and_range(const ParamInfo& param) {
    switch (param.type) {
    case ParamType::Bool: return "bool (true/false)";
    case ParamType::Int: return "int, range " + range_text(param);
    case ParamType::Double: return "real, range " + range_text(param);
    case ParamType::Text: return "text";
    case ParamType::Choice: return "one of " + std::string(param.choices);
    }
    return {};
}

}  // namespace rays::config
