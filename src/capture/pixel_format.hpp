// SPDX-License-Identifier: Apache-2.0
// The capture formats the camera understands, their V4L2 four-character codes, and the choice among
// what a device offers.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace rays::capture {

enum class PixelFormat { Grey, Yuyv, Mjpeg };

const char* format_name(PixelFormat format);  // "GREY", "YUYV", "MJPEG"
std::string fourcc_text(std::uint32_t fourcc);  // 'MJPG' → "MJPG"

// The format a fourcc carries, if it is one we read ('MJPG' and 'JPEG' are both MJPEG).
std::optional<PixelFormat> format_of(std::uint32_t fourcc);

// The user's choice: "auto", "grey", "yuyv" or "mjpeg". False with error for anything else.
struct FormatRequest {
    std::optional<PixelFormat> format;  // empty: auto
};
bool parse_format_request(const std::string& text, FormatRequest& out, std::string& error);

// Picks from the fourccs a device offers, in its order: the requested format, or in auto the first
// GREY, else YUYV, else MJPEG (cheapest to read first). Returns the chosen fourcc, or nullopt with an
// error naming what the device has.
std::optional<std::uint32_t> choose_format(FormatRequest request, std::span<const std::uint32_t> offered,
                                           std::string& error);

}  // namespace rays::capture
