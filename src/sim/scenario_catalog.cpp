// SPDX-License-Identifier: Apache-2.0
// The named scenarios. Angles here are in degrees (converted once, by deg()); what the seed changes
// is the world, the textures and the noise, never a path, so a scenario's guarantees (bounds,
// visibility, speeds — see tests/sim) hold for every seed.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "common/angles.hpp"
#include "sim/scenario.hpp"

namespace rays::sim {
namespace {

constexpr double deg(double degrees) { return degrees * kRadPerDeg; }

control::WorldAngles angles_deg(double azimuth, double elevation) { return {deg(azimuth), deg(elevation)}; }

Occluder bar_deg(double azimuth_lo, double azimuth_hi, double elevation_lo, double elevation_hi, double grey) {
    return {deg(azimuth_lo), deg(azimuth_hi), deg(elevation_lo), deg(elevation_hi), grey};
}

// Keyframes of a walk with stops: each leg starts from a standstill, speeds up evenly over
// kSpeedUp_s to its speed, cruises, and slows down evenly to a stop at its end.
class WalkPlan {
public:
    WalkPlan(double azimuth, double elevation) { keyframes_.push_back({0.0, angles_deg(azimuth, elevation), 0, 0}); }

    WalkPlan& pause(double seconds) {
        Keyframe k = keyframes_.back();
        k.t_s += seconds;
        keyframes_.push_back(k);
        return *this;
    }

    WalkPlan& walk_to(double azimuth, double elevation, double speed_deg_s) {
        const Keyframe from = keyframes_.back();
        const control::WorldAngles to = angles_deg(azimuth, elevation);
        const double d_az = to.azimuth - from.position.azimuth, d_el = to.elevation - from.position.elevation;
        const double length = std::hypot(d_az, d_el), speed = deg(speed_deg_s);
        const double speed_up = std::min(kSpeedUp_s, length / speed), cruise = (length - speed * speed_up) / speed;
        const double az_rate = speed * d_az / length, el_rate = speed * d_el / length;
        const auto moving = [&](double t, double travelled) {
            return Keyframe{t, {from.position.azimuth + travelled * d_az / length,
                                from.position.elevation + travelled * d_el / length}, az_rate, el_rate};
        };
        keyframes_.push_back(moving(from.t_s + speed_up, speed * speed_up / 2));
        if (cruise > 0) keyframes_.push_back(moving(from.t_s + speed_up + cruise, length - speed * speed_up / 2));
        keyframes_.push_back({from.t_s + 2 * speed_up + cruise, to, 0, 0});
        return *this;
    }

    std::shared_ptr<const Path> path() const { return std::make_shared<KeyframePath>(keyframes_); }

private:
    static constexpr double kSpeedUp_s = 1.0;
    std::vector<Keyframe> keyframes_;
};

Wave wave_deg(double amplitude, double period_s, double phase) { return steady_wave(deg(amplitude), period_s, phase); }

std::shared_ptr<const Path> waves_deg(double azimuth, double elevation, std::vector<Wave> along_azimuth,
                                      std::vector<Wave> along_elevation) {
    return std::make_shared<WavePath>(angles_deg(azimuth, elevation), std::move(along_azimuth), std::move(along_elevation));
}

// The daemon's demo: a dark walker patrolling across ±40° of azimuth at 7–15 deg/s with pauses
// (a 34 s round), and now and then (15–32 s of every 45 s) a small bright textured disc drifting
// around azimuth 70°, elevation 12°. Mild noise; the exposure drifts by ±12 % over 50 s.
Scenario patrol() {
    Scenario s;
    const auto walk = WalkPlan(-40, -1)
                          .walk_to(40, -1, 12)
                          .pause(3)
                          .walk_to(-5, 0, 7)
                          .pause(1.5)
                          .walk_to(20, -2, 15)
                          .pause(2)
                          .walk_to(-40, -1, 9)
                          .pause(2)
                          .path();
    s.targets.push_back({WalkerShape{16}, 35, 8, 1.0, walk, {}});
    s.targets.push_back({DiscShape{6}, 200, 40, 1.2, waves_deg(70, 12, {wave_deg(8, 23, 0)}, {wave_deg(4, 17, 1)}),
                         Presence{45, 15, 32}});
    s.noise_sigma = 2.5;
    s.exposure = {0.12, 50, 1, 0};
    return s;
}

// The 30-minute soaks: a textured ellipse 7° wide and 9° tall on sums of sines with incommensurate
// periods (131, 31, 6.1 s in azimuth; 79, 14.3, 3.7 s in elevation), so the path does not repeat
// within the soak: azimuth within ±91°, speed mostly 2–17 deg/s (under 2 around the turns: about 4 %
// of the time through the buildings, 11 % against the sky, where the elevation swings are smaller),
// changing direction and speed smoothly. Four poles 1.3° wide from the ground up
// to +45° at azimuths −62, −18, 27 and 71°, and a beam 0.8° high across azimuths −52…−28°, each hiding
// at most a quarter of the target as it passes behind; they are far enough apart that two never hide
// it at once. Noise σ 4; the exposure drifts by ±15 % over 97 s and steps to ×0.75 for the second
// half of every 240 s.
//   soak: above the rooftops, against the sky (elevation 24.5…39.5°, the beam at 32°): what stays
//         hard is the poles, the speed changes, the noise and the exposure.
//   soak-clutter: through the buildings and the ground (elevation −8…+28°, the beam at 8°), where the
//         target often passes in front of things of its own grey.
Scenario soak_at(double elevation, double elevation_scale, double beam_elevation) {
    Scenario s;
    const double k = elevation_scale;
    const auto path = waves_deg(0, elevation, {wave_deg(60, 131, 0.3), wave_deg(22, 31, 1.1), wave_deg(9, 6.1, 2.0)},
                                {wave_deg(10 * k, 79, 0.7), wave_deg(5 * k, 14.3, 2.2), wave_deg(3 * k, 3.7, 0.4)});
    s.targets.push_back({EllipseShape{7, 9}, 65, 30, 1.5, path, {}});
    for (const auto& [azimuth, grey] : {std::pair{-62.0, 45.0}, {-18.0, 150.0}, {27.0, 80.0}, {71.0, 200.0}})
        s.occluders.push_back(bar_deg(azimuth - 0.65, azimuth + 0.65, -60, 45, grey));
    s.occluders.push_back(bar_deg(-52, -28, beam_elevation - 0.4, beam_elevation + 0.4, 60));
    s.noise_sigma = 4;
    s.exposure = {0.15, 97, 0.75, 240};
    return s;
}

Scenario soak() { return soak_at(32, 0.4, 32); }
Scenario soak_clutter() { return soak_at(10, 1.0, 8); }

// Speed ramp: a textured disc 8° across swinging in azimuth as 80°·sin φ(t) — wider than the field of
// view, so a camera that cannot keep up loses it — the rate of φ rising linearly from 1/16 rad/s at
// t = 0 to 5 rad/s at t = 160 s and staying there (Wave's chirp), so the peak speed of each swing,
// 80°·φ'(t), grows from 5 deg/s to 400 deg/s over 160 s:
//   peak azimuth rate(t) = 5 + 395·min(t, 160)/160 deg/s (angular speed: cos 12° = 0.978 times that).
// The elevation sways as 2°·cos(t/2 s⁻¹) around −12° (the ground, below the buildings: the ramp
// measures speed, not clutter), adding at most 1 deg/s. No occluders, mild noise, fixed exposure.
Scenario ramp() {
    Scenario s;
    const Wave sweep{deg(80), 1.0 / 16.0, 5.0, 160.0, 0.0};
    const auto path = waves_deg(0, -12, {sweep}, {wave_deg(2, 4 * std::numbers::pi, std::numbers::pi / 2)});
    s.targets.push_back({DiscShape{8}, 55, 25, 1.5, path, {}});
    s.noise_sigma = 2;
    return s;
}

// Three targets at once, crossing in front of each other: a dark walker patrolling azimuths
// −30…+10° (the primary), a bright textured ellipse and a spinning grey star on sums of sines.
Scenario crowd() {
    Scenario s;
    const auto walk = WalkPlan(-30, -2).walk_to(10, -2, 8).pause(2).walk_to(-30, -2, 10).pause(1).path();
    s.targets.push_back({WalkerShape{14}, 40, 8, 1.0, walk, {}});
    s.targets.push_back({EllipseShape{7, 5}, 190, 35, 1.2,
                         waves_deg(-5, 6, {wave_deg(25, 29, 0), wave_deg(6, 7.3, 1)}, {wave_deg(6, 19, 0)}), {}});
    s.targets.push_back({StarShape{8, 4, 5, 20}, 90, 20, 1.5,
                         waves_deg(15, 2, {wave_deg(20, 37, 2)}, {wave_deg(8, 13, 0.5)}), {}});
    s.noise_sigma = 3;
    s.exposure = {0.1, 45, 1, 0};
    return s;
}

// A textured walker 16° tall (grey 70 ± 30 of texture) walking up and down across the horizon
// (−1…+4°, sky above, textured ground below, buildings standing on it) between azimuths −50 and +45°
// at 6–10 deg/s with pauses (a 40 s round), its centre from −8° to +6° of elevation, so that the
// horizon line runs across its body, then its legs; three poles 1.3° wide in front at azimuths −25,
// 5 and 30°. The failure it is for: a contour that slides onto the horizon's long straight edge and
// tilts the unit to the sky. Noise σ 3; the exposure drifts by ±10 % over 60 s.
Scenario horizon() {
    Scenario s;
    const auto walk = WalkPlan(-50, -8)
                          .walk_to(-10, 6, 8)
                          .pause(2)
                          .walk_to(45, -4, 10)
                          .pause(1.5)
                          .walk_to(10, 4, 6)
                          .pause(1)
                          .walk_to(-50, -8, 9)
                          .pause(1)
                          .path();
    s.targets.push_back({WalkerShape{16}, 70, 30, 1.0, walk, {}});
    for (const auto& [azimuth, grey] : {std::pair{-25.0, 50.0}, {5.0, 140.0}, {30.0, 85.0}})
        s.occluders.push_back(bar_deg(azimuth - 0.65, azimuth + 0.65, -60, 45, grey));
    s.noise_sigma = 3;
    s.exposure = {0.1, 60, 1, 0};
    return s;
}

struct Entry {
    std::string_view name;
    Scenario (*make)();
};

constexpr std::array kCatalog{Entry{"patrol", patrol}, Entry{"soak", soak}, Entry{"soak-clutter", soak_clutter},
                           Entry{"ramp", ramp}, Entry{"crowd", crowd}, Entry{"horizon", horizon}};
constexpr auto kNames = [] {
    std::array<std::string_view, kCatalog.size()> names{};
    for (std::size_t i = 0; i < kCatalog.size(); ++i) names[i] = kCatalog[i].name;
    return names;
}();

}  // namespace

std::optional<Scenario> make_scenario(std::string_view name, std::uint64_t seed) {
    for (const Entry& entry : kCatalog) {
        if (entry.name != name) continue;
        Scenario s = entry.make();
        s.name = std::string(name);
        s.seed = seed;
        const control::WorldAngles start = s.targets[s.primary].path->at(0.0).position;
        s.initial_pan_rad = start.azimuth;
        s.initial_tilt_rad = start.elevation;
        return s;
    }
    return std::nullopt;
}

std::span<const std::string_view> scenario_names() { return kNames; }

}  // namespace rays::sim
