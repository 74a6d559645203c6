// SPDX-License-Identifier: Apache-2.0
// Standard base64 (RFC 4648, with padding), for binary data inside JSON replies.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace rays::daemon {

std::string base64_encode(const std::vector<std::uint8_t>& data);

// False on a character outside the alphabet or a length that is not a multiple of 4.
bool base64_decode(const std::string& text, std::vector<std::uint8_t>& out);

}  // namespace rays::daemon
