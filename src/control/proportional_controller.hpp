// SPDX-License-Identifier: Apache-2.0
// The paper's controller (§4): axis velocities proportional to the target's angular offset from the
// optical axis in the last frame, zero within the deadband. No prediction: the baseline.
#pragma once
#include "control/controller.hpp"

namespace rays::control {

class ProportionalController final : public Controller {
public:
    ProportionalController(const CameraModel& camera, const ControllerSettings& settings)
        : camera_(camera), settings_(settings) {}

    const char* law() const override { return "proportional"; }
    void sighted(Point pixel, const UnitPose& unit, double confidence = 1.0) override;
    void lost() override { has_target_ = false; }
    bool has_target() const override { return has_target_; }
    bool consistent(Point, const UnitPose&) const override { return true; }
    ptu::PtuCommand command(const UnitPose& unit) const override;
    std::optional<Point> expected_pixel(const UnitPose&) const override { return std::nullopt; }
    bool can_coast() const override { return false; }

private:
    CameraModel camera_;
    ControllerSettings settings_;
    bool has_target_ = false;
    double pan_error_ = 0, tilt_error_ = 0;  // target angles − unit angles in the last frame
};

}  // namespace rays::control
