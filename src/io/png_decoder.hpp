// SPDX-License-Identifier: Apache-2.0
// PNG to 8-bit luma through libpng: grey, grey+alpha, RGB, RGBA, palette, 1..16 bits per sample.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "io/source_image.hpp"

namespace rays::io {

// Holds its row buffers between files so a folder of equal-sized images decodes without regrowing them.
class PngDecoder {
public:
    // Decodes the file into out: alpha is dropped, colour becomes Rec.601 luma, 16-bit is rounded to 8.
    bool decode(const std::string& path, SourceImage& out, std::string& error);

private:
    std::vector<std::uint8_t> pixels_;   // decoded rows, 1 or 3 bytes per pixel
    std::vector<std::uint8_t*> rows_;    // pointers into pixels_ for libpng
};

}  // namespace rays::io
