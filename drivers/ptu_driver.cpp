// SPDX-License-Identifier: Apache-2.0
#include "drivers/ptu_driver.hpp"

#include <cstring>

namespace rays::ptu {

DriverStatus DriverStatus::failure(const char* text) {
    DriverStatus status;
    status.ok = false;
    if (text == nullptr) return status;
    const std::size_t length = strnlen(text, status.message.size() - 1);  // longer text is cut
    std::memcpy(status.message.data(), text, length);
    return status;  // message was zero-filled, so it stays NUL-terminated
}

}  // namespace rays::ptu
