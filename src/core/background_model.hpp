// SPDX-License-Identifier: Apache-2.0
// The still camera's background: a running average of the smoothed frames, learned where they look
// like it and not round the target, and from it how much each pixel of a frame looks like foreground
// (0 … 1). The paper finds the mover by differencing consecutive frames (§4.1); a background learned
// over many frames tells the whole target from the background, not only its leading and trailing
// edges, even where the two are alike in grey (a dark walker passing dark clouds differs from what
// was there before). Only a still camera has one: a turning camera resets it. Fixed memory.
#pragma once
#include "core/contour.hpp"
#include "core/image.hpp"

namespace rays {

class BackgroundModel {
public:
    void reset() { frames_ = 0; }

    // Rates each pixel of the frame against the background learned so far (the foreground()).
    void rate(const FloatImage& smoothed);
    // Learns the frame where it looks like the background, except round `target` (null: no target).
    // Foreground that has not changed for a while becomes background, even there: a target that
    // stood still for long, or the ghost of what stood where the background was first learned.
    void learn(const FloatImage& smoothed, const Contour* target);

    // The rated frame's foreground; null when too few frames were learned since the last reset for
    // it to mean something, or when the frame is so unlike the background (a light switched on, the
    // camera knocked) that it says nothing.
    const FloatImage* foreground() const;
    double noise() const { return noise_; }  // mean |frame − background| where nothing moves, grey

private:
    bool ready() const;

    FloatImage background_;
    FloatImage foreground_;
    FloatImage last_;                // each row as last learned
    FloatImage unchanged_;           // per pixel: learnings it has been foreground and unchanged
    int frames_ = 0;
    double noise_ = 0.0;
    double foreground_area_ = 0.0;  // sum of foreground_, px
};

}  // namespace rays
