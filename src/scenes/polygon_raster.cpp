// SPDX-License-Identifier: Apache-2.0
// Scoring a contour polygon against a mask exactly as ../shared/tools/score-contours.py does.
#include <limits>

#include "scenes/scene.hpp"

namespace rays::scenes {
namespace {

// Even-odd fill sampled at pixel centres: a pixel is inside when an odd number of the polygon's
// non-horizontal edges cross its row strictly to its right, an edge spanning rows y with
// (y0 > y) != (y1 > y). Fewer than 3 points fill nothing.
void rasterise(std::span<const Point> polygon, GreyImage& inside) {
    inside.px.fill(0);
    if (polygon.size() < 3) return;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Point a = polygon[i], b = polygon[(i + 1) % n];
        if (a.y == b.y) continue;
        for (int y = 0; y < kFrameSize; ++y) {
            if ((a.y > y) == (b.y > y)) continue;
            const double crossing_x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
            for (int x = 0; x < kFrameSize && x < crossing_x; ++x) inside.at(x, y) ^= 1;
        }
    }
}

}  // namespace

double polygon_mask_iou(std::span<const Point> polygon, const GreyImage& mask) {
    if (polygon.size() < 3) return 0.0;
    GreyImage inside;
    rasterise(polygon, inside);
    long both = 0, either = 0;
    for (std::size_t i = 0; i < inside.px.size(); ++i) {
        const bool m = mask.px[i] > 127, p = inside.px[i] != 0;
        both += m && p;
        either += m || p;
    }
    return either > 0 ? static_cast<double>(both) / static_cast<double>(either) : 0.0;
}

Point polygon_centroid_px(std::span<const Point> polygon) {
    GreyImage inside;
    rasterise(polygon, inside);
    double count = 0, sx = 0, sy = 0;
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x)
            if (inside.at(x, y)) {
                count += 1;
                sx += x;
                sy += y;
            }
    if (count == 0) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    return {sx / count, sy / count};
}

}  // namespace rays::scenes
