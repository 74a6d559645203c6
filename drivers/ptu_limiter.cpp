// SPDX-License-Identifier: Apache-2.0
#include "drivers/ptu_limiter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "drivers/stopping_bound.hpp"

namespace rays::ptu {
namespace {

using Seconds = std::chrono::duration<double>;

bool positive(double value) { return std::isfinite(value) && value > 0.0; }

bool valid(const AxisLimits& limits) {
    return std::isfinite(limits.min_rad) && std::isfinite(limits.max_rad) && limits.min_rad <= limits.max_rad &&
           positive(limits.max_velocity_rad_s) && positive(limits.max_accel_rad_s2);
}

TimePoint::duration latency_of(const PtuDriver& driver) {
    const double latency_s = driver.command_latency_s();
    return std::chrono::duration_cast<TimePoint::duration>(Seconds(std::isfinite(latency_s) ? std::max(latency_s, 0.0) : 0.0));
}

}  // namespace

PtuLimiter::PtuLimiter(PtuDriver& driver) : driver_(driver) {}

void PtuLimiter::set_limits(const PtuLimits& limits) { limits_ = limits; }

DriverStatus PtuLimiter::activate() {
    const DriverStatus status = driver_.activate();
    forget_all();
    return status;
}

void PtuLimiter::deactivate() {
    driver_.deactivate();
    forget_all();
}

DriverStatus PtuLimiter::home(TimePoint now) {
    const DriverStatus status = driver_.home(now);
    forget_all();
    return status;
}

DriverStatus PtuLimiter::write(const PtuCommand& command, TimePoint now) {
    last_write_ = now;
    written_ = true;
    const TimePoint::duration latency = latency_of(driver_);
    PtuCommand sent;
    for (std::size_t i = 0; i < kAxes; ++i) {
        sent.axes[i] = shape(i, command.axes[i], now, latency);
        remember(i, sent.axes[i], now, latency);
    }
    const DriverStatus status = driver_.write(sent, now);
    if (!status.ok)  // the unit may not have taken it: wait for its next report
        for (AxisTrack& track : tracks_) track.reported = false;
    return status;
}

DriverStatus PtuLimiter::read(PtuState& state, TimePoint now) {
    const DriverStatus status = driver_.read(state, now);
    if (!status.ok) return status;
    for (std::size_t i = 0; i < kAxes; ++i) {
        AxisTrack& track = tracks_[i];
        track.report = state.axes[i];
        track.report_at = state.stamp;
        track.reported = state.axes[i].enabled && !state.axes[i].fault;
    }
    return status;
}

DriverStatus PtuLimiter::stop(TimePoint now) {
    const TimePoint::duration latency = latency_of(driver_);
    for (std::size_t i = 0; i < kAxes; ++i) {
        AxisTrack& track = tracks_[i];
        track.mode = CommandMode::Velocity;
        track.velocity = 0.0;
        track.last_sent = now;
        remember(i, AxisCommand{}, now, latency);
    }
    const DriverStatus status = driver_.write(PtuCommand::stop(), now);
    if (!status.ok)
        for (AxisTrack& track : tracks_) track.reported = false;
    return status;
}

bool PtuLimiter::command_stale(TimePoint now, double max_age_s) const {
    return !written_ || Seconds(now - last_write_).count() > max_age_s;
}

bool PtuLimiter::predictable(std::size_t axis) const {
    const AxisTrack& track = tracks_[axis];
    return valid(limits_.axes[axis]) && positive(limits_.command_interval_s) && track.reported &&
           track.lost_until <= track.report_at;
}

// The axis as it will be at `until`: the last report, the command in force then, and every command
// sent since that had not yet taken effect.
AxisDynamics PtuLimiter::predict(std::size_t axis, TimePoint until, TimePoint::duration latency) const {
    const AxisTrack& track = tracks_[axis];
    AxisDynamicsConfig config;
    config.max_velocity_rad_s = limits_.axes[axis].max_velocity_rad_s;
    config.max_accel_rad_s2 = limits_.axes[axis].max_accel_rad_s2;
    AxisDynamics predicted(config);
    AxisCommand in_force{};
    std::size_t k = 0;
    for (; k < track.count && track.nth(k).at + latency <= track.report_at; ++k) in_force = track.nth(k).command;
    predicted.reset(track.report.position_rad, track.report.velocity_rad_s, in_force, track.report_at);
    for (; k < track.count; ++k) predicted.command(track.nth(k).command, track.nth(k).at + latency);
    predicted.advance(until);
    return predicted;
}

AxisCommand PtuLimiter::shape(std::size_t axis, const AxisCommand& wanted, TimePoint now,
                              TimePoint::duration latency) {
    AxisTrack& track = tracks_[axis];
    if (!predictable(axis)) {
        track.mode = CommandMode::Velocity;
        track.velocity = 0.0;
        track.last_sent = now;
        return AxisCommand{};
    }
    const AxisDynamics predicted = predict(axis, now + latency, latency);
    if (wanted.mode == CommandMode::Velocity || !std::isfinite(wanted.value))
        return {CommandMode::Velocity, shape_velocity(axis, std::isfinite(wanted.value) ? wanted.value : 0.0, predicted, now)};
    if (track.mode == CommandMode::Velocity && track.velocity != 0.0)
        return {CommandMode::Velocity, shape_velocity(axis, 0.0, predicted, now)};  // ramp down before the position move
    // The target clamped into the soft angles, approached at most at max_velocity: what is passed on
    // advances from the last target sent (from the predicted position when the axis was not on a
    // position move) by at most max_velocity·dt. However fast the drive's own profile, the move keeps
    // to the limits in force now.
    const AxisLimits& limits = limits_.axes[axis];
    const double target = std::clamp(wanted.value, limits.min_rad, limits.max_rad);
    const double from = track.mode == CommandMode::Position ? track.position : predicted.position();
    const double step = limits.max_velocity_rad_s * since_last_command(axis, now);
    // Within the soft angles even from an axis beyond them (limits moved in on it).
    track.position = std::clamp(std::clamp(target, from - step, from + step), limits.min_rad, limits.max_rad);
    track.mode = CommandMode::Position;
    track.last_sent = now;
    return {CommandMode::Position, track.position};
}

double PtuLimiter::since_last_command(std::size_t axis, TimePoint now) const {
    return std::clamp(Seconds(now - tracks_[axis].last_sent).count(), 0.0, limits_.command_interval_s);
}

double PtuLimiter::shape_velocity(std::size_t axis, double wanted, const AxisDynamics& predicted, TimePoint now) {
    AxisTrack& track = tracks_[axis];
    const AxisLimits& limits = limits_.axes[axis];
    const double hold_s = limits_.command_interval_s;
    const double accel = limits.max_accel_rad_s2;
    const double step = accel * since_last_command(axis, now);
    const double from = track.mode == CommandMode::Velocity ? track.velocity : predicted.velocity();
    double velocity = std::clamp(wanted, from - step, from + step);
    velocity = std::clamp(velocity, -limits.max_velocity_rad_s, limits.max_velocity_rad_s);
    const double position = predicted.position();
    const double moving = predicted.velocity();
    if (velocity > 0.0)
        velocity = fastest_stoppable(limits.max_rad - position, moving, velocity, from - step, hold_s, accel);
    else if (velocity < 0.0)
        velocity = -fastest_stoppable(position - limits.min_rad, -moving, -velocity, -(from + step), hold_s, accel);
    track.mode = CommandMode::Velocity;
    track.velocity = velocity;
    track.last_sent = now;
    return velocity;
}

// Keeps the command for later predictions, dropping those the last report already shows in force.
void PtuLimiter::remember(std::size_t axis, const AxisCommand& sent, TimePoint now, TimePoint::duration latency) {
    AxisTrack& track = tracks_[axis];
    while (track.count >= 2 && track.nth(1).at + latency <= track.report_at) {
        track.first = (track.first + 1) % kInFlightCapacity;
        --track.count;
    }
    if (track.count == kInFlightCapacity) {  // the prediction stays unknown until a report catches up
        track.lost_until = now + latency;
        track.first = (track.first + 1) % kInFlightCapacity;
        --track.count;
    }
    track.sent[(track.first + track.count) % kInFlightCapacity] = SentCommand{now, sent};
    ++track.count;
}

void PtuLimiter::forget_all() {
    for (AxisTrack& track : tracks_) track = AxisTrack{};
}

}  // namespace rays::ptu
