// SPDX-License-Identifier: Apache-2.0
// A likelihood map read round a target drawn at a known place: the mean log-odds on the target
// beyond a contour round its middle, on the world well away from it, and over the whole map.
#pragma once
#include <algorithm>
#include <cmath>

#include "core/appearance_model.hpp"

namespace rays::test {

struct MapMeans {
    double target = 0.0;      // over the target's cells 8 … 12 px from its centre
    double background = 0.0;  // over the cells further than 20 px from it
    double magnitude = 0.0;   // mean |log-odds| over the whole map
    float most = -1e9f;       // the largest log-odds anywhere
};

inline MapMeans map_means(const LikelihoodMap& map, Point target) {
    MapMeans m;
    int nt = 0, nb = 0;
    for (int j = 0; j < kChromaSize; ++j)
        for (int i = 0; i < kChromaSize; ++i) {
            const double d = std::hypot(2 * i + 0.5 - target.x, 2 * j + 0.5 - target.y);
            const float v = map.cell(i, j);
            m.magnitude += std::abs(v) / kChromaPixels;
            m.most = std::max(m.most, v);
            if (d >= 8.0 && d <= 12.0) m.target += v, ++nt;
            if (d > 20.0) m.background += v, ++nb;
        }
    m.target /= nt;
    m.background /= nb;
    return m;
}

}  // namespace rays::test
