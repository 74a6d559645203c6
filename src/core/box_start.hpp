// SPDX-License-Identifier: Apache-2.0
// Where a box start's rays begin. The rays see the contour from m (a star-shaped contour, eq. 8),
// and a box's centre need not lie on the target at all: a swan whose neck rises from one end of its
// body leaves the middle of the box round it on the water. Where the colours seeded from the box
// (AppearanceModel::seed_box) call the centre background, the rays begin at the deepest of the box's
// target-coloured cells instead: the one farthest from every cell they call background and from the
// box's border (a two-pass chamfer distance, 1 and √2 a step), the nearest to the centre among equals.
// Where they call the centre the target, or call nothing inside the box the target, the box's centre.
// Fixed memory; nothing allocated.
#pragma once
#include <array>

#include "core/appearance_model.hpp"
#include "core/box.hpp"

namespace rays {

class BoxStartPoint {
public:
    // `colours`: the log-odds seeded from `box` (> 0: the target's colours).
    Point find(const Box& box, const LikelihoodMap& colours);

private:
    std::array<float, kChromaPixels> depth_{};  // per cell, in cells; 0 outside the target's colours
};

}  // namespace rays
