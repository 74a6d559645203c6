// SPDX-License-Identifier: Apache-2.0
#include "capture/pixel_format.hpp"

#include <linux/videodev2.h>

#include <array>

namespace rays::capture {

const char* format_name(PixelFormat format) {
    switch (format) {
        case PixelFormat::Grey: return "GREY";
        case PixelFormat::Yuyv: return "YUYV";
        case PixelFormat::Mjpeg: return "MJPEG";
    }
    return "?";
}

std::string fourcc_text(std::uint32_t fourcc) {
    std::string text;
    for (int shift = 0; shift < 32; shift += 8) {
        const char c = static_cast<char>((fourcc >> shift) & 0xffu);
        if (c != ' ' && c != '\0') text += (c >= 0x21 && c <= 0x7e) ? c : '?';
    }
    return text;
}

std::optional<PixelFormat> format_of(std::uint32_t fourcc) {
    switch (fourcc) {
        case V4L2_PIX_FMT_GREY: return PixelFormat::Grey;
        case V4L2_PIX_FMT_YUYV: return PixelFormat::Yuyv;
        case V4L2_PIX_FMT_MJPEG:
        case V4L2_PIX_FMT_JPEG: return PixelFormat::Mjpeg;
        default: return std::nullopt;
    }
}

bool parse_format_request(const std::string& text, FormatRequest& out, std::string& error) {
    if (text == "auto") out.format.reset();
    else if (text == "grey") out.format = PixelFormat::Grey;
    else if (text == "yuyv") out.format = PixelFormat::Yuyv;
    else if (text == "mjpeg") out.format = PixelFormat::Mjpeg;
    else {
        error = "format '" + text + "' is not one of auto, grey, yuyv, mjpeg";
        return false;
    }
    return true;
}

std::optional<std::uint32_t> choose_format(FormatRequest request, std::span<const std::uint32_t> offered,
                                           std::string& error) {
    constexpr std::array kAutoOrder{PixelFormat::Grey, PixelFormat::Yuyv, PixelFormat::Mjpeg};
    for (PixelFormat wanted : kAutoOrder) {
        if (request.format && *request.format != wanted) continue;
        for (std::uint32_t fourcc : offered)
            if (format_of(fourcc) == wanted) return fourcc;
    }
    std::string has;
    for (std::uint32_t fourcc : offered) has += (has.empty() ? "" : ", ") + fourcc_text(fourcc);
    if (has.empty()) has = "none";
    error = request.format ? std::string("the device does not offer ") + format_name(*request.format)
                           : std::string("the device offers none of GREY, YUYV, MJPEG");
    error += " (it has: " + has + ")";
    return std::nullopt;
}

}  // namespace rays::capture
