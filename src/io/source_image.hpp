// SPDX-License-Identifier: Apache-2.0
// A decoded source frame before scaling, any size, row-major: the luma (stride = width) and, where the
// source has colour, its Cb and Cr planes at their own resolution (stride = chroma_width; 4:2:0 halves
// both axes, 4:2:2 the width). chroma_width = 0: a mono source.
#pragma once
#include <cstdint>
#include <vector>

namespace rays::io {

struct SourceImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> grey;
    int chroma_width = 0;
    int chroma_height = 0;
    std::vector<std::uint8_t> u;
    std::vector<std::uint8_t> v;

    bool has_chroma() const { return chroma_width > 0; }
};

}  // namespace rays::io
