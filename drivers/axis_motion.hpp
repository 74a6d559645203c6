// SPDX-License-Identifier: Apache-2.0
// How one axis moves next under a command: the phase of constant acceleration it is in, computed
// from its position and velocity alone. AxisDynamics strings these phases together in time.
#pragma once
#include <limits>

namespace rays::ptu {

struct MotionPhase {
    double accel = 0.0;                                         // rad/s², held for the whole phase
    double duration = std::numeric_limits<double>::infinity();  // s; infinite while holding
    double end_velocity = 0.0;                                  // rad/s when the phase completes
    bool ends_on_target = false;                                // a position move lands exactly here
};

// Velocity mode: ramp at max_accel to target_velocity (already within ±max_velocity), then hold it.
MotionPhase velocity_phase(double velocity, double target_velocity, double max_accel);

// Position mode: the time-optimal trapezoidal move to target under max_velocity and max_accel. The
// last phase brakes onto the target exactly; an axis too fast to stop in time brakes at max_accel,
// passes the target and comes back, once.
MotionPhase position_phase(double position, double velocity, double target, double max_velocity,
                           double max_accel);

}  // namespace rays::ptu
