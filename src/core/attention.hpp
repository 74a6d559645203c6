// SPDX-License-Identifier: Apache-2.0
// The attention module of §4.1: watches features of the contour (area, x and y moments, centroid
// speed) and declares the target lost when they change faster than the configured limits.
#pragma once
#include "core/contour.hpp"
#include "core/tracker_config.hpp"
#include "core/whole_area.hpp"

namespace rays {

struct ContourFeatures {
    double area = 0;       // zeroth moment, px²
    Point centroid;        // first moments / area
    double speed_px = 0;   // centroid displacement since the previous frame, px/frame
    double no_edge_fraction = 0;
};

class Attention {
public:
    void reset() {
        has_previous_ = false;
        whole_area_.reset();
    }

    // Returns nullptr while the contour is plausible, else the reason the target counts as lost.
    // `predicted` is where the centroid was expected this frame.
    const char* check(const Contour& contour, Point predicted, const AttentionTunables& limits);

private:
    bool has_previous_ = false;
    double area_ = 0;        // running area, so one noisy frame does not set the reference
    WholeArea whole_area_;   // a hidden part showing again is no jump
    ContourFeatures current_;
};

}  // namespace rays
