// SPDX-License-Identifier: Apache-2.0
// The one place motion limits are enforced, above every driver: PtuLimiter wraps the driver and
// shapes each command before passing it on.
//
// Position commands: the target is clamped into [min_rad, max_rad] and approached at most at
// max_velocity: each write passes on a target that advances from the last one sent (from the
// predicted position when the axis was not on a position move) by at most max_velocity·dt (dt = time
// since the last command, at most command_interval_s), and within [min_rad, max_rad] (at once from an
// axis beyond them). The drive's own profile moves to each, so a move keeps to the velocity limit in
// force now however fast that profile (and a reload that lowers the limit slows the next write's
// move); the move's acceleration is the profile's, so configure it within max_accel. A move
// therefore needs write() every frame until it arrives, as the frame loop does; a write stream that
// stops leaves the axis at the last target sent.
// Velocity commands, in this order: non-finite → 0; slew-limited to ±max_accel·dt around the last
// command (dt = time since it, at most command_interval_s); clamped to ±max_velocity; then reduced
// so the axis can still stop before the soft limit it moves toward even if this command is held for
// command_interval_s (about v ≤ √(2·amax·distance), exactly 0 at or beyond the limit). Motion away
// from a limit is always allowed. The limit overrides the slew limit only where the axis is past
// its braking point (after a position move ending at a limit, or limits moved in on it); then the
// command keeps it braking at max_accel.
//
// The distance to a limit is taken where the axis will be when the new command takes effect: from
// the last state read(), through the commands still in flight (sent within the driver's
// command_latency_s), integrated by an AxisDynamics with the limits' velocity and acceleration. A
// drive that ramps at max_accel with the latency it reports is predicted exactly and stays within
// the soft limits, as long as write() comes at least every command_interval_s (see command_stale).
// A drive that accelerates faster gets a little ahead of the prediction within each latency and
// frame (in the tests, less than half a frame's travel at max_velocity); each read() starts the
// prediction afresh, so that error does not add up.
//
// An axis is held still (every command on it becomes zero velocity) until read() reports it enabled
// and fault-free, again after activate(), deactivate(), a failed write or a fault, and while its
// limits are invalid or more commands are in flight than kInFlightCapacity.
//
// Mode switches: velocity → position first ramps the velocity command down to 0 at max_accel (the
// position command is passed on once it is 0); position → velocity slews from the predicted velocity.
//
// write(), read(), stop() and set_limits() do not allocate, block or throw. One thread (the frame
// loop) uses it.
#pragma once
#include <array>
#include <cstddef>

#include "core/clock.hpp"
#include "drivers/axis_dynamics.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::ptu {

// One axis's limits. Valid when finite, min_rad ≤ max_rad and both rates > 0; an axis with invalid
// limits (the defaults) is held still.
struct AxisLimits {
    double min_rad = 0.0;  // soft angle limits
    double max_rad = 0.0;
    double max_velocity_rad_s = 0.0;
    double max_accel_rad_s2 = 0.0;
};

struct PtuLimits {
    std::array<AxisLimits, kAxes> axes{};
    // The longest time between two writes the limiter plans for: a command may be held this long
    // before the next one can brake. Later writes can carry an axis past a soft limit.
    double command_interval_s = 0.1;
};

class PtuLimiter final : public PtuDriver {
public:
    static constexpr std::size_t kInFlightCapacity = 128;  // commands per axis remembered for the prediction

    // Holds every axis still until set_limits() gives valid limits.
    explicit PtuLimiter(PtuDriver& driver);

    void set_limits(const PtuLimits& limits);  // takes effect from the next command

    const char* name() const override { return driver_.name(); }
    double command_latency_s() const override { return driver_.command_latency_s(); }
    DriverStatus configure() override { return driver_.configure(); }
    DriverStatus activate() override;
    void deactivate() override;
    // Passes homing on; the axes are held until the unit reports them at rest again.
    DriverStatus home(TimePoint now) override;
    // Shapes the command as described above and passes it on; remembers `now` for command_stale.
    DriverStatus write(const PtuCommand& command, TimePoint now) override;
    // Passes the driver's state through and keeps it (with its stamp) for the prediction.
    DriverStatus read(PtuState& state, TimePoint now) override;

    // Zero velocity on both axes at once, without slew limiting: the drive ramps down at its own
    // acceleration, which the prediction assumes anyway. For shutdown, faults and stale commands.
    // Does not count as a write for command_stale.
    DriverStatus stop(TimePoint now);

    // True when write() has not been called within max_age_s before `now` (or never was).
    bool command_stale(TimePoint now, double max_age_s) const;

private:
    struct SentCommand {
        TimePoint at{};
        AxisCommand command;
    };

    struct AxisTrack {
        std::array<SentCommand, kInFlightCapacity> sent{};  // ring, oldest first
        std::size_t first = 0;
        std::size_t count = 0;
        TimePoint lost_until{};   // a command dropped from the full ring takes effect until then
        bool reported = false;    // the last report shows the axis enabled and fault-free
        AxisState report;
        TimePoint report_at{};
        CommandMode mode = CommandMode::Velocity;  // of the last command sent
        double velocity = 0.0;                     // the last velocity command sent
        double position = 0.0;                     // the last position target sent
        TimePoint last_sent{};

        const SentCommand& nth(std::size_t k) const { return sent[(first + k) % kInFlightCapacity]; }
    };

    bool predictable(std::size_t axis) const;
    AxisDynamics predict(std::size_t axis, TimePoint until, TimePoint::duration latency) const;
    AxisCommand shape(std::size_t axis, const AxisCommand& wanted, TimePoint now, TimePoint::duration latency);
    double shape_velocity(std::size_t axis, double wanted, const AxisDynamics& predicted, TimePoint now);
    // Seconds since the axis' last command, at most command_interval_s: what a rate limit allows for.
    double since_last_command(std::size_t axis, TimePoint now) const;
    void remember(std::size_t axis, const AxisCommand& sent, TimePoint now, TimePoint::duration latency);
    void forget_all();

    PtuDriver& driver_;
    PtuLimits limits_;
    std::array<AxisTrack, kAxes> tracks_;
    TimePoint last_write_{};
    bool written_ = false;
};

}  // namespace rays::ptu
