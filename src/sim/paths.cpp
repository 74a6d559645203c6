// SPDX-License-Identifier: Apache-2.0
#include "sim/paths.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace rays::sim {

double angular_speed(const PathPoint& point) {
    return std::hypot(std::cos(point.position.elevation) * point.azimuth_rate, point.elevation_rate);
}

KeyframePath::KeyframePath(std::vector<Keyframe> keyframes) : keyframes_(std::move(keyframes)) {
    assert(keyframes_.size() >= 2 && keyframes_.front().t_s == 0);
    assert(std::adjacent_find(keyframes_.begin(), keyframes_.end(),
                              [](const Keyframe& a, const Keyframe& b) { return a.t_s >= b.t_s; }) == keyframes_.end());
    [[maybe_unused]] const auto same = [](double a, double b) { return std::abs(a - b) < 1e-9; };
    assert(same(keyframes_.back().position.azimuth, keyframes_.front().position.azimuth) &&
           same(keyframes_.back().position.elevation, keyframes_.front().position.elevation) &&
           same(keyframes_.back().azimuth_rate, keyframes_.front().azimuth_rate) &&
           same(keyframes_.back().elevation_rate, keyframes_.front().elevation_rate));
}

PathPoint KeyframePath::at(double t_s) const {
    const double period = period_s(), local = t_s - period * std::floor(t_s / period);
    const auto after = std::upper_bound(keyframes_.begin() + 1, keyframes_.end() - 1, local,
                                        [](double t, const Keyframe& k) { return t < k.t_s; });
    const Keyframe& k0 = *(after - 1);
    const Keyframe& k1 = *after;
    const double h = k1.t_s - k0.t_s, s = std::clamp((local - k0.t_s) / h, 0.0, 1.0);
    const double s2 = s * s, s3 = s2 * s;
    // The Hermite basis and its derivative in s.
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d01 = -6 * s2 + 6 * s, d11 = 3 * s2 - 2 * s;
    const auto position = [&](double p0, double v0, double p1, double v1) {
        return h00 * p0 + h10 * h * v0 + h01 * p1 + h11 * h * v1;
    };
    const auto rate = [&](double p0, double v0, double p1, double v1) {
        return (d00 * p0 + d01 * p1) / h + d10 * v0 + d11 * v1;
    };
    const control::WorldAngles& a = k0.position;
    const control::WorldAngles& b = k1.position;
    return {{position(a.azimuth, k0.azimuth_rate, b.azimuth, k1.azimuth_rate),
             position(a.elevation, k0.elevation_rate, b.elevation, k1.elevation_rate)},
            rate(a.azimuth, k0.azimuth_rate, b.azimuth, k1.azimuth_rate),
            rate(a.elevation, k0.elevation_rate, b.elevation, k1.elevation_rate)};
}

double Wave::phase_at(double t_s) const {
    if (ramp_s <= 0) return phase + rate_end * t_s;
    const double ramped = std::min(t_s, ramp_s);
    const double during = rate_start * ramped + 0.5 * (rate_end - rate_start) * ramped * ramped / ramp_s;
    return phase + during + rate_end * std::max(0.0, t_s - ramp_s);
}

double Wave::rate_at(double t_s) const {
    if (ramp_s <= 0 || t_s >= ramp_s) return rate_end;
    return rate_start + (rate_end - rate_start) * t_s / ramp_s;
}

Wave steady_wave(double amplitude, double period_s, double phase) {
    const double rate = 2.0 * std::numbers::pi / period_s;
    return {amplitude, rate, rate, 0.0, phase};
}

WavePath::WavePath(control::WorldAngles centre, std::vector<Wave> azimuth, std::vector<Wave> elevation)
    : centre_(centre), azimuth_(std::move(azimuth)), elevation_(std::move(elevation)) {}

PathPoint WavePath::at(double t_s) const {
    PathPoint point{centre_, 0, 0};
    for (const Wave& w : azimuth_) {
        const double phi = w.phase_at(t_s);
        point.position.azimuth += w.amplitude * std::sin(phi);
        point.azimuth_rate += w.amplitude * std::cos(phi) * w.rate_at(t_s);
    }
    for (const Wave& w : elevation_) {
        const double phi = w.phase_at(t_s);
        point.position.elevation += w.amplitude * std::sin(phi);
        point.elevation_rate += w.amplitude * std::cos(phi) * w.rate_at(t_s);
    }
    return point;
}

}  // namespace rays::sim
