// SPDX-License-Identifier: Apache-2.0
#include "snake/image_gradient.hpp"

#include <cmath>

namespace rays::snake {

void gradient_magnitude(const FloatImage& image, FloatImage& magnitude) {
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x) {
            const Point g = gradient_at(image, x, y);
            magnitude.at(x, y) = static_cast<float>(std::sqrt(g.x * g.x + g.y * g.y));
        }
}

}  // namespace rays::snake
