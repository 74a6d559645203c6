// SPDX-License-Identifier: Apache-2.0
// The any-time curve (§2.3, Fig. 6): contour quality against the time budget per frame.
#pragma once
#include <vector>

#include "bench_setup.hpp"

namespace rays::bench {

struct AnytimePoint {
    int budget_us = 0;
    double iou = 0;   // mean over all frames of the contour's IoU with the target mask (0 when not tracking)
    double rays = 0;  // mean contour points over the tracking frames
    int tracking = 0; // frames in the tracking state
};

// Runs a fresh tracker per budget with deadline = frame start + budget, at the configured rays.count.
std::vector<AnytimePoint> measure_anytime_curve(const BenchSetup& setup);

}  // namespace rays::bench
