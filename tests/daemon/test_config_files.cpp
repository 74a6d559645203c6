// SPDX-License-Identifier: Apache-2.0
// The two shipped config files: config/raysd.ini documents every key (generated from the parameter
// table, and kept in step by this test), config/demo.ini runs without hardware as any user.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "config/config_engine.hpp"
#include "daemon/daemon_params.hpp"

namespace {

using namespace rays::daemon;

std::string read(const std::string& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

const std::string kConfigDir = std::string(RAYS_SOURCE_DIR) + "/config/";

}  // namespace

TEST_CASE("config/raysd.ini documents every key with unit, range and default, as the code has them") {
    DaemonConfig config;
    REQUIRE_FALSE(load_daemon_config(kConfigDir + "raysd.ini", config));
    std::string text = read(kConfigDir + "raysd.ini");
    std::string generated = rays::config::sample_ini(daemon_params(), rig_template());
    INFO("regenerate the file's body with: raysd --sample-config");
    CHECK(text.size() > generated.size());
    CHECK(text.compare(text.size() - generated.size(), generated.size(), generated) == 0);
    for (const auto& param : daemon_params().params()) {
        std::string line(1, '\n');  // built piece by piece: g++ 12's false -Wrestrict (GCC bug 105329)
        line += param.info.key();
        line += " = ";
        CHECK(text.find(line) != std::string::npos);
    }
    CHECK(config.camera.source == "v4l2");  // a real install never falls back to a simulation
    CHECK(config.ptu.driver == "modbus");
    CHECK(config.socket.path == "/run/raysd/raysd.sock");
}

TEST_CASE("config/demo.ini is the embedded default (simulated camera, mock unit) with a socket in the working directory") {
    DaemonConfig config;
    REQUIRE_FALSE(load_daemon_config(kConfigDir + "demo.ini", config));
    CHECK(config.camera.source == "sim");
    CHECK(config.sim.scenario == "soak");
    CHECK(config.ptu.driver == "mock");
    CHECK(config.socket.path.front() != '/');
}
