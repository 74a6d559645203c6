// SPDX-License-Identifier: Apache-2.0
// The pointing controllers behind one interface: the paper's proportional controller (§4) as the
// baseline, and a predictive one (predictive_controller.hpp). The frame loop tells a controller what
// each frame showed (sighted / lost) and asks it for the unit's velocity command; a controller may
// also say where the target will show in the next frame, which the tracker uses as its prediction.
// Times are seconds on the loop's monotonic clock. Nothing here allocates or throws.
#pragma once
#include <optional>

#include "control/camera_model.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::control {

// The unit's pose and motion at one moment (rig angles, rad and rad/s).
struct UnitPose {
    double t_s = 0;
    double pan = 0, tilt = 0;
    double pan_rate = 0, tilt_rate = 0;

    UnitPose at(double t) const {  // extrapolated at constant rate
        return {t, pan + pan_rate * (t - t_s), tilt + tilt_rate * (t - t_s), pan_rate, tilt_rate};
    }
    // The state a unit reported, taken at t_s.
    static UnitPose of(const ptu::PtuState& state, double t_s) {
        return {t_s, state.axes[0].position_rad, state.axes[1].position_rad, state.axes[0].velocity_rad_s,
                state.axes[1].velocity_rad_s};
    }
};

struct ControllerSettings {
    double gain_per_s = 2.0;            // velocity command per rad of angular error
    double deadband_rad = 0.0087;       // errors within this command zero velocity
    double max_velocity_rad_s = 1.57;   // commands are held within this
    double lead_s = 0.02;               // predictive: aim where target and unit will be this much later
    double still_rate_rad_s = 0.0087;   // predictive: a target slower than this may rest in the deadband
};

class Controller {
public:
    virtual ~Controller() = default;
    virtual const char* law() const = 0;

    // The target's reference point in a frame captured at `unit.t_s`, with the unit at that pose.
    // `confidence` in (0, 1]: how much of the target the contour holds (less while it is partly
    // hidden, when its centre is biased toward the visible part).
    virtual void sighted(Point pixel, const UnitPose& unit, double confidence = 1.0) = 0;
    virtual void lost() = 0;  // the target is gone: forget it
    virtual bool has_target() const = 0;
    // Whether a contour at `pixel` in a frame taken at `unit` can be the target this controller
    // follows; a controller without a model of the target's motion accepts every one.
    virtual bool consistent(Point pixel, const UnitPose& unit) const = 0;

    // The velocity command for now, with the unit as it is now.
    virtual ptu::PtuCommand command(const UnitPose& unit) const = 0;
    // Where the target's reference point will be in a frame captured with the unit at `unit`;
    // nullopt when this controller does not predict.
    virtual std::optional<Point> expected_pixel(const UnitPose& unit) const = 0;
    // Whether, with the target out of sight, the prediction is worth following (coasting): only a
    // motion estimate that has settled. One made of a few sightings after a (re)start may be a
    // contour on something that moves with the camera, whose rate is the unit's own: followed, it
    // would run the unit away.
    virtual bool can_coast() const = 0;
};

// The command with the deadband applied and each axis held within the velocity limit.
ptu::PtuCommand velocity_command(double pan_rate, double tilt_rate, const ControllerSettings& settings);

}  // namespace rays::control
