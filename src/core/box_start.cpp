// SPDX-License-Identifier: Apache-2.0
#include "core/box_start.hpp"

#include <algorithm>
#include <cmath>

namespace rays {

Point BoxStartPoint::find(const Box& box, const LikelihoodMap& colours) {
    const Point centre = box.centre();
    auto nearest_cell = [](double px) { return std::clamp(static_cast<int>(std::lround((px - 0.5) / 2.0)), 0, kChromaSize - 1); };
    if (colours.cell(nearest_cell(centre.x), nearest_cell(centre.y)) > 0.0f) return centre;
    // The cells whose centres (2i + 0.5, 2j + 0.5) lie on the box's pixels x … x + w − 1, y … y + h − 1.
    const int i0 = std::max(0, static_cast<int>(std::ceil((box.x - 0.5) / 2.0)));
    const int i1 = std::min(kChromaSize - 1, static_cast<int>(std::floor((box.x + box.w - 1.5) / 2.0)));
    const int j0 = std::max(0, static_cast<int>(std::ceil((box.y - 0.5) / 2.0)));
    const int j1 = std::min(kChromaSize - 1, static_cast<int>(std::floor((box.y + box.h - 1.5) / 2.0)));
    if (i0 > i1 || j0 > j1) return centre;
    auto depth = [&](int i, int j) -> float& { return depth_[static_cast<std::size_t>(j * kChromaSize + i)]; };
    // Outside the box counts as background: its border bounds the depth.
    auto seen = [&](int i, int j) { return i < i0 || i > i1 || j < j0 || j > j1 ? 0.0f : depth(i, j); };
    constexpr float kFar = 1e6f, kDiagonal = 1.41421356f;
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) depth(i, j) = colours.cell(i, j) > 0.0f ? kFar : 0.0f;
    for (int j = j0; j <= j1; ++j)  // forward: from the left and above
        for (int i = i0; i <= i1; ++i)
            if (depth(i, j) > 0.0f)
                depth(i, j) = std::min({depth(i, j), seen(i - 1, j) + 1.0f, seen(i, j - 1) + 1.0f,
                                        seen(i - 1, j - 1) + kDiagonal, seen(i + 1, j - 1) + kDiagonal});
    for (int j = j1; j >= j0; --j)  // backward: from the right and below
        for (int i = i1; i >= i0; --i)
            if (depth(i, j) > 0.0f)
                depth(i, j) = std::min({depth(i, j), seen(i + 1, j) + 1.0f, seen(i, j + 1) + 1.0f,
                                        seen(i + 1, j + 1) + kDiagonal, seen(i - 1, j + 1) + kDiagonal});
    Point best = centre;
    float deepest = 0.0f;
    double nearest = 0.0;
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            const Point p{2.0 * i + 0.5, 2.0 * j + 0.5};
            const double d2 = (p.x - centre.x) * (p.x - centre.x) + (p.y - centre.y) * (p.y - centre.y);
            if (depth(i, j) > deepest || (depth(i, j) == deepest && deepest > 0.0f && d2 < nearest)) {
                deepest = depth(i, j);
                nearest = d2;
                best = p;
            }
        }
    return best;
}

}  // namespace rays
