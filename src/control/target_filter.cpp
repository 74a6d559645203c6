#include "control/target_filter.hpp"

#include <Eigen/LU>
#include <cmath>

namespace rays::control {
namespace {

constexpr double kStartRateSigma = 1.0;  // rad/s: a new target may already be moving fast

}  // namespace

void TargetFilter::start(WorldAngles measured, double t_s) {
    started_ = true;
    updates_ = 0;
    time_s_ = t_s;
    x_ << measured.azimuth, measured.elevation, 0.0, 0.0;
    const double r2 = settings_.measurement_rad * settings_.measurement_rad;
    const double v2 = kStartRateSigma * kStartRateSigma;
    p_ = Matrix4::Zero();
    p_.diagonal() << r2, r2, v2, v2;
}

void TargetFilter::predict(double t_s, Vector4& x, Matrix4& p) const {
    const double dt = std::max(0.0, t_s - time_s_);
    Matrix4 f = Matrix4::Identity();
    f(0, 2) = dt;
    f(1, 3) = dt;
    const double a2 = settings_.accel_rad_s2 * settings_.accel_rad_s2;
    Matrix4 q = Matrix4::Zero();
    for (int axis = 0; axis < 2; ++axis) {
        q(axis, axis) = a2 * dt * dt * dt * dt / 4.0;
        q(axis, axis + 2) = q(axis + 2, axis) = a2 * dt * dt * dt / 2.0;
        q(axis + 2, axis + 2) = a2 * dt * dt;
    }
    x = f * x_;
    p = f * p_ * f.transpose() + q;
}

double TargetFilter::distance2(WorldAngles measured, double t_s) const {
    Vector4 x;
    Matrix4 p;
    predict(t_s, x, p);
    Eigen::Vector2d innovation(angle_difference(measured.azimuth, x(0)), measured.elevation - x(1));
    Eigen::Matrix2d s = p.topLeftCorner<2, 2>();
    s.diagonal().array() += settings_.measurement_rad * settings_.measurement_rad;
    return innovation.dot(s.inverse() * innovation);
}

bool TargetFilter::update(WorldAngles measured, double t_s, double noise_scale) {
    if (!started_) {
        start(measured, t_s);
        return false;
    }
    Vector4 x;
    Matrix4 p;
    predict(t_s, x, p);

    // Update with the measured angles: H = [I 0].
    Eigen::Vector2d innovation(angle_difference(measured.azimuth, x(0)), measured.elevation - x(1));
    Eigen::Matrix2d s = p.topLeftCorner<2, 2>();
    const double r = settings_.measurement_rad * noise_scale;
    s.diagonal().array() += r * r;
    const Eigen::Matrix2d s_inv = s.inverse();
    if (innovation.dot(s_inv * innovation) > settings_.gate_sigma * settings_.gate_sigma) {
        start(measured, t_s);  // not the target we were following, or it turned on a sixpence
        return false;
    }
    const Eigen::Matrix<double, 4, 2> gain = p.leftCols<2>() * s_inv;
    x_ = x + gain * innovation;
    x_(0) = angle_difference(x_(0), 0.0);
    p_ = p - gain * p.topRows<2>();
    time_s_ = t_s;
    ++updates_;
    return true;
}

TargetEstimate TargetFilter::at(double t_s) const {
    const double dt = t_s - time_s_;
    return {{angle_difference(x_(0) + x_(2) * dt, 0.0), x_(1) + x_(3) * dt}, x_(2), x_(3)};
}

double TargetFilter::angle_sigma(int axis) const { return std::sqrt(p_(axis, axis)); }

}  // namespace rays::control
