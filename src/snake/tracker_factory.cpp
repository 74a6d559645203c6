// SPDX-License-Identifier: Apache-2.0
#include "snake/tracker_factory.hpp"

#include "core/tracker.hpp"
#include "snake/greedy_snake_tracker.hpp"

namespace rays {

std::unique_ptr<ContourTracker> make_tracker(const TrackerConfig& config, const Clock& clock) {
    switch (config.method) {
        case TrackerMethod::Snake: return std::make_unique<GreedySnakeTracker>(config, clock);
        case TrackerMethod::Rays: break;
    }
    return std::make_unique<Tracker>(config, clock);
}

}  // namespace rays
