// SPDX-License-Identifier: Apache-2.0
#include "control/target_filter.hpp"

#include <Eigen/LU>
#include <cmath>

namespace rays::control {
namespace {

constexpr double kStartRateSigma = 1.0;   // rad/s: a new target may already be moving fast
constexpr double kStartAccelSigma = 3.0;  // rad/s²: ... and turning

}  // namespace

void TargetFilter::start(WorldAngles measured, double t_s) {
    started_ = true;
    updates_ = 0;
    time_s_ = t_s;
    x_ << measured.azimuth, measured.elevation, 0.0, 0.0, 0.0, 0.0;
    const double r2 = settings_.measurement_rad * settings_.measurement_rad;
    const double v2 = kStartRateSigma * kStartRateSigma;
    const double a2 = settings_.motion == TargetMotion::ConstantAcceleration ? kStartAccelSigma * kStartAccelSigma : 0.0;
    p_ = Matrix::Zero();
    p_.diagonal() << r2, r2, v2, v2, a2, a2;
}

void TargetFilter::predict(double t_s, Vector& x, Matrix& p) const {
    const double dt = std::max(0.0, t_s - time_s_);
    const bool accelerating = settings_.motion == TargetMotion::ConstantAcceleration;
    Matrix f = Matrix::Identity();
    Matrix q = Matrix::Zero();
    const double d2 = dt * dt, d3 = d2 * dt, d4 = d3 * dt;
    for (int angle = 0; angle < 2; ++angle) {
        const int rate = angle + 2, accel = angle + 4;
        f(angle, rate) = dt;
        if (accelerating) {
            f(angle, accel) = d2 / 2.0;
            f(rate, accel) = dt;
            // Discrete white-noise jerk: Γ = [dt³/6, dt²/2, dt]ᵀ, Q = Γ Γᵀ σ_j².
            const double j2 = settings_.jerk_rad_s3 * settings_.jerk_rad_s3;
            const double g[3] = {d3 / 6.0, d2 / 2.0, dt};
            const int index[3] = {angle, rate, accel};
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) q(index[r], index[c]) = j2 * g[r] * g[c];
        } else {
            // Discrete white-noise acceleration: Γ = [dt²/2, dt]ᵀ; the acceleration states stay 0.
            const double a2 = settings_.accel_rad_s2 * settings_.accel_rad_s2;
            q(angle, angle) = a2 * d4 / 4.0;
            q(angle, rate) = q(rate, angle) = a2 * d3 / 2.0;
            q(rate, rate) = a2 * d2;
        }
    }
    x = f * x_;
    p = f * p_ * f.transpose() + q;
}

void TargetFilter::innovate(WorldAngles measured, const Vector& x, const Matrix& p, double noise_scale,
                            Eigen::Vector2d& innovation, Eigen::Matrix2d& s) const {
    innovation << angle_difference(measured.azimuth, x(0)), measured.elevation - x(1);
    s = p.topLeftCorner<2, 2>();
    const double r = settings_.measurement_rad * noise_scale;
    s.diagonal().array() += r * r;
}

double TargetFilter::distance2(WorldAngles measured, double t_s) const {
    Vector x;
    Matrix p;
    predict(t_s, x, p);
    Eigen::Vector2d innovation;
    Eigen::Matrix2d s;
    innovate(measured, x, p, 1.0, innovation, s);
    return innovation.dot(s.inverse() * innovation);
}

bool TargetFilter::update(WorldAngles measured, double t_s, double noise_scale) {
    if (!started_) {
        start(measured, t_s);
        return false;
    }
    Vector x;
    Matrix p;
    predict(t_s, x, p);

    // Update with the measured angles: H = [I 0].
    Eigen::Vector2d innovation;
    Eigen::Matrix2d s;
    innovate(measured, x, p, noise_scale, innovation, s);
    const Eigen::Matrix2d s_inv = s.inverse();
    if (innovation.dot(s_inv * innovation) > settings_.gate_sigma * settings_.gate_sigma) {
        start(measured, t_s);  // not the target we were following, or it turned on a sixpence
        return false;
    }
    const Eigen::Matrix<double, 6, 2> gain = p.leftCols<2>() * s_inv;
    x_ = x + gain * innovation;
    x_(0) = angle_difference(x_(0), 0.0);
    p_ = p - gain * p.topRows<2>();
    time_s_ = t_s;
    ++updates_;
    return true;
}

TargetEstimate TargetFilter::at(double t_s) const {
    const double dt = t_s - time_s_, h = dt * dt / 2.0;
    return {{angle_difference(x_(0) + x_(2) * dt + x_(4) * h, 0.0), x_(1) + x_(3) * dt + x_(5) * h},
            x_(2) + x_(4) * dt, x_(3) + x_(5) * dt};
}

double TargetFilter::angle_sigma(int axis) const { return std::sqrt(p_(axis, axis)); }

}  // namespace rays::control
