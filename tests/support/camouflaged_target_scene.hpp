// SPDX-License-Identifier: Apache-2.0
// A colour scene drawn by the tests: a round target of the same blocky texture, grey range and
// colours as the world it crosses, while the camera pans the other way. Neither its edges (the
// texture's are everywhere) nor its colours tell it from the world; that it moves with itself does.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <vector>

#include "core/contour.hpp"
#include "core/image.hpp"
#include "scenes/scene.hpp"
#include "support/block_texture.hpp"

namespace rays::test {

struct CamouflagedTargetScene {
    static constexpr double kRadius = 16.0;       // the target's, px
    static constexpr double kTargetStep = 0.75;   // px per frame, to the right
    static constexpr double kPanStep = 1.5;       // px per frame: the view shows the world moving left
    static constexpr Point kStart{44.0, 64.0};    // the target's centre in frame 0

    GreyImage image;
    Chroma chroma;
    GreyImage mask;  // 255 on the target

    Point centre(int frame) const { return {kStart.x + kTargetStep * frame, kStart.y}; }

    void draw(int frame) {
        const Point c = centre(frame);
        const double pan = kPanStep * frame;  // the view at x shows the world at x + pan
        for (int y = 0; y < kFrameSize; ++y)
            for (int x = 0; x < kFrameSize; ++x) {
                const double dx = x - c.x, dy = y - c.y;
                const bool on = dx * dx + dy * dy <= kRadius * kRadius;
                const double grey = on ? smooth_blocks(dx, dy, 7u, 5.0, 60, 120) : smooth_blocks(x + pan, y, 1u, 5.0, 60, 120);
                image.at(x, y) = static_cast<std::uint8_t>(std::lround(grey));
                mask.at(x, y) = on ? 255 : 0;
            }
        chroma.present = true;
        for (int j = 0; j < kChromaSize; ++j)
            for (int i = 0; i < kChromaSize; ++i) {
                const auto k = static_cast<std::size_t>(j * kChromaSize + i);
                chroma.u[k] = 110;  // one brownish colour, target and world alike
                chroma.v[k] = 150;
            }
    }
};

// The contour's intersection over union with a mask.
inline double contour_mask_iou(const Contour& contour, const GreyImage& mask) {
    std::vector<Point> polygon(static_cast<std::size_t>(contour.size));
    for (int i = 0; i < contour.size; ++i) polygon[static_cast<std::size_t>(i)] = contour.points[static_cast<std::size_t>(i)].p;
    return scenes::polygon_mask_iou(polygon, mask);
}

}  // namespace rays::test
