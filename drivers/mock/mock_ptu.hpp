// SPDX-License-Identifier: Apache-2.0
// A simulated pan/tilt unit for tests and for running the daemon without hardware: two AxisDynamics
// (latency, velocity and acceleration limits, end stops), the lifecycle enforced as a real unit would
// (write before activate fails and moves nothing), every write recorded, and faults on demand.
//
// Threads: the frame thread calls write/read; a test may call records(), lifecycle_calls(),
// inject_fault() and clear_fault() from another thread at any time. One mutex guards the state; it
// is held only for in-memory work, never across blocking calls. Records are append-only in a buffer
// allocated at construction, so the span records() returns stays valid and unchanged while the
// writer goes on appending.
#pragma once
#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <mutex>
#include <span>

#include "core/clock.hpp"
#include "drivers/axis_dynamics.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::ptu {

struct EndStops {
    double min_rad = 0.0;
    double max_rad = 0.0;
};

struct MockPtuConfig {
    double max_velocity_rad_s = 2.0;
    double max_accel_rad_s2 = 12.0;
    double latency_s = 0.01;  // from write() to effect
    // Position moves cruise at most at this: the drive's profile velocity, with which it follows
    // PtuLimiter's position targets (ptu_limiter.hpp), set within the soft limits.
    double profile_velocity_rad_s = std::numeric_limits<double>::infinity();
    // Pan ±175°, tilt −35° to 95°: just beyond the daemon's default soft limits.
    std::array<EndStops, kAxes> end_stops{{{-3.0543, 3.0543}, {-0.6109, 1.6581}}};
    std::size_t record_capacity = 4096;  // writes kept; later ones are only counted
};

struct CommandRecord {
    TimePoint time{};
    PtuCommand command;
    bool accepted = false;  // false: refused (not active, or a fault), nothing moved
};

enum class LifecycleStep { Configure, Activate, Deactivate };

struct LifecycleCall {
    LifecycleStep step = LifecycleStep::Configure;
    bool ok = false;
};

class MockPtu final : public PtuDriver {
public:
    static constexpr std::size_t kLifecycleCapacity = 64;  // calls kept; later ones are not

    // `clock` times the calls that carry no time of their own: deactivate() and inject_fault().
    MockPtu(const MockPtuConfig& config, const Clock& clock);

    const char* name() const override { return "mock"; }
    double command_latency_s() const override { return latency_s_; }
    DriverStatus configure() override;  // fails while active
    DriverStatus activate() override;   // fails before configure
    void deactivate() override;         // halts both axes (ramp to rest at max_accel)
    // The simulated unit knows its absolute angles: always homed, homing succeeds at once.
    DriverStatus home(TimePoint) override { return DriverStatus::success(); }
    DriverStatus write(const PtuCommand& command, TimePoint now) override;  // fails unless active and fault-free
    DriverStatus read(PtuState& state, TimePoint now) override;             // fails before configure

    // From now until clear_fault(): read() reports the axis faulted and disabled, write() fails with
    // `reason`, and both axes halt (a fault on one axis stops the other).
    void inject_fault(Axis axis, const char* reason);
    void clear_fault();

    bool configured() const;
    bool active() const;
    std::span<const CommandRecord> records() const;
    std::size_t dropped_records() const;  // writes beyond record_capacity
    std::span<const LifecycleCall> lifecycle_calls() const;

private:
    void note(LifecycleStep step, bool ok);

    const Clock& clock_;
    const double latency_s_;
    mutable std::mutex mutex_;
    std::array<AxisDynamics, kAxes> axes_;
    std::array<bool, kAxes> faulted_{};
    DriverStatus fault_;  // what write() answers while an axis is faulted
    bool configured_ = false;
    bool active_ = false;
    std::unique_ptr<CommandRecord[]> records_;
    std::size_t record_capacity_ = 0;
    std::size_t record_count_ = 0;
    std::size_t dropped_records_ = 0;
    std::array<LifecycleCall, kLifecycleCapacity> lifecycle_{};
    std::size_t lifecycle_count_ = 0;
};

}  // namespace rays::ptu
