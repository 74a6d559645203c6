// SPDX-License-Identifier: Apache-2.0
// An error found in a configuration file, named by file and line (line 0: the file as a whole).
#pragma once
#include <string>

namespace rays::config {

struct ConfigError {
    std::string file;
    int line = 0;
    std::string message;

    std::string to_string() const;  // "FILE:LINE: message"
};

}  // namespace rays::config
