// SPDX-License-Identifier: Apache-2.0
// One axis's homing sequence, without I/O: seek the home switch at the homing speed, stop on it,
// move off until it releases, move on by the back-off distance, then the position there becomes the
// home offset. Fails on the opposite switch or after the timeout.
#pragma once
#include "core/clock.hpp"
#include "drivers/gpio/step_axis.hpp"

namespace rays::gpio {

class Homing {
public:
    enum class Phase { Idle, Seek, Release, Backoff };

    struct Step {
        AxisGoal goal;
        bool finished = false;          // the axis is at its home position now: set the offset
        const char* failure = nullptr;  // homing failed: why
    };

    Homing(const AxisKinematics& kinematics, int home_side, double timeout_s);

    void start(TimePoint now);
    void cancel() { phase_ = Phase::Idle; }
    bool running() const { return phase_ != Phase::Idle; }

    // Advances the sequence with the switches as read now; the axis follows the returned goal.
    Step update(bool home_switch, bool opposite_switch, const StepAxis& axis, TimePoint now);

private:
    AxisKinematics kinematics_;
    int side_;
    TimePoint::duration timeout_;
    Phase phase_ = Phase::Idle;
    TimePoint started_{};
    long backoff_target_ = 0;
};

}  // namespace rays::gpio
