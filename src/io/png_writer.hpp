// SPDX-License-Identifier: Apache-2.0
// 8-bit PNG output (grey or RGB) to a file or to memory, e.g. for overlays and snapshots.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace rays::io {

// data: h rows of w·channels bytes, channels 1 (grey) or 3 (RGB). Replaces out's contents.
bool encode_png(int w, int h, int channels, const std::uint8_t* data, std::vector<std::uint8_t>& out);

bool write_png(const std::string& path, int w, int h, int channels, const std::uint8_t* data, std::string& error);

}  // namespace rays::io
