// SPDX-License-Identifier: Apache-2.0
// Shared by the simulated camera's tests: the demo's 60°×60° camera, named scenarios on their own
// generated world, and small hand-made scenarios.
#pragma once
#include <memory>
#include <string_view>

#include "common/angles.hpp"
#include "sim/sim_camera.hpp"

namespace rays::test {

inline constexpr double kFovDeg = 60.0;
inline constexpr std::uint64_t kSeed = 7;

inline control::CameraModel demo_camera() {
    return control::CameraModel::from_fov(kFovDeg * kRadPerDeg, kFovDeg * kRadPerDeg);
}

inline std::unique_ptr<sim::SimCamera> named_camera(std::string_view name) {
    std::optional<sim::Scenario> scenario = sim::make_scenario(name, kSeed);
    if (!scenario) return nullptr;
    return std::make_unique<sim::SimCamera>(std::move(*scenario), demo_camera(), sim::Panorama::generate(kSeed));
}

// A target that stands still at (azimuth, elevation), deg.
inline std::shared_ptr<const sim::Path> standing_at(double azimuth_deg, double elevation_deg) {
    return std::make_shared<sim::WavePath>(
        control::WorldAngles{azimuth_deg * kRadPerDeg, elevation_deg * kRadPerDeg}, std::vector<sim::Wave>{},
        std::vector<sim::Wave>{});
}

// One plain dark disc `diameter_deg` across standing at (azimuth, elevation), no noise, fixed exposure.
inline sim::Scenario still_disc(double azimuth_deg, double elevation_deg, double diameter_deg = 10) {
    sim::Scenario s;
    s.name = "still-disc";
    s.seed = kSeed;
    s.targets.push_back({sim::DiscShape{diameter_deg}, 30, 0, 1, standing_at(azimuth_deg, elevation_deg), {}});
    s.initial_pan_rad = azimuth_deg * kRadPerDeg;
    s.initial_tilt_rad = elevation_deg * kRadPerDeg;
    return s;
}

inline sim::SimCamera camera_on(sim::Scenario scenario) {
    return sim::SimCamera(std::move(scenario), demo_camera(), sim::Panorama::generate(kSeed));
}

// The angle between two world directions, deg.
inline double separation_deg(control::WorldAngles a, control::WorldAngles b) {
    const double c = control::direction_of(a).dot(control::direction_of(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * kDegPerRad;
}

}  // namespace rays::test
