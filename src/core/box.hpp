// SPDX-License-Identifier: Apache-2.0
// A box start (ContourTracker::start_in): the target's extent as a person draws it round the target,
// in processing pixels — left, top, width, height — covering the pixels x … x+w−1 and y … y+h−1, as
// cv::Rect does (pixel centres at integers, so the box's centre is at x + (w−1)/2).
#pragma once
#include "core/image.hpp"

namespace rays {

struct Box {
    double x = 0.0;  // left, px
    double y = 0.0;  // top, px
    double w = 0.0;  // width, px
    double h = 0.0;  // height, px

    Point centre() const { return {x + 0.5 * (w - 1.0), y + 0.5 * (h - 1.0)}; }
};

// Why `box` cannot start a track, for the person who gave it, or nullptr when it can: its width and
// height are above 0 and it lies wholly inside the 128×128 processing frame.
const char* box_problem(const Box& box);

}  // namespace rays
