// SPDX-License-Identifier: Apache-2.0
// The whole-frame search for a lost target's looks, a few filter windows a frame: the windows lie on
// a grid of half the filter's window, so that every place in the frame is near some window's middle,
// and each frame's search goes on where the last one stopped. Fixed size; nothing allocated.
#pragma once

#include "core/correlation_filter.hpp"

namespace rays {

class FrameSweep {
public:
    static constexpr int kWindowsPerFrame = 4;  // each a filter locate

    // From the frame's first window again (a new loss).
    void restart() { cursor_ = 0; }
    // The clearest match in the sweep's next kWindowsPerFrame windows of `image`.
    FilterMatch next(CorrelationFilter& filter, const FloatImage& image, const Chroma& chroma);

private:
    int cursor_ = 0;  // the next window
};

}  // namespace rays
