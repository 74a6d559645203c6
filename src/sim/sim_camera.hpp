// SPDX-License-Identifier: Apache-2.0
// The simulated pan/tilt camera: renders the 128×128 grey view of a scenario's world and targets
// for given unit angles at time t, with the primary target's visible mask and ground truth, so the
// daemon's control loop closes through it as on a real rig. Deterministic: the same (t, pan, tilt)
// always gives the same view. render() allocates nothing, throws nothing and, being const, may run
// on several threads at once.
#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "control/camera_model.hpp"
#include "core/image.hpp"
#include "sim/panorama.hpp"
#include "sim/scenario.hpp"

namespace rays::sim {

// About the scenario's primary target in one view. Pixels: the processing frame's, centres at
// integers; NaN where a position does not exist.
struct SimTruth {
    bool in_view = false;          // some of it is visible: the mask is not empty
    control::WorldAngles target;   // its centre, azimuth wrapped into (−π, π]
    Point centre_px;               // the centre's projection, may lie outside 0…127; NaN when behind the camera
    Point mask_centroid_px;        // NaN when the mask is empty
    double visible_px = 0;         // its visible area in the frame, px (anti-aliased coverage)
    double visible_fraction = 0;   // visible ÷ the area it would cover in the frame with nothing in front
                                   // of it (occluders, later targets); 0 when it would cover none
    double speed_deg_s = 0;        // true angular speed of its centre
    double speed_px_per_s = 0;     // speed of the centre's projection with the unit held still at
                                   // (pan, tilt); NaN when behind the camera
};

struct SimView {
    GreyImage image;
    GreyImage mask;  // 255 where the primary target is visible (coverage ≥ ½), else 0
    SimTruth truth;
};

class SimCamera {
public:
    static constexpr std::size_t kMaxTargets = 8;
    static constexpr std::size_t kMaxOccluders = 32;

    // Throws std::invalid_argument when the scenario has no targets or more than kMaxTargets, more
    // than kMaxOccluders occluders, a target without a path, or a primary index out of range.
    SimCamera(Scenario scenario, const control::CameraModel& camera, Panorama panorama);

    // The view at time t_s (seconds, ≥ 0) with the unit at (pan_rad, tilt_rad).
    void render(double t_s, double pan_rad, double tilt_rad, SimView& out) const;

    const Scenario& scenario() const { return scenario_; }
    const control::CameraModel& camera() const { return camera_; }

private:
    // An occluder's bar as planes and bounds that a viewing direction is tested against.
    struct OccluderGeometry {
        Eigen::Vector3d low_side;   // normal of the meridian plane at azimuth_lo, pointing into the bar
        Eigen::Vector3d high_side;  // same at azimuth_hi
        Eigen::Vector3d facing;     // horizontal, toward the bar's middle azimuth
        double elevation_lo, elevation_hi, sin_lo, sin_hi;
        double grey;
    };

    double occluder_coverage(const OccluderGeometry& bar, const Eigen::Vector3d& ray, double norm, double elevation,
                             const Eigen::Vector3d& step_x, const Eigen::Vector3d& step_y) const;
    bool occluder_in_view(const Occluder& occluder, const Eigen::Vector3d& axis) const;

    Scenario scenario_;
    control::CameraModel camera_;
    Panorama panorama_;
    std::vector<Eigen::Vector3d> rays_;  // per pixel, camera frame, scaled to z = 1
    std::vector<OccluderGeometry> occluders_;
    double pixel_reach_rad_;  // an angle that holds any pixel's footprint around its centre ray
    double view_reach_rad_;   // the angle between the optical axis and the frame's farthest corner
};

}  // namespace rays::sim
