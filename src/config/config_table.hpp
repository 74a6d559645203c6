// SPDX-License-Identifier: Apache-2.0
// The parameter table of the tracking core: every field of rays::TrackerConfig.
#pragma once
#include "config/param_table.hpp"
#include "core/tracker_config.hpp"

namespace rays::config {

// Built once, on first use.
const ParamTable<TrackerConfig>& tracker_params();

// Samples along one ray: floor((lambda_max_px - lambda_min_px) / step_px) + 1.
int samples_per_ray(double lambda_min_px, double lambda_max_px, double step_px);

}  // namespace rays::config
