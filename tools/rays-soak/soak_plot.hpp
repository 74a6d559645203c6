// SPDX-License-Identifier: Apache-2.0
// An optional picture of a run for a person: three panels over time — pan with the target's
// azimuth, tilt with its elevation, and the pointing error — written as an RGB PNG; and the
// records behind it as CSV.
#pragma once
#include <string>
#include <vector>

#include "soak_metrics.hpp"

namespace rays::soak {

bool write_plot(const std::string& path, const std::vector<SoakFrame>& frames, std::string& error);

// Every frame's record as CSV, for a closer look at a run.
bool write_trace(const std::string& path, const std::vector<SoakFrame>& frames, std::string& error);

}  // namespace rays::soak
