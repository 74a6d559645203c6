// SPDX-License-Identifier: Apache-2.0
#include "io/y4m_header.hpp"

#include <algorithm>
#include <charconv>

namespace rays::io {
namespace {

constexpr std::string_view kMagic = "YUV4MPEG2";

bool parse_int(std::string_view text, int& value) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc{} && ptr == end && !text.empty();
}

bool parse_side(char tag, std::string_view text, int& side, std::string& error) {
    if (!parse_int(text, side)) {
        error = std::string("bad ") + tag + " value '" + std::string(text) + "' in YUV4MPEG2 header";
        return false;
    }
    if (side < 1 || side > kMaxY4mSide) {
        error.assign(1, tag);
        error += std::to_string(side);
        error += " out of range 1..";
        error += std::to_string(kMaxY4mSide);
        return false;
    }
    return true;
}

// F<num>:<den>; F0:0 means unknown.
bool parse_rate(std::string_view text, Y4mHeader& out, std::string& error) {
    const auto colon = text.find(':');
    int num = 0;
    int den = 0;
    if (colon == std::string_view::npos || !parse_int(text.substr(0, colon), num) ||
        !parse_int(text.substr(colon + 1), den) || num < 0 || den < 0) {
        error = "bad frame rate F" + std::string(text) + " in YUV4MPEG2 header";
        return false;
    }
    out.fps_num = (num > 0 && den > 0) ? num : 0;
    out.fps_den = (num > 0 && den > 0) ? den : 0;
    return true;
}

bool parse_colour(std::string_view text, Y4mColour& colour, std::string& error) {
    if (text == "mono") colour = Y4mColour::Mono;
    else if (text == "mono16") colour = Y4mColour::Mono16;
    else if (text == "420" || text == "420jpeg" || text == "420paldv" || text == "420mpeg2") colour = Y4mColour::C420;
    else if (text == "411") colour = Y4mColour::C411;
    else if (text == "422") colour = Y4mColour::C422;
    else if (text == "444") colour = Y4mColour::C444;
    else if (text == "444alpha") colour = Y4mColour::C444Alpha;
    else {
        error = "unsupported colour space C" + std::string(text) +
                " (supported: mono, mono16, 420*, 411, 422, 444, 444alpha)";
        return false;
    }
    return true;
}

}  // namespace

double Y4mHeader::fps() const {
    return fps_den > 0 ? static_cast<double>(fps_num) / fps_den : 0.0;
}

std::size_t Y4mHeader::luma_bytes() const {
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    return colour == Y4mColour::Mono16 ? 2 * pixels : pixels;
}

// Chroma planes are subsampled with rounding up: a 5-wide 4:2:0 frame has 3-wide chroma rows.
std::size_t Y4mHeader::chroma_bytes() const {
    const std::size_t planes = 2 * static_cast<std::size_t>(chroma_width()) * static_cast<std::size_t>(chroma_height());
    if (colour == Y4mColour::C444Alpha) return planes + static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    return planes;
}

int Y4mHeader::chroma_width() const {
    switch (colour) {
        case Y4mColour::Mono:
        case Y4mColour::Mono16: return 0;
        case Y4mColour::C420:
        case Y4mColour::C422: return (width + 1) / 2;
        case Y4mColour::C411: return (width + 3) / 4;
        case Y4mColour::C444:
        case Y4mColour::C444Alpha: return width;
    }
    return 0;
}

int Y4mHeader::chroma_height() const {
    if (chroma_width() == 0) return 0;
    return colour == Y4mColour::C420 ? (height + 1) / 2 : height;
}

bool parse_y4m_header(std::string_view line, Y4mHeader& out, std::string& error) {
    if (line.substr(0, kMagic.size()) != kMagic || (line.size() > kMagic.size() && line[kMagic.size()] != ' ')) {
        error = "bad magic: not a YUV4MPEG2 stream";
        return false;
    }
    out = Y4mHeader{};
    bool have_width = false;
    bool have_height = false;
    std::size_t pos = kMagic.size();
    while (pos < line.size()) {
        const std::size_t end = std::min(line.find(' ', pos), line.size());
        const std::string_view token = line.substr(pos, end - pos);
        pos = end + 1;
        if (token.empty()) continue;
        const std::string_view value = token.substr(1);
        bool ok = true;
        switch (token[0]) {
            case 'W': ok = parse_side('W', value, out.width, error); have_width = true; break;
            case 'H': ok = parse_side('H', value, out.height, error); have_height = true; break;
            case 'F': ok = parse_rate(value, out, error); break;
            case 'C': ok = parse_colour(value, out.colour, error); break;
            default: break;  // I (interlacing), A (aspect), X (extensions) do not change the luma plane
        }
        if (!ok) return false;
    }
    if (!have_width || !have_height) {
        error = std::string("missing ") + (have_width ? "H" : "W") + " in YUV4MPEG2 header";
        return false;
    }
    return true;
}

}  // namespace rays::io
