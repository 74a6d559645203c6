// SPDX-License-Identifier: Apache-2.0
// The predictive controller: a Kalman filter (target_filter.hpp) follows the target's direction and
// angular rate in world coordinates, so the rig's own motion is removed; the command is the target's
// rate (velocity feed-forward) plus a proportional correction of the error between where the target
// and the unit will be `lead_s` from now. A deadband stops the axes outright when the error is small
// and the target itself is still. It also predicts the target's pixel in the next frame for the tracker.
#pragma once
#include "control/controller.hpp"
#include "control/target_filter.hpp"

namespace rays::control {

class PredictiveController final : public Controller {
public:
    PredictiveController(const CameraModel& camera, const ControllerSettings& settings,
                         const TargetFilterSettings& filter)
        : camera_(camera), settings_(settings), filter_(filter) {}

    const char* law() const override { return "predictive"; }
    // A sighting of lower confidence counts with a proportionally larger measurement noise.
    void sighted(Point pixel, const UnitPose& unit, double confidence = 1.0) override;
    void lost() override { filter_.reset(); }
    bool has_target() const override { return filter_.started(); }
    // Within the filter's gate once it has settled (a few sightings after a start).
    bool consistent(Point pixel, const UnitPose& unit) const override;
    ptu::PtuCommand command(const UnitPose& unit) const override;
    std::optional<Point> expected_pixel(const UnitPose& unit) const override;
    // Once the filter has settled (kSettledSightings folded in since its start).
    bool can_coast() const override;

    const TargetFilter& filter() const { return filter_; }

private:
    CameraModel camera_;
    ControllerSettings settings_;
    TargetFilter filter_;
};

}  // namespace rays::control
