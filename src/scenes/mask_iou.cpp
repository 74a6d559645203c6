#include <cmath>
#include <vector>

#include "scenes/scene.hpp"

namespace rays::scenes {

double polygon_mask_iou(std::span<const Point> polygon, const GreyImage& mask) {
    if (polygon.size() < 3) return 0.0;
    // Even-odd rule at pixel centres: a pixel is inside when an odd number of edges cross its row
    // to its right (as score-contours.py).
    std::vector<unsigned char> inside(kFramePixels, 0);
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Point a = polygon[i], b = polygon[(i + 1) % n];
        if (a.y == b.y) continue;
        for (int y = 0; y < kFrameSize; ++y) {
            if ((a.y > y) == (b.y > y)) continue;
            const double xc = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
            for (int x = 0; x < kFrameSize && x < xc; ++x) inside[static_cast<std::size_t>(y * kFrameSize + x)] ^= 1;
        }
    }
    long both = 0, either = 0;
    for (int i = 0; i < kFramePixels; ++i) {
        const bool m = mask.px[static_cast<std::size_t>(i)] > 127, p = inside[static_cast<std::size_t>(i)] != 0;
        both += m && p;
        either += m || p;
    }
    return either > 0 ? static_cast<double>(both) / static_cast<double>(either) : 0.0;
}

}  // namespace rays::scenes
