// SPDX-License-Identifier: Apache-2.0
#include "daemon/control_tunables.hpp"

#include "common/angles.hpp"

namespace rays::daemon {

ControlTunables control_tunables(const ControlSettings& c, const PtuMotion& motion) {
    ControlTunables t;
    t.predictive = c.law == "predictive";
    t.intrinsics = c.fx_px > 0
                       ? control::Intrinsics{c.fx_px, c.fy_px > 0 ? c.fy_px : c.fx_px, c.cx_px, c.cy_px}
                       : control::CameraModel::from_fov(c.horizontal_fov_deg * kRadPerDeg, c.vertical_fov_deg * kRadPerDeg)
                             .intrinsics();
    t.controller.gain_per_s = c.gain;
    t.controller.deadband_rad = c.deadband_deg * kRadPerDeg;
    t.controller.max_velocity_rad_s = motion.max_velocity_deg_s * kRadPerDeg;
    t.controller.lead_s = c.lead_ms / 1000.0;
    t.controller.still_rate_rad_s = c.still_deg_s * kRadPerDeg;
    t.filter.motion = c.target_motion == "acceleration" ? control::TargetMotion::ConstantAcceleration
                                                         : control::TargetMotion::ConstantVelocity;
    t.filter.accel_rad_s2 = c.target_accel_deg_s2 * kRadPerDeg;
    t.filter.jerk_rad_s3 = c.target_jerk_deg_s3 * kRadPerDeg;
    t.filter.measurement_rad = c.sighting_noise_px / t.intrinsics.fx;
    t.lost.action = c.lost_action == "search" ? control::LostAction::Search
                    : c.lost_action == "home" ? control::LostAction::Home
                                              : control::LostAction::Hold;
    t.lost.timeout_s = c.lost_timeout_s;
    t.lost.search_step_rad = c.search_step_deg * kRadPerDeg;
    t.lost.search_steps = c.search_steps;
    t.lost.search_dwell_s = c.search_dwell_s;
    t.lost.home_pan_rad = motion.home_pan_deg * kRadPerDeg;
    t.lost.home_tilt_rad = motion.home_tilt_deg * kRadPerDeg;
    t.still_rad_s = c.still_deg_s * kRadPerDeg;
    t.coast_s = c.coast_s;
    return t;
}

}  // namespace rays::daemon
