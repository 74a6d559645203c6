// SPDX-License-Identifier: Apache-2.0
// The simulated camera's scripted content as functions of time t (seconds): targets moving on
// paths, fixed occluders in front of them, sensor noise and the camera's exposure. Named
// scenarios come from make_scenario; a test or tool may also assemble its own.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sim/paths.hpp"
#include "sim/target_shape.hpp"

namespace rays::sim {

// When a target is there: within [from_s, until_s) of every period_s; always when period_s is 0.
struct Presence {
    double period_s = 0;
    double from_s = 0;
    double until_s = 0;
    bool at(double t_s) const;
};

struct Target {
    TargetShape shape;
    double grey = 60;                // mean grey level, before exposure
    double texture_amplitude = 0;    // ± grey levels of value-noise texture fixed to the target
    double texture_cell_deg = 1.5;   // its coarsest detail
    std::shared_ptr<const Path> path;  // of the shape's centre
    Presence presence;
};

// A fixed bar in front of every target (a pole, a beam): a rectangle in world angles, rad.
struct Occluder {
    double azimuth_lo = 0, azimuth_hi = 0;
    double elevation_lo = 0, elevation_hi = 0;
    double grey = 60;  // before exposure
};

// The camera's global gain: a slow sinusoidal drift times a square wave of steps,
//   gain(t) = (1 + drift·sin(2π·t/drift_period_s)) · (step_factor if t mod step_period_s falls in
//             the second half of the period, else 1).
struct Exposure {
    double drift = 0;
    double drift_period_s = 60;
    double step_factor = 1;
    double step_period_s = 0;  // 0: no steps
    double gain(double t_s) const;
};

struct Scenario {
    std::string name;
    std::uint64_t seed = 0;           // of the world (Panorama::generate), the textures and the noise
    std::vector<Target> targets;      // drawn in order: a later target passes in front of an earlier one
    std::size_t primary = 0;          // the target the ground truth (SimTruth) describes
    std::vector<Occluder> occluders;  // in front of every target
    double noise_sigma = 0;           // grey levels, Gaussian, independent per pixel and frame
    Exposure exposure;
    double initial_pan_rad = 0;   // the unit pointing at the primary target at t = 0
    double initial_tilt_rad = 0;
};

// patrol, soak, soak-clutter, ramp, crowd, horizon (described in scenario_catalog.cpp); nullopt for another name.
std::optional<Scenario> make_scenario(std::string_view name, std::uint64_t seed);
std::span<const std::string_view> scenario_names();

}  // namespace rays::sim
