// SPDX-License-Identifier: Apache-2.0
// What a benchmark run works on: the tracker configuration and the scene's frames, rendered up front
// so that rendering never enters a timing.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "core/image.hpp"
#include "core/tracker_config.hpp"

namespace rays::bench {

struct BenchSetup {
    TrackerConfig config;
    std::string config_source;  // the INI file read, or "built-in defaults"
    std::string scene;
    std::vector<GreyImage> images;
    std::vector<GreyImage> masks;  // the target's visible pixels, for the contour IoU
    Point start;                   // the target's centre in frame 0, given to the tracker as its start point
};

// Loads the configuration, applies --hypotheses and renders the frames; a bad argument gives a message.
std::optional<std::string> make_setup(const BenchOptions& options, BenchSetup& out);

// `config` with rays.count = `rays` (rays.centroid_rays capped to it).
TrackerConfig with_ray_count(const TrackerConfig& config, int rays);

}  // namespace rays::bench
