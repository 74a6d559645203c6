// SPDX-License-Identifier: Apache-2.0
#include "drivers/mock/mock_ptu.hpp"

#include <cstdio>

namespace rays::ptu {
namespace {

AxisDynamics axis_model(const MockPtuConfig& config, Axis axis) {
    const EndStops& stops = config.end_stops[static_cast<std::size_t>(axis)];
    return AxisDynamics(AxisDynamicsConfig{config.max_velocity_rad_s, config.max_accel_rad_s2, config.latency_s,
                                           stops.min_rad, stops.max_rad, config.profile_velocity_rad_s});
}

}  // namespace

MockPtu::MockPtu(const MockPtuConfig& config, const Clock& clock)
    : clock_(clock),
      latency_s_(config.latency_s),
      axes_{axis_model(config, Axis::Pan), axis_model(config, Axis::Tilt)},
      records_(std::make_unique<CommandRecord[]>(config.record_capacity)),
      record_capacity_(config.record_capacity) {}

DriverStatus MockPtu::configure() {
    std::lock_guard lock(mutex_);
    if (active_) {
        note(LifecycleStep::Configure, false);
        return DriverStatus::failure("mock: configure while active");
    }
    configured_ = true;
    note(LifecycleStep::Configure, true);
    return DriverStatus::success();
}

DriverStatus MockPtu::activate() {
    std::lock_guard lock(mutex_);
    if (!configured_) {
        note(LifecycleStep::Activate, false);
        return DriverStatus::failure("mock: activate before configure");
    }
    active_ = true;
    note(LifecycleStep::Activate, true);
    return DriverStatus::success();
}

void MockPtu::deactivate() {
    std::lock_guard lock(mutex_);
    const TimePoint now = clock_.now();
    for (AxisDynamics& axis : axes_) axis.halt(now);
    active_ = false;
    note(LifecycleStep::Deactivate, true);
}

DriverStatus MockPtu::write(const PtuCommand& command, TimePoint now) {
    std::lock_guard lock(mutex_);
    const bool faulted = faulted_[0] || faulted_[1];
    const bool accepted = active_ && !faulted;
    if (record_count_ < record_capacity_)
        records_[record_count_++] = CommandRecord{now, command, accepted};
    else
        ++dropped_records_;
    if (!active_) return DriverStatus::failure("mock: write while not active");
    if (faulted) return fault_;
    for (std::size_t i = 0; i < kAxes; ++i) axes_[i].command(command.axes[i], now);
    return DriverStatus::success();
}

DriverStatus MockPtu::read(PtuState& state, TimePoint now) {
    std::lock_guard lock(mutex_);
    if (!configured_) return DriverStatus::failure("mock: read before configure");
    for (std::size_t i = 0; i < kAxes; ++i) {
        axes_[i].advance(now);
        state.axes[i] = AxisState{axes_[i].position(), axes_[i].velocity(), active_ && !faulted_[i], faulted_[i], true};
    }
    state.stamp = now;
    return DriverStatus::success();
}

void MockPtu::inject_fault(Axis axis, const char* reason) {
    std::lock_guard lock(mutex_);
    const auto index = static_cast<std::size_t>(axis);
    for (AxisDynamics& each : axes_) each.halt(clock_.now());  // as a drive should: the other axis stops too
    faulted_[index] = true;
    std::array<char, sizeof(fault_.message)> text{};
    std::snprintf(text.data(), text.size(), "mock: %s axis fault: %s", axis == Axis::Pan ? "pan" : "tilt",
                  reason != nullptr ? reason : "");
    fault_ = DriverStatus::failure(text.data());
}

void MockPtu::clear_fault() {
    std::lock_guard lock(mutex_);
    faulted_ = {};
    fault_ = DriverStatus::success();
}

bool MockPtu::configured() const {
    std::lock_guard lock(mutex_);
    return configured_;
}

bool MockPtu::active() const {
    std::lock_guard lock(mutex_);
    return active_;
}

std::span<const CommandRecord> MockPtu::records() const {
    std::lock_guard lock(mutex_);
    return {records_.get(), record_count_};
}

std::size_t MockPtu::dropped_records() const {
    std::lock_guard lock(mutex_);
    return dropped_records_;
}

std::span<const LifecycleCall> MockPtu::lifecycle_calls() const {
    std::lock_guard lock(mutex_);
    return {lifecycle_.data(), lifecycle_count_};
}

void MockPtu::note(LifecycleStep step, bool ok) {
    if (lifecycle_count_ < kLifecycleCapacity) lifecycle_[lifecycle_count_++] = LifecycleCall{step, ok};
}

}  // namespace rays::ptu
