// SPDX-License-Identifier: Apache-2.0
#include "core/contour_tracker.hpp"

namespace rays {

const Chroma kNoChroma{};

const char* to_string(TrackState s) {
    switch (s) {
        case TrackState::Detecting: return "detecting";
        case TrackState::Tracking: return "tracking";
        case TrackState::Lost: return "lost";
    }
    return "?";
}

}  // namespace rays
