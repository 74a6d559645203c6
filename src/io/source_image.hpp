// A decoded source frame before scaling: luma only, any size, row-major, stride = width.
#pragma once
#include <cstdint>
#include <vector>

namespace rays::io {

struct SourceImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> grey;
};

}  // namespace rays::io
