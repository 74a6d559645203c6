// SPDX-License-Identifier: Apache-2.0
#include "core/frame_sweep.hpp"

#include <algorithm>
#include <cmath>

namespace rays {

FilterMatch FrameSweep::next(CorrelationFilter& filter, const FloatImage& image, const Chroma& chroma) {
    const int per_axis = std::max(1, static_cast<int>(std::ceil(2.0 * kFrameSize / filter.window_px())));
    const double spacing = static_cast<double>(kFrameSize) / per_axis;
    FilterMatch best;
    for (int k = 0; k < kWindowsPerFrame; ++k) {
        const int window = cursor_++ % (per_axis * per_axis);
        const Point centre{(window % per_axis + 0.5) * spacing, (window / per_axis + 0.5) * spacing};
        const FilterMatch m = filter.locate(image, chroma, centre);
        if (m.psr > best.psr) best = m;
    }
    cursor_ %= per_axis * per_axis;
    return best;
}

}  // namespace rays
