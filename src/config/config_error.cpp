// SPDX-License-Identifier: Apache-2.0
#include "config/config_error.hpp"

namespace rays::config {

std::string ConfigError::to_string() const {
    return file + ":" + std::to_string(line) + ": " + message;
}

}  // namespace rays::config
