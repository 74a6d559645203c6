// SPDX-License-Identifier: Apache-2.0
// The JSON Lines rays-replay writes: a header describing the mapping and settings, then a record per frame.
#pragma once
#include <cstdio>

#include "core/tracker.hpp"
#include "io/area_scaler.hpp"

namespace rays::replay {

void write_header(std::FILE* out, int source_w, int source_h, const io::AreaScaler& scaler,
                  const TrackerConfig& config, long budget_us);

// One frame: state, ref and contour in processing pixels (empty while not tracking), rays, levels,
// whether the deadline cut refinement short, why the track was lost on the frame it was, and the
// tracker's own time for the frame.
void write_frame(std::FILE* out, const Tracker& tracker, double time_us, bool crossings);

}  // namespace rays::replay
