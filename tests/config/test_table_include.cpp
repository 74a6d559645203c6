// SPDX-License-Identifier: Apache-2.0
// How a later section ([camera], [ptu], ...) joins the file: its own table for its own struct,
// combined with the tracker's table into the table of a struct that holds both.
#include <catch2/catch.hpp>

#include "config/config_engine.hpp"
#include "config/config_table.hpp"
#include "temp_ini_file.hpp"

using namespace rays;
using namespace rays::config;
using rays::test::TempIniFile;

namespace {

struct CameraSettings {
    int exposure_us = 8000;
    bool auto_gain = false;
};

struct DaemonSettings {
    TrackerConfig tracker;
    CameraSettings camera;
};

ParamTable<CameraSettings> camera_params() {
    ParamTable<CameraSettings> table;
    table.section("camera", ParamKind::Tunable, [](CameraSettings& camera) -> auto& { return camera; })
        .add("exposure_us", &CameraSettings::exposure_us, "us", 10, 100000, "exposure time")
        .add("auto_gain", &CameraSettings::auto_gain, "let the camera choose its gain");
    return table;
}

ParamTable<DaemonSettings> daemon_params() {
    ParamTable<DaemonSettings> table;
    table.include(tracker_params(), &DaemonSettings::tracker);
    table.include(camera_params(), &DaemonSettings::camera);
    return table;
}

}  // namespace

TEST_CASE("included tables keep their parameters, defaults and rules", "[config][include]") {
    const ParamTable<DaemonSettings> table = daemon_params();
    CHECK(table.params().size() == tracker_params().params().size() + 2);
    CHECK(table.rules().size() == tracker_params().rules().size());
    CHECK(table.sections().back() == "camera");
    CHECK(std::get<int>(table.find("camera.exposure_us")->info.default_value) == 8000);

    TempIniFile file("[rays]\nalpha = 0.5\n[camera]\nexposure_us = 2500\nauto_gain = yes\n");
    DaemonSettings settings;
    REQUIRE_FALSE(load_ini(file.path(), table, settings));
    CHECK(settings.tracker.tunables.rays.alpha == 0.5);
    CHECK(settings.camera.exposure_us == 2500);
    CHECK(settings.camera.auto_gain);

    CHECK(set_param(table, settings, "rays.count", "1000", false) == "rays.count = 1000 must be <= rays.max_rays = 720");
    CHECK(set_param(table, settings, "camera.exposure_us", "5", false) ==
          "camera.exposure_us = 5 is out of range [10, 100000] us");
    CHECK_FALSE(set_param(table, settings, "camera.exposure_us", "4000", false));
    std::string value;
    CHECK_FALSE(get_param(table, settings, "camera.exposure_us", value));
    CHECK(value == "4000");
    CHECK(to_json(table, settings)["camera.auto_gain"] == true);

    TempIniFile sample(sample_ini(table, DaemonSettings{}));
    DaemonSettings reloaded = settings;
    REQUIRE_FALSE(load_ini(sample.path(), table, reloaded));
    CHECK(to_json(table, reloaded) == to_json(table, DaemonSettings{}));
}
