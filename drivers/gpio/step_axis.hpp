// One stepper axis's step schedule, without I/O: what the next edge is (set DIR, or a STEP) and when,
// from the goal the pulse thread gives it. Time comes in as arguments, so tests can drive it.
//
// Kinematics per step: the speed at each step w_k is chosen so that |w_{k+1}² − w_k²| ≤ 2·accel (the
// exact constant-acceleration relation over one step) and the interval between steps k and k+1 is
// 2 / (w_k + w_{k+1}); so the average rate over an interval never exceeds the larger of the two
// speeds, and measured accelerations from edge intervals are at most `accel`. A move from rest
// steps at once (w_0 = 0), so a new command shows on the lines without waiting out a first interval.
// Direction changes only at rest; the first step after one waits dir_setup. Steps are scheduled on
// an ideal timeline so wake-up jitter does not slow the motion, but never closer than 1/max_step_rate
// to the previous step's actual edge; an axis more than kMaxLag behind its timeline is re-based.
#pragma once
#include <chrono>

#include "core/clock.hpp"
#include "drivers/gpio/stepper_config.hpp"

namespace rays::gpio {

struct AxisGoal {
    enum class Kind { Stop, Halt, Velocity, Position };
    Kind kind = Kind::Stop;  // Stop: ramp to rest; Halt: rest now (no further step)
    double velocity = 0.0;   // steps/s, Velocity
    long target = 0;         // steps, Position
    double max_speed = 0.0;  // steps/s, cruise speed of a Position move and cap of a Velocity one

    static AxisGoal stop() { return {}; }
    static AxisGoal halt() { return {Kind::Halt, 0.0, 0, 0.0}; }
};

// The speed at the next step for a wanted speed along the travel (≥ 0), one step's worth of ramp.
double speed_toward(double speed, double wanted, double accel);
// The speed at the next step of a move with `remaining` steps to go after this one (≤ 0: passed).
double speed_to_target(double speed, long remaining, double max_speed, double accel);

class StepAxis {
public:
    enum class Action { None, SetDir, Step };
    static constexpr std::chrono::milliseconds kMaxLag{2};

    StepAxis(const AxisKinematics& kinematics, double max_step_rate_hz, double dir_setup_s);

    // Decides the next edge under `goal`; call after every edge and whenever the goal may change.
    void plan(const AxisGoal& goal, TimePoint now);
    Action action() const { return action_; }
    TimePoint due() const { return due_; }  // when the action is due (TimePoint::max() for None)
    int wanted_direction() const { return wanted_direction_; }  // SetDir: +1 (DIR high) or −1

    void dir_set(int direction, TimePoint at);  // the DIR edge happened at `at`
    void stepped(TimePoint at);                 // the STEP rising edge happened at `at`
    void halt();                                // at rest now
    void set_position(long steps) { position_ = steps; }

    long position() const { return position_; }
    double velocity() const;  // steps/s, signed
    bool at_rest() const { return !moving_; }
    long rebases() const { return rebases_; }

private:
    double next_speed(const AxisGoal& goal) const;
    int start_direction(const AxisGoal& goal) const;

    AxisKinematics kinematics_;
    TimePoint::duration min_interval_;
    TimePoint::duration dir_setup_;
    TimePoint::duration start_interval_;  // from rest, one step under accel: √(2/accel)
    long position_ = 0;
    int direction_ = -1;  // of the DIR line; it starts low
    bool moving_ = false;
    int travel_ = 0;
    double speed_ = 0.0;       // at the last step
    double next_speed_ = 0.0;  // at the next step
    TimePoint ideal_last_{};
    TimePoint ideal_next_{};
    TimePoint actual_last_{};
    bool stepped_before_ = false;
    TimePoint dir_time_{};
    Action action_ = Action::None;
    TimePoint due_ = TimePoint::max();
    int wanted_direction_ = 0;
    long rebases_ = 0;
};

}  // namespace rays::gpio
