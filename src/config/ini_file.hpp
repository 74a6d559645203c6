// SPDX-License-Identifier: Apache-2.0
// Reads an INI file with libinih and hands each section header and key to a visitor, keeping the
// line number itself (Debian builds libinih without INI_HANDLER_LINENO). Stops at the first error.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "config/config_error.hpp"

namespace rays::config {

struct IniEntry {
    std::string_view section;  // "" before the first [section] header
    std::string_view key;
    std::string_view value;  // blanks and an inline "; comment" removed
    int line;
};

struct IniVisitor {
    // Each return an error message for the current line, or nullopt to go on.
    std::function<std::optional<std::string>(std::string_view name)> section;
    std::function<std::optional<std::string>(const IniEntry& entry)> entry;
};

// The first error in file order: the file cannot be read (line 0), a syntax error, a line too
// long, an indented line (libinih would take it as a continued value), or a visitor's error.
std::optional<ConfigError> read_ini(const std::string& path, const IniVisitor& visitor);

}  // namespace rays::config
