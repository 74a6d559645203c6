// SPDX-License-Identifier: Apache-2.0
// One servo axis as its drive moves it: a command takes effect latency_s after it is given, velocity
// changes at most at max_accel, speed stays within max_velocity, a position command follows a
// trapezoidal profile that stops exactly on its target, and hard end stops halt the axis (velocity 0).
// advance() integrates the piecewise-constant acceleration exactly, so the state does not depend on
// how time is sliced. Standalone and deterministic: no clock reads (time comes in as arguments), no
// allocation, no exceptions. Used by the mock driver and by PtuLimiter to predict the axis.
// Soft travel limits are not its business (PtuLimiter). Not thread-safe.
#pragma once
#include <array>
#include <cstddef>
#include <limits>

#include "core/clock.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::ptu {

struct AxisDynamicsConfig {
    double max_velocity_rad_s = 1.0;  // > 0
    double max_accel_rad_s2 = 4.0;    // > 0
    double latency_s = 0.0;           // from command() to effect, ≥ 0
    double min_stop_rad = -std::numeric_limits<double>::infinity();  // hard mechanical end stops
    double max_stop_rad = std::numeric_limits<double>::infinity();
    // A position move cruises at most at this (a drive's profile velocity), and at most at max_velocity.
    double position_velocity_rad_s = std::numeric_limits<double>::infinity();
};

class AxisDynamics {
public:
    // Commands in flight at once; a command given while the ring is full replaces the newest one in
    // it (counted by dropped_commands), which a drive fed faster than it acts would also never see.
    static constexpr std::size_t kPendingCapacity = 32;

    // At rest at position_rad (clamped to the end stops). Its time starts at the first time it is given.
    explicit AxisDynamics(const AxisDynamicsConfig& config, double position_rad = 0.0);

    // Advances to `given`, then queues the command to take effect at given + latency. Non-finite
    // values command zero velocity; velocities beyond max_velocity are held at it.
    void command(const AxisCommand& command, TimePoint given);
    // Advances to `now`, drops the commands in flight and ramps to rest at max_accel (a quick stop).
    void halt(TimePoint now);
    // From `now` on: at position_rad (within the end stops), moving at velocity_rad_s under
    // `active`, with nothing in flight.
    void reset(double position_rad, double velocity_rad_s, const AxisCommand& active, TimePoint now);
    // A drive's profile velocity written at run time (non-positive or non-finite: none), for the
    // position moves commanded after it.
    void set_position_velocity(double rad_s);
    // Integrates up to `now`, applying the commands that fell due; earlier times change nothing.
    void advance(TimePoint now);

    double position() const { return position_; }
    double velocity() const { return velocity_; }
    std::size_t dropped_commands() const { return dropped_commands_; }

private:
    struct Pending {
        AxisCommand command;
        TimePoint due;
    };

    void start_at(TimePoint now);
    void apply_due_commands();
    void integrate(double seconds);

    AxisDynamicsConfig config_;
    TimePoint::duration latency_;
    double position_ = 0.0;
    double velocity_ = 0.0;
    AxisCommand active_{};  // the command in effect
    TimePoint time_{};
    bool started_ = false;
    std::array<Pending, kPendingCapacity> pending_{};
    std::size_t first_pending_ = 0;
    std::size_t pending_count_ = 0;
    std::size_t dropped_commands_ = 0;
};

}  // namespace rays::ptu
