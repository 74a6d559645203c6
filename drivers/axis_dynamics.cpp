// SPDX-License-Identifier: Apache-2.0
#include "drivers/axis_dynamics.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "drivers/axis_motion.hpp"

namespace rays::ptu {
namespace {

using Seconds = std::chrono::duration<double>;

// Phases one integration step may pass through: a move has at most five, an end stop adds one.
// The bound only guards against a planning fault; time left beyond it would pass without motion.
constexpr int kMaxPhasesPerStep = 16;
constexpr double kNever = std::numeric_limits<double>::infinity();

AxisCommand finite_or_stop(const AxisCommand& command) {
    return std::isfinite(command.value) ? command : AxisCommand{};
}

// The first time in [0, horizon] at which motion from 0 with velocity v and acceleration a (both
// counted towards a level `gap` ≥ 0 away) reaches the level, or kNever.
double first_reach(double gap, double v, double a, double horizon) {
    if (std::isinf(gap)) return kNever;  // no end stop on this side
    gap = std::max(gap, 0.0);            // a rounding step past the stop counts as on it
    double t = kNever;
    if (a == 0.0) {
        if (v > 0.0) t = gap / v;
    } else {
        const double discriminant = v * v + 2.0 * a * gap;
        if (discriminant >= 0.0) {
            const double root = std::sqrt(discriminant);
            if (v > 0.0)
                t = 2.0 * gap / (v + root);  // the stable form of the smaller root
            else if (a > 0.0)
                t = (root - v) / a;
        }
    }
    return t <= horizon ? t : kNever;
}

}  // namespace

AxisDynamics::AxisDynamics(const AxisDynamicsConfig& config, double position_rad)
    : config_(config),
      latency_(std::chrono::duration_cast<TimePoint::duration>(Seconds(std::max(config.latency_s, 0.0)))),
      position_(std::clamp(position_rad, config.min_stop_rad, config.max_stop_rad)) {}

void AxisDynamics::command(const AxisCommand& command, TimePoint given) {
    advance(given);
    const Pending entry{finite_or_stop(command), time_ + latency_};
    if (pending_count_ == kPendingCapacity) {
        pending_[(first_pending_ + pending_count_ - 1) % kPendingCapacity] = entry;
        ++dropped_commands_;
        return;
    }
    pending_[(first_pending_ + pending_count_) % kPendingCapacity] = entry;
    ++pending_count_;
}

void AxisDynamics::halt(TimePoint now) {
    advance(now);
    pending_count_ = 0;
    active_ = AxisCommand{};
}

void AxisDynamics::reset(double position_rad, double velocity_rad_s, const AxisCommand& active, TimePoint now) {
    started_ = true;
    time_ = now;
    position_ = std::clamp(position_rad, config_.min_stop_rad, config_.max_stop_rad);
    velocity_ = velocity_rad_s;
    pending_count_ = 0;
    active_ = finite_or_stop(active);
}

void AxisDynamics::start_at(TimePoint now) {
    if (started_) return;
    time_ = now;
    started_ = true;
}

void AxisDynamics::set_position_velocity(double rad_s) {
    config_.position_velocity_rad_s = std::isfinite(rad_s) && rad_s > 0.0 ? rad_s : std::numeric_limits<double>::infinity();
}

void AxisDynamics::advance(TimePoint now) {
    start_at(now);
    for (;;) {
        apply_due_commands();
        TimePoint until = now;
        if (pending_count_ > 0) until = std::min(until, pending_[first_pending_].due);
        if (until <= time_) return;
        integrate(Seconds(until - time_).count());
        time_ = until;
    }
}

void AxisDynamics::apply_due_commands() {
    while (pending_count_ > 0 && pending_[first_pending_].due <= time_) {
        active_ = pending_[first_pending_].command;
        first_pending_ = (first_pending_ + 1) % kPendingCapacity;
        --pending_count_;
    }
}

void AxisDynamics::integrate(double seconds) {
    const double vmax = config_.max_velocity_rad_s;
    const double amax = config_.max_accel_rad_s2;
    double remaining = seconds;
    for (int i = 0; i < kMaxPhasesPerStep && remaining > 0.0; ++i) {
        const MotionPhase phase =
            active_.mode == CommandMode::Velocity
                ? velocity_phase(velocity_, std::clamp(active_.value, -vmax, vmax), amax)
                : position_phase(position_, velocity_, active_.value, std::min(vmax, config_.position_velocity_rad_s), amax);
        const double span = std::min(phase.duration, remaining);
        const double to_max_stop = first_reach(config_.max_stop_rad - position_, velocity_, phase.accel, span);
        const double to_min_stop = first_reach(position_ - config_.min_stop_rad, -velocity_, -phase.accel, span);
        if (to_max_stop != kNever || to_min_stop != kNever) {
            const bool upper = to_max_stop <= to_min_stop;
            const double hit = upper ? to_max_stop : to_min_stop;
            const bool pinned = hit == 0.0 && velocity_ == 0.0;  // pressed against the stop: stays there
            position_ = upper ? config_.max_stop_rad : config_.min_stop_rad;
            velocity_ = 0.0;
            remaining -= hit;
            if (pinned) return;
            continue;
        }
        const double end_velocity = span == phase.duration ? phase.end_velocity : velocity_ + phase.accel * span;
        position_ += 0.5 * (velocity_ + end_velocity) * span;
        if (span == phase.duration && phase.ends_on_target) position_ = active_.value;
        velocity_ = end_velocity;
        remaining -= span;
    }
}

}  // namespace rays::ptu
