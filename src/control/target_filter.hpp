// SPDX-License-Identifier: Apache-2.0
// A Kalman filter on the target's direction in world angles: per axis (azimuth, elevation) the state
// is angle and angular rate under a constant-velocity model with white-noise acceleration, or angle,
// rate and angular acceleration under a constant-acceleration model with white-noise jerk (for targets
// that swing and turn hard, seen through a camera with latency, where extrapolating the rate alone
// overshoots every turn); each
// sighting measures the angles (the contour's centre through the camera model at the unit's pose
// at capture time), so the rig's own motion is already removed. Azimuth innovations are wrapped.
// Fixed-size Eigen matrices: no allocation.
#pragma once
#include <Eigen/Core>

#include "control/camera_model.hpp"

namespace rays::control {

enum class TargetMotion { ConstantVelocity, ConstantAcceleration };

struct TargetFilterSettings {
    TargetMotion motion = TargetMotion::ConstantVelocity;
    double accel_rad_s2 = 1.0;          // constant velocity: how hard targets accelerate (process noise, 1 σ)
    double jerk_rad_s3 = 30.0;          // constant acceleration: how fast their acceleration changes (1 σ)
    double measurement_rad = 0.004;     // 1 σ of a sighting's angles
    double gate_sigma = 6.0;            // a sighting further than this from the prediction restarts the filter
};

struct TargetEstimate {
    WorldAngles angles;        // at the requested time
    double azimuth_rate = 0;   // rad/s
    double elevation_rate = 0;
};

class TargetFilter {
public:
    explicit TargetFilter(const TargetFilterSettings& settings = {}) : settings_(settings) {}
    void set_settings(const TargetFilterSettings& settings) { settings_ = settings; }
    const TargetFilterSettings& settings() const { return settings_; }

    // Folds in a sighting made at t_s (seconds on the loop's clock). The first sighting after reset()
    // (or one outside the gate) starts the filter there, at rest with a wide rate uncertainty.
    // Returns false when the sighting restarted the filter.
    // `noise_scale` (≥ 1) multiplies the sighting's 1 σ, for a sighting known to be less exact.
    bool update(WorldAngles measured, double t_s, double noise_scale = 1.0);
    void reset() { started_ = false; }

    bool started() const { return started_; }
    int updates() const { return updates_; }  // sightings folded in since the (re)start
    // Squared Mahalanobis distance of a sighting at t_s from the filter's prediction for then.
    double distance2(WorldAngles measured, double t_s) const;
    double last_update_s() const { return time_s_; }
    // The state extrapolated to t_s (no update), by the motion model, from the last sighting.
    TargetEstimate at(double t_s) const;
    // 1 σ of the angle estimate per axis, as the filter sees it now.
    double angle_sigma(int axis) const;

private:
    // azimuth, elevation, their rates, their accelerations (held at 0 under constant velocity)
    using Vector = Eigen::Matrix<double, 6, 1>;
    using Matrix = Eigen::Matrix<double, 6, 6>;

    void start(WorldAngles measured, double t_s);
    // x and P predicted to t_s: x ← F x, P ← F P Fᵀ + Q (discrete white-noise acceleration or jerk).
    void predict(double t_s, Vector& x, Matrix& p) const;
    // The innovation of a sighting against the predicted x, P (H = [I 0], azimuth wrapped) and its
    // covariance S = H P Hᵀ + R, the sighting's 1 σ scaled by `noise_scale`.
    void innovate(WorldAngles measured, const Vector& x, const Matrix& p, double noise_scale,
                  Eigen::Vector2d& innovation, Eigen::Matrix2d& s) const;

    TargetFilterSettings settings_;
    bool started_ = false;
    int updates_ = 0;
    double time_s_ = 0;
    Vector x_ = Vector::Zero();
    Matrix p_ = Matrix::Identity();
};

}  // namespace rays::control
