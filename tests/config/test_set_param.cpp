// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include "config/tracker_config_io.hpp"

using namespace rays;
using namespace rays::config;

TEST_CASE("set_param changes a tunable and get_param reads it back", "[config][set]") {
    TrackerConfig config;
    CHECK_FALSE(set_param(config, "rays.alpha", "0.125", false));
    CHECK(config.tunables.rays.alpha == 0.125);
    CHECK_FALSE(set_param(config, "track.predict", "off", false));
    CHECK_FALSE(config.tunables.predict);
    CHECK_FALSE(set_param(config, "attention.lost_frames", "4", false));
    CHECK(config.tunables.attention.lost_frames == 4);

    std::string value;
    CHECK_FALSE(get_param(config, "rays.alpha", value));
    CHECK(value == "0.125");
    CHECK_FALSE(get_param(config, "track.predict", value));
    CHECK(value == "false");
    CHECK_FALSE(get_param(config, "rays.max_rays", value));
    CHECK(value == "720");
    CHECK(get_param(config, "rays.alhpa", value) == "unknown parameter rays.alhpa (did you mean rays.alpha?)");
    CHECK(value == "720");
}

TEST_CASE("set_param refuses capacities unless allowed", "[config][set]") {
    TrackerConfig config;
    CHECK(set_param(config, "rays.max_rays", "800", false) ==
          "rays.max_rays is a capacity, fixed at start: change it in the configuration file and restart");
    CHECK(config.capacity.max_rays == 720);
    CHECK_FALSE(set_param(config, "rays.max_rays", "800", true));
    CHECK(config.capacity.max_rays == 800);
}

TEST_CASE("set_param refuses bad values and leaves the config unchanged", "[config][set]") {
    const TrackerConfig before;
    TrackerConfig config = before;
    CHECK(set_param(config, "rays.alpha", "-1", false) == "rays.alpha = -1 is out of range [0, 10]");
    CHECK(set_param(config, "rays.step_px", "0", false) == "rays.step_px = 0 is out of range [0.05, 16] px");
    CHECK(set_param(config, "rays.count", "many", false) == "rays.count = many is not an integer");
    CHECK(set_param(config, "rays.zoom", "1", false) == "unknown parameter rays.zoom");
    // In range on its own, but beyond the capacity: the same cross-field rules as the file.
    CHECK(set_param(config, "rays.count", "1000", false) == "rays.count = 1000 must be <= rays.max_rays = 720");
    CHECK(set_param(config, "rays.max_rays", "100", true) == "rays.count = 360 must be <= rays.max_rays = 100");
    CHECK(set_param(config, "rays.step_px", "0.1", false)->find("581 samples per ray") != std::string::npos);
    CHECK(set_param(config, "detect.threshold", "200", false) ==
          "detect.threshold = 200 must be <= detect.threshold_max = 120");
    CHECK(to_json(config) == to_json(before));
}
