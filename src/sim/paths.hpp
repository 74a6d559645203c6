// SPDX-License-Identifier: Apache-2.0
// Scripted paths of the simulated targets' centres in world angles, as smooth functions of time
// (continuous velocity, so a true angular speed exists at every instant). Random access in t.
#pragma once
#include <vector>

#include "control/camera_model.hpp"

namespace rays::sim {

struct PathPoint {
    control::WorldAngles position;  // azimuth not wrapped: a path may run past ±π
    double azimuth_rate = 0;        // rad/s
    double elevation_rate = 0;      // rad/s
};

// The angular speed along the sphere, rad/s: √((cos el · az')² + el'²).
double angular_speed(const PathPoint& point);

class Path {
public:
    virtual ~Path() = default;
    virtual PathPoint at(double t_s) const = 0;  // defined for every t ≥ 0
};

// Cubic Hermite interpolation between keyframes that each fix position and velocity, so velocity is
// continuous: a keyframe with zero rates is a stop, two equal ones a pause. The path repeats: the
// last keyframe must repeat the first one's position and rates, and its time is the period.
struct Keyframe {
    double t_s = 0;                 // the first keyframe's is 0
    control::WorldAngles position;  // rad
    double azimuth_rate = 0;        // rad/s
    double elevation_rate = 0;      // rad/s
};

class KeyframePath final : public Path {
public:
    explicit KeyframePath(std::vector<Keyframe> keyframes);  // at least two, in increasing time
    PathPoint at(double t_s) const override;
    double period_s() const { return keyframes_.back().t_s; }

private:
    std::vector<Keyframe> keyframes_;
};

// One sinusoidal term a·sin(φ(t)) whose phase rate may ramp linearly from rate_start to rate_end
// over the first ramp_s seconds (a chirp) and then stays at rate_end:
//   φ(t) = phase + rate_start·t + ½·(rate_end − rate_start)·t²/ramp_s   for t ≤ ramp_s,
//   φ(t) = φ(ramp_s) + rate_end·(t − ramp_s)                            after.
// With ramp_s = 0 the rate is rate_end throughout.
struct Wave {
    double amplitude = 0;   // rad
    double rate_start = 0;  // rad/s
    double rate_end = 0;    // rad/s
    double ramp_s = 0;
    double phase = 0;  // rad, at t = 0

    double phase_at(double t_s) const;
    double rate_at(double t_s) const;
};

Wave steady_wave(double amplitude, double period_s, double phase);  // a constant-rate term

// A centre plus sums of waves along each axis: smooth, bounded by the sum of the amplitudes, and
// not periodic when the periods are incommensurate.
class WavePath final : public Path {
public:
    WavePath(control::WorldAngles centre, std::vector<Wave> azimuth, std::vector<Wave> elevation);
    PathPoint at(double t_s) const override;

private:
    control::WorldAngles centre_;
    std::vector<Wave> azimuth_, elevation_;
};

}  // namespace rays::sim
