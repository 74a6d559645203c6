// SPDX-License-Identifier: Apache-2.0
// StepAxis and Homing on virtual time (no thread, no lines): exact step counts, speeds and intervals.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "drivers/gpio/homing.hpp"
#include "drivers/gpio/step_axis.hpp"

using namespace rays;
using namespace rays::gpio;

namespace {

struct Run {
    long steps = 0;
    double max_rate = 0.0;
    double max_accel = 0.0;
    // Largest (r_next² − r'²) / 2 over consecutive intervals, r' = 1/(Δt − min(lateness, kJitter)) of the
    // first (its own rate when on time): at most kRampRise · accel (step_axis.hpp).
    double max_rise = 0.0;
};

// How late the k-th STEP edge comes after its due time; none by default.
using Lateness = std::function<TimePoint::duration(long k)>;

// Runs the axis under `goal` from `t` for `seconds`, acting on every edge when due (plus `late`).
Run simulate(StepAxis& axis, const AxisGoal& goal, TimePoint& t, double seconds, const Lateness& late = nullptr) {
    Run run;
    const TimePoint end = t + std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(seconds));
    TimePoint last{};
    double last_rate = 0.0;
    bool have_last = false;
    double last_interval = 0.0;
    TimePoint::duration last_lateness{};
    for (;;) {
        axis.plan(goal, t);
        if (axis.action() == StepAxis::Action::None || axis.due() > end) break;
        t = std::max(t, axis.due());
        if (axis.action() == StepAxis::Action::SetDir) {
            axis.dir_set(axis.wanted_direction(), t);
            continue;
        }
        const TimePoint::duration lateness = late ? late(run.steps) : TimePoint::duration::zero();
        t += lateness;
        axis.stepped(t);
        ++run.steps;
        if (have_last) {
            const double interval = std::chrono::duration<double>(t - last).count();
            const double rate = 1.0 / interval;
            run.max_rate = std::max(run.max_rate, rate);
            if (last_interval > 0.0 && last_rate > 0.0) {
                run.max_accel = std::max(run.max_accel, std::abs(rate - last_rate) / (0.5 * (interval + last_interval)));
                const double allowed = std::chrono::duration<double>(std::min(last_lateness, TimePoint::duration(StepAxis::kJitter))).count();
                const double before = 1.0 / (last_interval - allowed);
                run.max_rise = std::max(run.max_rise, 0.5 * (rate * rate - before * before));
            }
            last_rate = rate;
            last_interval = interval;
            last_lateness = lateness;
        }
        last = t;
        have_last = true;
    }
    t = end;
    return run;
}

// An axis of `accel` steps/s² and `max_speed` steps/s under a `max_rate` step rate, 5 µs DIR setup.
StepAxis axis_of(double accel, double max_speed, double max_rate) {
    AxisKinematics k;
    k.accel = accel;
    k.max_speed = max_speed;
    return StepAxis(k, max_rate, 5e-6);
}

}  // namespace

TEST_CASE("StepAxis: a position move is a trapezoid that lands exactly", "[gpio][step_axis]") {
    StepAxis axis = axis_of(10000.0, 2000.0, 5000.0);
    TimePoint t{};
    const Run run = simulate(axis, AxisGoal{AxisGoal::Kind::Position, 0.0, 1234, 2000.0}, t, 3.0);
    CHECK(axis.position() == 1234);
    CHECK(run.steps == 1234);
    CHECK(axis.at_rest());
    CHECK(run.max_rate <= 2000.0 * 1.0001);
    CHECK(run.max_accel <= 10000.0 * 1.01);
    CHECK(run.max_accel >= 9000.0);
    // A short move never reaches top speed and still lands.
    simulate(axis, AxisGoal{AxisGoal::Kind::Position, 0.0, 1200, 2000.0}, t, 1.0);
    CHECK(axis.position() == 1200);
}

TEST_CASE("StepAxis: velocity ramps, holds and reverses through rest", "[gpio][step_axis]") {
    StepAxis axis = axis_of(4000.0, 1000.0, 2000.0);
    TimePoint t{};
    Run run = simulate(axis, AxisGoal{AxisGoal::Kind::Velocity, 5000.0, 0, 1000.0}, t, 1.0);  // capped at max_speed
    CHECK(run.max_rate <= 1000.0 * 1.0001);
    CHECK(axis.velocity() == Approx(1000.0));
    // 0.25 s ramp (125 steps) then 0.75 s at 1000/s: 875 steps.
    CHECK(run.steps == Approx(875.0).margin(2.0));
    run = simulate(axis, AxisGoal{AxisGoal::Kind::Velocity, -500.0, 0, 1000.0}, t, 1.0);
    CHECK(axis.velocity() == Approx(-500.0));
    CHECK(run.max_accel <= 4000.0 * 1.01);
    simulate(axis, AxisGoal::stop(), t, 1.0);
    CHECK(axis.at_rest());
}

TEST_CASE("StepAxis: a late edge is not caught up: no later interval beats the rate or the ramp", "[gpio][step_axis]") {
    StepAxis axis = axis_of(32000.0, 8000.0, 10000.0);
    TimePoint t{};
    // The pulse thread's lateness: jitter of 0–63 µs (under kJitter) on every edge, 300 µs every 397th,
    // 3 ms every 1009th.
    unsigned state = 12345;
    const Lateness late = [&state](long step) {
        state = state * 1103515245u + 12345u;
        long us = static_cast<long>((state >> 16) % 64);
        if (step % 397 == 13) us += 300;
        if (step % 1009 == 500) us += 3000;
        return std::chrono::duration_cast<TimePoint::duration>(std::chrono::microseconds(us));
    };
    const Run moving = simulate(axis, AxisGoal{AxisGoal::Kind::Velocity, 20000.0, 0, 8000.0}, t, 1.0, late);
    CHECK(moving.steps > 2000);  // slowed by each late edge's re-planned ramp
    CHECK(moving.max_rate <= 8000.0 * 1.0001);
    CHECK(moving.max_rise <= kRampRise * 32000.0 * 1.001);
    CHECK(axis.late_edges() >= 5);  // the 300 µs and 3 ms ones: jitter does not count
    CHECK(axis.late_edges() <= 20);
    CHECK(axis.lost_steps() > 20);  // 3 ms at 8000 steps/s alone is 24
    // A position move under the same lateness lands exactly, never faster than its ramp allows.
    const Run move = simulate(axis, AxisGoal{AxisGoal::Kind::Position, 0.0, 2000, 8000.0}, t, 3.0, late);
    CHECK(axis.position() == 2000);
    CHECK(axis.at_rest());
    CHECK(move.max_rate <= 8000.0 * 1.0001);
    CHECK(move.max_rise <= kRampRise * 32000.0 * 1.001);
    // On time, the same run ramps at the full acceleration: lateness is what slowed the ramp above.
    StepAxis punctual = axis_of(32000.0, 8000.0, 10000.0);
    TimePoint u{};
    const Run on_time = simulate(punctual, AxisGoal{AxisGoal::Kind::Velocity, 20000.0, 0, 8000.0}, u, 1.0);
    CHECK(on_time.max_rise >= 0.99 * kRampRise * 32000.0);  // the bound is reached, at the start
    CHECK(on_time.max_rise <= kRampRise * 32000.0 * 1.001);
    CHECK(punctual.late_edges() == 0);
    CHECK(punctual.lost_steps() == 0);
}

TEST_CASE("Homing: seek, release, back off, finish", "[gpio][homing]") {
    AxisKinematics k;
    k.accel = 10000.0;
    k.max_speed = 2000.0;
    k.homing_speed = 500.0;
    k.backoff_steps = 50;
    StepAxis axis(k, 5000.0, 0.0);
    Homing homing(k, -1, 10.0);
    TimePoint t{};
    homing.start(t);
    bool finished = false;
    for (int i = 0; i < 20000 && !finished; ++i) {
        const bool on_switch = axis.position() <= -100;
        const Homing::Step step = homing.update(on_switch, false, axis, t);
        REQUIRE(step.failure == nullptr);
        finished = step.finished;
        simulate(axis, step.goal, t, 0.0005);
    }
    REQUIRE(finished);
    CHECK(axis.position() == -99 + 50);
    CHECK_FALSE(homing.running());
}

TEST_CASE("Homing: the opposite switch and the timeout fail it", "[gpio][homing]") {
    AxisKinematics k;
    k.homing_speed = 100.0;
    StepAxis axis(k, 5000.0, 0.0);
    Homing homing(k, 1, 1.0);
    homing.start(TimePoint{});
    CHECK(homing.update(false, true, axis, TimePoint{}).failure != nullptr);
    homing.start(TimePoint{});
    CHECK(homing.update(false, false, axis, TimePoint{} + std::chrono::seconds(2)).failure != nullptr);
}
