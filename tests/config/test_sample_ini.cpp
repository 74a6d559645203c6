// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include "config/tracker_config_io.hpp"
#include "temp_ini_file.hpp"

using namespace rays;
using namespace rays::config;
using rays::test::TempIniFile;

TEST_CASE("the sample file parses back to the defaults", "[config][sample]") {
    TempIniFile file(sample_ini(TrackerConfig{}));
    TrackerConfig config;
    config.tunables.rays.alpha = 0.9;
    auto error = load_ini(file.path(), config);
    INFO((error ? error->to_string() : "no error"));
    REQUIRE_FALSE(error);
    CHECK(to_json(config) == to_json(TrackerConfig{}));
}

TEST_CASE("the sample file carries the values it is given", "[config][sample]") {
    TrackerConfig values;
    REQUIRE_FALSE(set_param(values, "rays.max_rays", "1000", true));
    REQUIRE_FALSE(set_param(values, "rays.count", "999", false));
    REQUIRE_FALSE(set_param(values, "rays.beta", "0.0123456789", false));
    REQUIRE_FALSE(set_param(values, "track.predict", "false", false));
    TempIniFile file(sample_ini(values));
    TrackerConfig config;
    REQUIRE_FALSE(load_ini(file.path(), config));
    CHECK(to_json(config) == to_json(values));
}

TEST_CASE("the sample file documents every key", "[config][sample]") {
    const std::string text = sample_ini(TrackerConfig{});
    for (const ParamInfo* info : list_params()) {
        INFO(info->name);
        std::string key_line = "\n";  // appended piece by piece: g++ 12 -Wrestrict false positive on "\n" + string
        key_line += info->key();
        key_line += " = ";
        CHECK(text.find(key_line) != std::string::npos);
    }
    CHECK(text.find("\n[rays]\n") < text.find("\n[detect]\n"));
    CHECK(text.find("; most rays per contour; sizes the ray buffers\n"
                    "; int, range [4, 4096] rays, default 720, fixed at start\n"
                    "max_rays = 720\n") != std::string::npos);
    CHECK(text.find("; real, range [0, 255] grey/px, default 2, tunable at run time\nedge_floor = 2\n") !=
          std::string::npos);
    CHECK(text.find("; bool (true/false), default true, tunable at run time\npredict = true\n") != std::string::npos);
}
