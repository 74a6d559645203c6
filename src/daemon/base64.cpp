// SPDX-License-Identifier: Apache-2.0
#include "daemon/base64.hpp"

namespace rays::daemon {
namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

int sextet(char c) {
    for (int i = 0; i < 64; ++i)
        if (kAlphabet[i] == c) return i;
    return -1;
}

}  // namespace

std::string base64_encode(const std::vector<std::uint8_t>& data) {
    std::string text;
    text.reserve((data.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < data.size(); i += 3) {
        std::uint32_t triple = (std::uint32_t{data[i]} << 16) | (std::uint32_t{data[i + 1]} << 8) | data[i + 2];
        for (int shift = 18; shift >= 0; shift -= 6) text += kAlphabet[(triple >> shift) & 63];
    }
    if (std::size_t rest = data.size() - i; rest > 0) {
        std::uint32_t triple = std::uint32_t{data[i]} << 16;
        if (rest == 2) triple |= std::uint32_t{data[i + 1]} << 8;
        text += kAlphabet[(triple >> 18) & 63];
        text += kAlphabet[(triple >> 12) & 63];
        text += rest == 2 ? kAlphabet[(triple >> 6) & 63] : '=';
        text += '=';
    }
    return text;
}

bool base64_decode(const std::string& text, std::vector<std::uint8_t>& out) {
    out.clear();
    if (text.size() % 4 != 0) return false;
    for (std::size_t i = 0; i < text.size(); i += 4) {
        std::uint32_t triple = 0;
        int padding = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            char c = text[i + k];
            bool last_group = i + 4 == text.size();
            int value = 0;
            if (c == '=' && last_group && k >= 2) ++padding;
            else if (padding > 0 || (value = sextet(c)) < 0) return false;
            triple = (triple << 6) | static_cast<std::uint32_t>(value);
        }
        out.push_back(static_cast<std::uint8_t>(triple >> 16));
        if (padding < 2) out.push_back(static_cast<std::uint8_t>(triple >> 8));
        if (padding < 1) out.push_back(static_cast<std::uint8_t>(triple));
    }
    return true;
}

}  // namespace rays::daemon
