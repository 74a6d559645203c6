// SPDX-License-Identifier: Apache-2.0
// The image gradient the greedy snake sees: central differences of the smoothed frame, and its
// magnitude |∇I| for the whole frame, computed once per frame into a preallocated image.
#pragma once
#include <algorithm>

#include "core/image.hpp"

namespace rays::snake {

// ∇I at pixel (x, y) in grey/px; one-sided at the frame's border (neighbours clamped into it).
inline Point gradient_at(const FloatImage& image, int x, int y) {
    const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, kFrameSize - 1);
    const int y0 = std::max(y - 1, 0), y1 = std::min(y + 1, kFrameSize - 1);
    return {(image.at(x1, y) - image.at(x0, y)) / static_cast<double>(x1 - x0),
            (image.at(x, y1) - image.at(x, y0)) / static_cast<double>(y1 - y0)};
}

// |∇I| of every pixel of `image` into `magnitude`. No allocation.
void gradient_magnitude(const FloatImage& image, FloatImage& magnitude);

}  // namespace rays::snake
