// SPDX-License-Identifier: Apache-2.0
// The one place that picks the contour tracker for track.method: active rays or the greedy snake.
#pragma once
#include <memory>

#include "core/clock.hpp"
#include "core/contour_tracker.hpp"
#include "core/tracker_config.hpp"

namespace rays {

// A rays::Tracker for TrackerMethod::Rays, a GreedySnakeTracker for TrackerMethod::Snake, both
// sized from config.capacity. Allocates: call at start, not per frame.
std::unique_ptr<ContourTracker> make_tracker(const TrackerConfig& config, const Clock& clock);

}  // namespace rays
