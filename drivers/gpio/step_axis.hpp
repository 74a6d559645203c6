// SPDX-License-Identifier: Apache-2.0
// One stepper axis's step schedule, without I/O: what the next edge is (set DIR, or a STEP) and when,
// from the goal the pulse thread gives it. Time comes in as arguments, so tests can drive it.
//
// Kinematics per step: the speed at each step w_k is chosen so that |w_{k+1}² − w_k²| ≤ 2·accel (the
// exact constant-acceleration relation over one step) and the interval between steps k and k+1 is
// 2 / (w_k + w_{k+1}); so the average rate over an interval never exceeds the larger of the two
// speeds, and measured accelerations from edge intervals are at most `accel`. A move from rest
// steps at once (w_0 = 0), so a new command shows on the lines without waiting out a first interval.
// Direction changes only at rest; the first step after one waits dir_setup. Each step is scheduled
// from the previous step's actual edge, never closer than 1/max_step_rate, so an edge that comes late
// (the thread woke after its due time) is never caught up: the steps the plan lost are counted
// (lost_steps), not made up, and the position stays exact. Lateness up to kJitter is jitter and costs
// nothing more; beyond it the axis re-plans from the speed it really had over the interval it made
// less kJitter, Δt' = Δt − kJitter: w ≤ max(1/Δt', 2/Δt' − w_prev) (the second is the exact relation
// above). So every interval's rate r_next obeys (r_next² − r'²) / 2 ≤ kRampRise · accel against the
// rate r' = 1/Δt' of the interval before it (on time, r' is that interval's own rate; the bound is
// reached by the second interval from rest): late edges never make the following ones beat the ramp.
#pragma once
#include <chrono>
#include <cmath>

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

// Between neighbouring intervals of a ramp at `accel`, (r_next² − r²) / 2 ≤ kRampRise · accel, r = 1/Δt.
inline constexpr double kRampRise = 1.2071067811865476;  // (1 + √2) / 2

// The speed at the next step for a wanted speed along the travel (≥ 0), one step's worth of ramp.
double speed_toward(double speed, double wanted, double accel);
// The speed at the next step of a move with `remaining` steps to go after this one (≤ 0: passed).
double speed_to_target(double speed, long remaining, double max_speed, double accel);

class StepAxis {
public:
    enum class Action { None, SetDir, Step };
    // Lateness that does not re-plan the ramp: one step at kMaxStepRateHz, so the lines are never more
    // than one step behind the plan at the top rate (a sixteenth of a full step at 16 microsteps).
    static constexpr std::chrono::microseconds kJitter{1000000 / kMaxStepRateHz};
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
    long late_edges() const { return late_edges_; }  // steps more than kJitter after their due time
    long lost_steps() const { return std::lround(lost_steps_); }  // the plan's steps lateness dropped

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
    TimePoint::duration interval_{};  // planned from the last step to the next
    TimePoint last_step_{};
    bool stepped_before_ = false;
    TimePoint dir_time_{};
    Action action_ = Action::None;
    TimePoint due_ = TimePoint::max();
    int wanted_direction_ = 0;
    long late_edges_ = 0;
    double lost_steps_ = 0.0;
};

}  // namespace rays::gpio
