// SPDX-License-Identifier: Apache-2.0
#include "io/pgm_decoder.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "io/stdio_file.hpp"

namespace rays::io {
namespace {

constexpr int kMaxSide = 8192;

// Skips whitespace and '#' comments (which run to the end of the line), then reads a decimal number.
bool read_number(std::FILE* file, int& value) {
    int c = std::getc(file);
    while (c == '#' || std::isspace(c)) {
        if (c == '#')
            while (c != '\n' && c != EOF) c = std::getc(file);
        c = std::getc(file);
    }
    if (!std::isdigit(c)) return false;
    long long v = 0;
    for (; std::isdigit(c); c = std::getc(file)) {
        v = v * 10 + (c - '0');
        if (v > 1'000'000) return false;
    }
    if (c != EOF) std::ungetc(c, file);
    value = static_cast<int>(v);
    return true;
}

// Maps 0..maxval onto 0..255 with rounding to nearest.
std::uint8_t to_8bit(int v, int maxval) {
    return static_cast<std::uint8_t>(maxval == 255 ? v : (v * 255 + maxval / 2) / maxval);
}

bool read_binary_samples(std::FILE* file, int maxval, SourceImage& out) {
    if (maxval == 255) return std::fread(out.grey.data(), 1, out.grey.size(), file) == out.grey.size();
    for (auto& px : out.grey) {
        int v = std::getc(file);
        if (maxval > 255) {  // two bytes, most significant first
            const int low = std::getc(file);
            if (v == EOF || low == EOF) return false;
            v = (v << 8) | low;
        }
        if (v == EOF || v > maxval) return false;
        px = to_8bit(v, maxval);
    }
    return true;
}

bool read_ascii_samples(std::FILE* file, int maxval, SourceImage& out) {
    for (auto& px : out.grey) {
        int v = 0;
        if (!read_number(file, v) || v > maxval) return false;
        px = to_8bit(v, maxval);
    }
    return true;
}

}  // namespace

bool read_pgm(const std::string& path, SourceImage& out, std::string& error) {
    StdioFile file(std::fopen(path.c_str(), "rb"));
    if (!file) {
        error = path + ": cannot open: " + std::strerror(errno);
        return false;
    }
    const int m0 = std::getc(file.get());
    const int m1 = std::getc(file.get());
    if (m0 != 'P' || (m1 != '5' && m1 != '2')) {
        error = path + ": not a PGM file (expected P5 or P2)";
        return false;
    }
    int width = 0;
    int height = 0;
    int maxval = 0;
    if (!read_number(file.get(), width) || !read_number(file.get(), height) || !read_number(file.get(), maxval)) {
        error = path + ": bad PGM header";
        return false;
    }
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide || maxval < 1 || maxval > 65535) {
        error = path + ": PGM size " + std::to_string(width) + "x" + std::to_string(height) + " or maxval " +
                std::to_string(maxval) + " out of range";
        return false;
    }
    out.width = width;
    out.height = height;
    out.grey.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    bool ok = true;
    if (m1 == '5') {
        // Exactly one whitespace byte separates maxval from the samples.
        ok = std::isspace(std::getc(file.get())) && read_binary_samples(file.get(), maxval, out);
    } else {
        ok = read_ascii_samples(file.get(), maxval, out);
    }
    if (!ok) error = path + ": truncated or invalid PGM samples";
    return ok;
}

}  // namespace rays::io
